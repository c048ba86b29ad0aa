// libFuzzer target: the pack reader on arbitrary bytes. The checksum is recomputed over the input
// first (when it is long enough), so the fuzzer reaches the structural validation and the
// accessors instead of stopping at the checksum; every accepted pack is then walked.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <xxhash.h>

#include "kiln/pack/reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace kiln::pack;
    std::vector<uint8_t> bytes(data, data + size);
    if (bytes.size() >= kHeaderSize) {
        for (uint32_t i = 0; i < 8; ++i)
            bytes[kChecksumOffset + i] = 0;
        const uint64_t sum = XXH64(bytes.data(), bytes.size(), 0);
        for (uint32_t i = 0; i < 8; ++i)
            bytes[kChecksumOffset + i] = uint8_t(sum >> (8 * i));
    }
    kiln::Result<Pack> opened = Pack::Open(bytes);
    if (!opened)
        return 0;
    const Pack pack = std::move(opened).value();
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
