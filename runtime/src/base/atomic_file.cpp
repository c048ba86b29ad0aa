#include "base/atomic_file.h"

#include "kiln/base/files.h"

namespace kiln::runtime {

std::optional<Error> WriteFileAtomically(const std::string& path, std::span<const uint8_t> bytes) {
    const Result<bool> written = base::WriteFileAtomically(path, bytes);
    if (!written)
        return Error{written.error().message};
    return std::nullopt;
}

}  // namespace kiln::runtime
