// Opens a pack with kiln::pack, picks the variant an engine would for a set of keywords, and
// turns the pass's render state into enums (no string compares): what an engine's loader does.
#include <cstdio>

#include "kiln/diagnostic.h"

#include "kiln/pack/pass_id.h"
#include "kiln/pack/reader.h"
#include "kiln/pack/render_state.h"
#include "kiln/pack/variant_selector.h"

using namespace kiln::pack;

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: pick_variant PACK\n");
        return 2;
    }
    // Every call that can fail gives a kiln::Result: a value or an Error with a stable code.
    const kiln::Result<MappedFile> file = MappedFile::Map(argv[1]);
    if (!file) {
        std::fprintf(stderr, "%s [%s]\n", file.error().message.c_str(),
                     kiln::FormatDiagCode(file.error().code).c_str());
        return 1;
    }
    const kiln::Result<Pack> opened = Pack::Open(file.value().bytes());
    if (!opened) {
        std::fprintf(stderr, "%s [%s]\n", opened.error().message.c_str(),
                     kiln::FormatDiagCode(opened.error().code).c_str());
        return 1;
    }
    const Pack& pack = opened.value();
    const auto shader = pack.FindShader("Consumer/Lit");
    const auto pass = shader ? pack.FindPass(*shader, "ForwardBase") : std::nullopt;
    if (!pass) {
        std::fprintf(stderr, "no Consumer/Lit ForwardBase pass\n");
        return 1;
    }
    VariantSelector selector(pack, MissingVariantPolicy::kError);
    const kiln::Result<VariantChoice> choice = selector.Select(*pass, {"HALF_TINT"});
    if (!choice) {
        std::fprintf(stderr, "%s\n", choice.error().message.c_str());
        return 1;
    }
    const VariantRec variant = pack.Variant(choice.value().variant).value();
    const std::span<const uint32_t> spirv =
        pack.SpirvWords(pack.Module(variant.fragment_module).value());
    const kiln::Result<PassState> state = ResolvePassState(pack, *pass, nullptr, {});
    if (!state) {
        std::fprintf(stderr, "%s\n", state.error().message.c_str());
        return 1;
    }
    const BlendTargetState& blend = state.value().targets[0];
    const bool alpha_blend = blend.enable && blend.src == BlendFactor::kSrcAlpha &&
                             blend.dst == BlendFactor::kOneMinusSrcAlpha;
    std::printf("pass %s variant %s: %zu SPIR-V words (magic %08x), alpha blend %s, zwrite %s\n",
                PassLabel(pack, *pass).c_str(),
                JoinKeywords(pack.KeywordsOf(*pass, VariantKey(variant.key))).c_str(), spirv.size(),
                spirv.empty() ? 0u : spirv[0], alpha_blend ? "yes" : "no",
                state.value().zwrite ? "on" : "off");
    // An index past the end is an error with its code, not a crash.
    const kiln::Result<ModuleRec> past_end = pack.Module(100000);
    return !past_end && past_end.error().code == kiln::DiagCode::kIndexOutOfRange ? 0 : 1;
}
