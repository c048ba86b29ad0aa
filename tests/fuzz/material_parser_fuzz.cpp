// libFuzzer target: the .material parser (JSON with positions, then the format's structure) on
// arbitrary bytes. Every issue must point inside the input.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "kiln/material/material.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace kiln::material;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Material m;
    std::vector<MaterialIssue> issues;
    const bool ok = ParseMaterial(text, m, issues);
    for (const MaterialIssue& i : issues) {
        if (i.pos.offset > size || i.pos.line == 0 || i.pos.column == 0 || i.message.empty())
            std::abort();
    }
    if (!ok && issues.empty())
        std::abort();
    (void)ClosestName(m.shader, {"Kiln/Standard", "Kiln/StandardMetallic"});
    return 0;
}
