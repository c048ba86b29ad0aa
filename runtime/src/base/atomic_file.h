// Writing output files so that a reader never sees half of one: the bytes go to "<path>.tmp",
// which is then renamed over `path` (atomic on POSIX file systems).
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
