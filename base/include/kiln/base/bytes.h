// Little-endian 32- and 64-bit words in byte strings, for Kiln's small binary formats
// (compile-cache entries, the worker protocol). The pack format has its own record reader and
// writer (kiln/pack/records.h).
#ifndef KILN_BASE_BYTES_H_
#define KILN_BASE_BYTES_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace kiln::base {

inline void AppendLe32(std::string& s, uint32_t x) {
    for (int i = 0; i < 4; ++i)
        s += static_cast<char>(x >> (8 * i));
}

// The caller checks that s[at..at+4) exists.
inline uint32_t LoadLe32(std::string_view s, size_t at) {
    uint32_t x = 0;
    for (size_t i = 0; i < 4; ++i)
        x |= uint32_t(uint8_t(s[at + i])) << (8 * i);
    return x;
}

inline void AppendLe64(std::string& s, uint64_t x) {
    AppendLe32(s, static_cast<uint32_t>(x));
    AppendLe32(s, static_cast<uint32_t>(x >> 32));
}

// The caller checks that s[at..at+8) exists.
inline uint64_t LoadLe64(std::string_view s, size_t at) {
    return uint64_t{LoadLe32(s, at)} | uint64_t{LoadLe32(s, at + 4)} << 32;
}

}  // namespace kiln::base

#endif  // KILN_BASE_BYTES_H_
