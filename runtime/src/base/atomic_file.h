// The runtime's outputs (images, usage logs, pipeline caches) through kiln/base/files.h: unique
// temporary file, fsync, rename; never a device, FIFO or directory. This adapter only turns the
// result into the runtime's error value.
#ifndef KILN_RUNTIME_BASE_ATOMIC_FILE_H_
#define KILN_RUNTIME_BASE_ATOMIC_FILE_H_

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "kiln/runtime/status.h"

namespace kiln::runtime {

std::optional<Error> WriteFileAtomically(const std::string& path, std::span<const uint8_t> bytes);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_BASE_ATOMIC_FILE_H_
