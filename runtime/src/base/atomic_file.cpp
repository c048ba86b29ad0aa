#include "base/atomic_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace kiln::runtime {

std::optional<Error> WriteFileAtomically(const std::string& path, std::span<const uint8_t> bytes) {
    const std::string temp = path + ".tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        if (!out) {
            std::remove(temp.c_str());
            return Error{"cannot write '" + temp + "'"};
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::remove(temp.c_str());
        return Error{"cannot rename '" + temp + "' to '" + path + "': " + ec.message()};
    }
    return std::nullopt;
}

}  // namespace kiln::runtime
