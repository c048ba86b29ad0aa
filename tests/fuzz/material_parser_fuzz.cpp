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
    kiln::DiagnosticList issues;
    const bool ok = ParseMaterial(text, "fuzz.material", m, issues);
    for (const kiln::Diagnostic& d : issues.all()) {
        const kiln::SourceLoc& at = d.range.begin;
        if (at.offset > size || at.line == 0 || at.column == 0 || d.message.empty() ||
            d.file != "fuzz.material")
            std::abort();
    }
    if (!ok && !issues.has_errors())
        std::abort();
    (void)ClosestName(m.shader, {"Kiln/Standard", "Kiln/StandardMetallic"});
    return 0;
}
