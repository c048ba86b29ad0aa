// libFuzzer target: the direct mode's manifest reader (driver/direct_bundle.h) on arbitrary bytes.
// The cache checks an entry's hash before its text is read, but a manifest is still never trusted:
// it reads as a manifest or as nothing, every number it holds names a line it has, and what it
// reads writes back to text that reads the same.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "driver/direct_bundle.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using kiln::driver::DirectBundle;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::optional<DirectBundle> b = kiln::driver::ParseDirectBundle(text);
    if (!b)
        return 0;
    for (const DirectBundle::Set& s : b->sets) {
        for (uint32_t f : s.files)
            if (f >= b->files.size())
                std::abort();
        for (uint32_t i : s.includes)
            if (i >= b->includes.size())
                std::abort();
    }
    for (const DirectBundle::Entry& e : b->entries)
        if (e.set >= b->sets.size() || e.direct.size() != 32 || e.result.size() != 32)
            std::abort();
    const std::string written = kiln::driver::SerializeDirectBundle(*b);
    if (written != text)
        std::abort();  // the text is canonical: one way to write each manifest
    return 0;
}
