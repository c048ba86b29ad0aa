// The pack format through its reader: round trip of a compiled pack, lookups, and rejection of
// every truncated prefix, every bit flip, another version and structurally corrupt packs.
#include "kiln/pack/reader.h"

#include <gtest/gtest.h>

#include "kiln/pack/pass_id.h"

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::pack {
namespace {

// The pack of two test shaders (compiled once per fixture).
std::vector<uint8_t> PackOf(const std::string& a, const std::string& b) {
    DiagnosticList diags;
    CompileOutput out = CompileShaders({test::DataPath(a), test::DataPath(b)}, {}, diags);
    EXPECT_TRUE(out.ok) << test::Brief(diags);
    return out.pack;
}

const std::vector<uint8_t>& CompiledPack() {
    static const std::vector<uint8_t> bytes =
        PackOf("data/compile/multi_light.shader", "../materials/Unlit.shader");
    return bytes;
}

TEST(PackReader, RoundTripOfACompiledPack) {
    Pack p;
    ASSERT_TRUE(kiln::test::OpenInto(CompiledPack(), p));
    EXPECT_EQ(p.Count(SectionTag::kShaders), 2u);
    EXPECT_NE(std::string(p.String(p.meta().producer)).find("glslang"), std::string::npos);
    const auto shader = p.FindShader("Test/MultiLight");
    ASSERT_TRUE(shader);
    const ShaderRec sr = p.Shader(*shader).value();
    EXPECT_EQ(sr.property_count, 2u);
    EXPECT_EQ(p.String(p.Get<PropertyRec>(SectionTag::kProperties, sr.first_property).value().name),
              "_Tint");
    const auto by_name = p.FindPass(*shader, "forward_delta");
    const auto by_light_mode = p.FindPass(*shader, "ForwardAdd");
    ASSERT_TRUE(by_name && by_light_mode);
    EXPECT_EQ(*by_name, *by_light_mode);
    const PassRec pass = p.Pass(*by_name).value();
    // light.cginc lights POINT and SPOT alike: SPOT is stored as an alias of POINT (KALI).
    EXPECT_EQ(pass.variant_count, 2u);
    EXPECT_EQ(pass.keyword_set_count, 1u);
    EXPECT_EQ(p.Count(SectionTag::kKeywordAliases), 1u);
    EXPECT_EQ(p.AliasOf(pass.first_keyword_set, 2), 1u);  // SPOT -> POINT
    EXPECT_EQ(p.AliasOf(pass.first_keyword_set, 1), 1u);
    bool saw_blend = false;
    for (uint32_t s = pass.first_state; s < pass.first_state + pass.state_count; ++s) {
        const auto st = p.Get<StateRec>(SectionTag::kStates, s).value();
        if (st.field == uint32_t(StateField::kBlendSrc))
            saw_blend = p.String(st.text) == "One";
    }
    EXPECT_TRUE(saw_blend);
    for (const char* kw : {"DIRECTIONAL", "POINT", "SPOT"}) {  // SPOT finds POINT's variant
        const VariantKey key = p.KeyFor(*by_name, {kw, "UNRELATED"});
        const auto v = p.FindVariant(*by_name, key);
        ASSERT_TRUE(v) << kw;
        EXPECT_EQ(p.KeywordsOf(*by_name, key), std::vector<std::string>{kw});
        const auto spirv = p.Spirv(p.Module(p.Variant(*v).value().fragment_module).value());
        ASSERT_GE(spirv.size(), 20u);
        EXPECT_EQ(spirv.size() % 4, 0u);
        EXPECT_EQ(reinterpret_cast<uintptr_t>(spirv.data()) % 4, 0u);
        EXPECT_EQ(spirv[0] | spirv[1] << 8 | spirv[2] << 16 | uint32_t(spirv[3]) << 24,
                  0x07230203u);
    }
    EXPECT_FALSE(p.FindVariant(*by_name, VariantKey(3)));  // index 3 of a 3-keyword set
    EXPECT_FALSE(p.FindShader("Nope"));
    // KeyFor ignores names no set declares (as Unity ignores such material keywords);
    // CheckKeywords names the first with the closest declared keyword.
    EXPECT_TRUE(p.CheckKeywords(*by_name, {"POINT"}).ok());
    const Status typo = p.CheckKeywords(*by_name, {"POINT", "SPOTT"});
    ASSERT_FALSE(typo.ok());
    EXPECT_EQ(typo.error().code, DiagCode::kUnknownKeyword);
    EXPECT_EQ(typo.error().message,
              "keyword 'SPOTT' is not declared by the pass; did you mean 'SPOT'?");
    const Status past_end = p.CheckKeywords(999, {});
    ASSERT_FALSE(past_end.ok());
    EXPECT_EQ(past_end.error().code, DiagCode::kIndexOutOfRange);
    // The SPIR-V as words, for vkCreateShaderModule.
    const ModuleRec m = p.Module(0).value();
    const std::span<const uint32_t> words = p.SpirvWords(m);
    ASSERT_EQ(words.size(), m.spirv_size / 4);
    EXPECT_EQ(words[0], 0x07230203u);
}

TEST(PackReader, OutOfRangeIndicesAreRejected) {
    Pack p;
    ASSERT_TRUE(kiln::test::OpenInto(CompiledPack(), p));
    const Result<ModuleRec> module = p.Module(100000);
    ASSERT_FALSE(module.ok());
    EXPECT_EQ(module.error().code, DiagCode::kIndexOutOfRange);
    EXPECT_EQ(module.error().message,
              "record 100000 of section MODL is out of range (the pack has " +
                  std::to_string(p.Count(SectionTag::kModules)) + ")");
    EXPECT_FALSE(p.Shader(p.Count(SectionTag::kShaders)).ok());  // one past the end
    EXPECT_TRUE(p.Shader(p.Count(SectionTag::kShaders) - 1).ok());
    EXPECT_FALSE(p.Pass(~0u).ok());
    EXPECT_FALSE(p.Variant(100000).ok());
    EXPECT_FALSE(p.KeywordSet(100000).ok());
    EXPECT_FALSE(p.Keyword(100000).ok());
    EXPECT_FALSE(p.Get<TagRec>(SectionTag::kTags, 100000).ok());
    EXPECT_FALSE(p.FindVariant(100000, VariantKey(0)));
    EXPECT_TRUE(p.KeywordsOf(100000, VariantKey(0)).empty());
    EXPECT_FALSE(p.FindPass(100000, "ForwardBase"));
    // A module record the pack does not hold gives no bytes, not someone else's.
    ModuleRec forged;
    forged.spirv_offset = 0xFFFFFFF0u;
    forged.spirv_size = 64;
    EXPECT_TRUE(p.Spirv(forged).empty());
    EXPECT_TRUE(p.SpirvWords(forged).empty());
    // An unopened pack holds nothing.
    const Pack empty;
    EXPECT_FALSE(empty.Shader(0).ok());
    EXPECT_EQ(empty.meta().variant_count, 0u);
}

TEST(PackReader, EveryTruncatedPrefixIsRejected) {
    const std::vector<uint8_t>& full = CompiledPack();
    for (size_t n = 0; n < full.size(); ++n) {
        std::vector<uint8_t> prefix(full.begin(), full.begin() + static_cast<ptrdiff_t>(n));
        const Result<Pack> opened = Pack::Open(prefix);
        ASSERT_FALSE(opened) << "prefix of " << n << " bytes accepted";
        if (n >= kHeaderSize) {
            EXPECT_EQ(opened.error().code, DiagCode::kPackTruncated) << n;
        }
    }
}

TEST(PackReader, EveryBitFlipIsRejected) {
    std::vector<uint8_t> b = CompiledPack();
    for (size_t i = 0; i < b.size(); ++i) {
        const int bit = int(i % 8);
        b[i] ^= uint8_t(1u << bit);
        ASSERT_FALSE(Pack::Open(b)) << "flip at byte " << i;
        b[i] ^= uint8_t(1u << bit);
    }
}

// Bytes of section `tag` of `b` (the section table read by hand), or b.size() when absent.
size_t SectionAt(const std::vector<uint8_t>& b, const char* tag) {
    const uint32_t sections = b[12] | b[13] << 8 | b[14] << 16 | uint32_t(b[15]) << 24;
    for (uint32_t i = 0; i < sections; ++i) {
        const uint8_t* e = b.data() + kHeaderSize + i * kSectionEntrySize;
        if (std::equal(e, e + 4, tag)) {
            uint64_t offset = 0;
            for (int k = 7; k >= 0; --k)
                offset = offset << 8 | e[8 + k];
            return size_t(offset);
        }
    }
    return b.size();
}

// A geometry pass and a tessellated pass: their variants' other stages are in VSTG.
const std::vector<uint8_t>& StagesPack() {
    static const std::vector<uint8_t> bytes =
        PackOf("data/stages/geometry.shader", "data/stages/tessellation.shader");
    return bytes;
}

TEST(PackReader, GeometryAndTessellationModulesAreReadAndChecked) {
    Pack p;
    ASSERT_TRUE(kiln::test::OpenInto(StagesPack(), p));
    ASSERT_EQ(p.Count(SectionTag::kVariantStages), 2u);
    const auto stages_of = [&](const char* shader) {
        const PassRec pass = p.Pass(p.Shader(*p.FindShader(shader)).value().first_pass).value();
        return p.Stages(p.Variant(pass.first_variant).value()).value();
    };
    const VariantStagesRec g = stages_of("Test/Geometry");
    ASSERT_NE(g.geometry_module, kNoModule);
    EXPECT_EQ(p.Module(g.geometry_module).value().stage, uint32_t(Stage::kGeometry));
    EXPECT_EQ(g.tess_control_module, kNoModule);
    const VariantStagesRec t = stages_of("Test/Tessellation");
    EXPECT_EQ(t.geometry_module, kNoModule);
    EXPECT_EQ(p.Module(t.tess_control_module).value().stage, uint32_t(Stage::kTessControl));
    EXPECT_EQ(p.Module(t.tess_eval_module).value().stage, uint32_t(Stage::kTessEval));

    // A VSTG slot naming a module of another stage, half a tessellation pair, a variant naming a
    // record past the table: each is a corrupt pack.
    const size_t at = SectionAt(StagesPack(), "VSTG");
    ASSERT_LT(at + 32, StagesPack().size());
    for (const auto& [field, value] :
         std::vector<std::pair<size_t, uint8_t>>{{0, 0}, {16 + 4, 0xff}, {16 + 8, 0xff}}) {
        std::vector<uint8_t> b = StagesPack();
        if (value == 0xff) {
            for (size_t k = 0; k < 4; ++k)
                b[at + field + k] = 0xff;  // kNoModule for one of the pair
        } else {
            for (size_t k = 0; k < 4; ++k)
                b[at + field + k] = 0;  // module 0: a vertex or fragment module
        }
        test::ResealPack(b);
        const Result<Pack> bad = Pack::Open(b);
        ASSERT_FALSE(bad) << field;
        EXPECT_EQ(bad.error().code, DiagCode::kBadPack);
        EXPECT_NE(bad.error().message.find("VSTG"), std::string::npos) << bad.error().message;
    }
    std::vector<uint8_t> b = StagesPack();
    const size_t vari = SectionAt(b, "VARI");
    b[vari + 4] = 9;  // VariantRec::stages of the first variant: past the 2 records
    test::ResealPack(b);
    ASSERT_FALSE(Pack::Open(b));
}

// Three shaders with GrabPasses: unnamed (Test/GrabInvert, Test/GrabEach) and named.
const std::vector<uint8_t>& GrabPack() {
    static const std::vector<uint8_t> bytes =
        PackOf("data/grabpass/invert.shader", "data/grabpass/named.shader");
    return bytes;
}

TEST(PackReader, GrabPassesAreReadInTheirPlaceAndChecked) {
    Pack p;
    ASSERT_TRUE(kiln::test::OpenInto(GrabPack(), p));
    ASSERT_EQ(p.Count(SectionTag::kGrabPasses), 2u);
    const ShaderRec invert = p.Shader(*p.FindShader("Test/GrabInvert")).value();
    ASSERT_EQ(invert.pass_count, 3u);
    EXPECT_FALSE(p.GrabTexture(invert.first_pass));
    ASSERT_TRUE(p.GrabTexture(invert.first_pass + 1));
    EXPECT_EQ(*p.GrabTexture(invert.first_pass + 1), "");
    const PassRec grab = p.Pass(invert.first_pass + 1).value();
    EXPECT_EQ(grab.flags, uint32_t(kPassGrab));
    EXPECT_EQ(grab.variant_count, 0u);
    EXPECT_EQ(grab.keyword_set_count, 0u);
    EXPECT_EQ(PassLabel(p, invert.first_pass + 2), "INVERT");
    const ShaderRec named = p.Shader(*p.FindShader("Test/GrabNamed")).value();
    ASSERT_TRUE(p.GrabTexture(named.first_pass));
    EXPECT_EQ(*p.GrabTexture(named.first_pass), "_Behind");
    EXPECT_EQ(PassLabel(p, named.first_pass + 1), "#2") << "a GrabPass counts, as in Unity";

    // {pass, texture offset, texture length, reserved}: a record naming a pass that is no
    // GrabPass, a pass past the table, a texture past the strings; records out of order.
    const size_t at = SectionAt(GrabPack(), "GRAB");
    ASSERT_LT(at + 32, GrabPack().size());
    for (const auto& [field, value] :
         std::vector<std::pair<size_t, uint32_t>>{{0, 0}, {0, 999}, {4, 0xfffffff0u}, {16, 0}}) {
        std::vector<uint8_t> b = GrabPack();
        for (size_t k = 0; k < 4; ++k)
            b[at + field + k] = uint8_t(value >> (8 * k));
        test::ResealPack(b);
        const Result<Pack> bad = Pack::Open(b);
        ASSERT_FALSE(bad) << field << "=" << value;
        EXPECT_EQ(bad.error().code, DiagCode::kBadPack);
    }
    // A pass with variants flagged as a GrabPass: the first pass of Test/GrabInvert ("RED").
    std::vector<uint8_t> b = GrabPack();
    const size_t pass = SectionAt(b, "PASS") + size_t(invert.first_pass) * 56 + 52;
    b[pass] = uint8_t(kPassGrab);
    test::ResealPack(b);
    const Result<Pack> flagged = Pack::Open(b);
    ASSERT_FALSE(flagged);
    EXPECT_EQ(flagged.error().message,
              "PASS record " + std::to_string(invert.first_pass) + " is out of bounds");
    // A GrabPass whose flag is cleared: its record names a pass that is no GrabPass.
    b = GrabPack();
    b[SectionAt(b, "PASS") + size_t(invert.first_pass + 1) * 56 + 52] = 0;
    test::ResealPack(b);
    const Result<Pack> unflagged = Pack::Open(b);
    ASSERT_FALSE(unflagged);
    EXPECT_EQ(unflagged.error().message, "GRAB holds 2 records for 1 GrabPass passes");
}

TEST(PackReader, KeywordAliasesAreCheckedLikeEveryOtherIndex) {
    const std::vector<uint8_t> good = CompiledPack();
    const size_t at = SectionAt(good, "KALI");
    ASSERT_LT(at + 16, good.size());
    // {set, from, to, reserved}: to == from, to past the set, an unknown set, to an alias.
    for (const auto& [field, value] :
         std::vector<std::pair<size_t, uint8_t>>{{8, 2}, {8, 3}, {0, 99}, {4, 0}}) {
        std::vector<uint8_t> b = good;
        b[at + field] = value;
        test::ResealPack(b);
        const Result<Pack> p = Pack::Open(b);
        ASSERT_FALSE(p) << field << "=" << int(value);
        EXPECT_EQ(p.error().code, DiagCode::kBadPack);
    }
}

TEST(PackReader, ForeignAndOtherVersionFilesGetTypedErrors) {
    std::vector<uint8_t> b = CompiledPack();
    b[0] = 'X';
    EXPECT_EQ(Pack::Open(b).error().code, DiagCode::kNotAPack);
    b = CompiledPack();
    b[4] = 2;  // format major 2
    test::ResealPack(b);
    const Result<Pack> other = Pack::Open(b);
    ASSERT_FALSE(other);
    EXPECT_EQ(other.error().code, DiagCode::kPackVersion);
    EXPECT_EQ(other.error().message, "pack format 2." + std::to_string(kFormatMinor) +
                                         " is not supported (reader knows 1.x)");
    b = CompiledPack();
    b.push_back(0);
    EXPECT_EQ(Pack::Open(b).error().code, DiagCode::kBadPack);
}

TEST(PackReader, ValidChecksumDoesNotMakeBadIndicesSafe) {
    // Rewrite every 4-byte-aligned word to a huge value, one at a time, with a fresh checksum:
    // the reader must reject or accept without reading out of bounds (ASan checks the latter).
    const std::vector<uint8_t>& full = CompiledPack();
    size_t rejected = 0;
    for (size_t i = kHeaderSize; i + 4 <= full.size(); i += 4) {
        std::vector<uint8_t> b = full;
        b[i] = b[i + 1] = b[i + 2] = b[i + 3] = 0xff;
        test::ResealPack(b);
        Pack p;
        if (!kiln::test::OpenInto(b, p)) {
            ++rejected;
            continue;
        }
        // Accepted (e.g. a float or a SPIR-V word changed): lookups stay in bounds.
        for (uint32_t s = 0; s < p.Count(SectionTag::kShaders); ++s) {
            const ShaderRec sr = p.Shader(s).value();
            (void)p.String(sr.name);
            for (uint32_t ps = sr.first_pass; ps < sr.first_pass + sr.pass_count; ++ps) {
                (void)p.FindVariant(ps, p.KeyFor(ps, {"SPOT"}));
            }
        }
    }
    EXPECT_GT(rejected, 100u);
}

}  // namespace
}  // namespace kiln::pack
