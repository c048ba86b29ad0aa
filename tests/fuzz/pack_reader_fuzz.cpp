// libFuzzer target: the pack reader on arbitrary bytes, opened with every check at open or with
// the variant data checked on first use. Half the inputs are resealed first (kiln/pack/seal.h),
// so the fuzzer reaches the structural validation and the accessors instead of stopping at a
// checksum; every accepted pack is then walked.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kiln/pack/reader.h"
#include "kiln/pack/seal.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace kiln::pack;
    std::vector<uint8_t> bytes(data, data + size);
    // Half the inputs resealed (the per-section sums and the whole-file checksum) and opened
    // either way; the other half as they are, checked on first use.
    const bool reseal = size % 2 == 0;
    if (reseal)
        Seal(bytes);
    const OpenChecks checks = size % 4 < 2 ? OpenChecks::kAll : OpenChecks::kOnFirstUse;
    kiln::Result<Pack> opened = Pack::Open(bytes, checks);
    if (!opened)
        return 0;
    const Pack pack = std::move(opened).value();
    if (!pack.CheckVariantData().ok()) {
        // Damaged variant data: none of it is returned, and lookups find nothing.
        for (uint32_t p = 0; p < pack.Count(SectionTag::kPasses); ++p) {
            if (pack.FindVariant(p, pack.KeyFor(p, {"SPOT", "POINT"})))
                __builtin_trap();
        }
        if (pack.Count(SectionTag::kVariants) > 0 && pack.Variant(0).ok())
            __builtin_trap();
        return 0;
    }
    for (uint32_t s = 0; s < pack.Count(SectionTag::kShaders); ++s) {
        const ShaderRec sr = pack.Shader(s).value();
        (void)pack.String(sr.name);
        (void)pack.FindShader(pack.String(sr.name));
        for (uint32_t p = sr.first_pass; p < sr.first_pass + sr.pass_count; ++p) {
            const PassRec pr = pack.Pass(p).value();
            (void)pack.FindPass(s, pack.String(pr.name));
            for (uint32_t v = pr.first_variant; v < pr.first_variant + pr.variant_count; ++v) {
                const VariantRec vr = pack.Variant(v).value();
                (void)pack.KeywordsOf(p, VariantKey(vr.key));
                (void)pack.FindVariant(p, VariantKey(vr.key));
                (void)pack.Spirv(pack.Module(vr.vertex_module).value());
                (void)pack.Spirv(pack.Module(vr.fragment_module).value());
            }
            (void)pack.FindVariant(p, pack.KeyFor(p, {"SPOT", "POINT"}));
            (void)pack.CheckKeywords(p, {"SPOT", "POINTT"});
        }
    }
    return 0;
}
