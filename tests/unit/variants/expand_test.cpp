#include "variants/expand.h"

#include <gtest/gtest.h>

#include "support/compile_support.h"
#include "support/test_support.h"
#include "variants/pass_pragmas.h"

namespace kiln::variants {
namespace {

KeywordSet Set(std::vector<std::string> kws,
               pack::KeywordSetKind kind = pack::KeywordSetKind::kMultiCompile) {
    KeywordSet s;
    s.kind = kind;
    s.keywords = std::move(kws);
    s.pragma = kind == pack::KeywordSetKind::kMultiCompile ? "multi_compile" : "shader_feature";
    return s;
}

TEST(Expand, LayoutPacksSetsInDeclarationOrder) {
    auto layout = LayoutSets({Set({"A", "B", "C"}), Set({"", "X"}), Set({"ONLY"})});
    ASSERT_TRUE(layout);
    ASSERT_EQ(layout->size(), 3u);
    EXPECT_EQ((*layout)[0].shift, 0u);
    EXPECT_EQ((*layout)[0].bits, 2u);
    EXPECT_EQ((*layout)[1].shift, 2u);
    EXPECT_EQ((*layout)[1].bits, 1u);
    EXPECT_EQ((*layout)[2].bits, 0u);
}

TEST(Expand, CartesianProductPicksOneKeywordPerSet) {
    PassPragmas p;
    p.sets = {Set({"DIRECTIONAL", "POINT", "SPOT"}), Set({"", "SHADOWS"})};
    DiagnosticList diags;
    auto ex = ExpandVariants(p, {}, "\"FORWARD\"", "t.shader", {}, diags);
    ASSERT_TRUE(ex);
    EXPECT_EQ(ex->keys.size(), 6u);
    EXPECT_EQ(ex->permutations, 6u);
    std::set<std::string> seen;
    for (auto k : ex->keys)
        seen.insert(pack::JoinKeywords(EnabledKeywords(p.sets, ex->layout, k)));
    EXPECT_EQ(seen, (std::set<std::string>{"DIRECTIONAL", "POINT", "SPOT", "DIRECTIONAL SHADOWS",
                                           "POINT SHADOWS", "SPOT SHADOWS"}));
}

TEST(Expand, ShaderFeatureCombinationsComeFromMaterialsAsInUnity) {
    PassPragmas p;
    p.sets = {Set({"A", "B"}), Set({"", "_NORMALMAP"}, pack::KeywordSetKind::kShaderFeature),
              Set({"", "_EMISSION"}, pack::KeywordSetKind::kShaderFeature)};
    auto described = [&](const VariantRequest& r) {
        DiagnosticList diags;
        std::set<std::string> out;
        const auto ex = ExpandVariants(p, r, "P", "t", {}, diags);
        for (auto k : ex->keys)
            out.insert(pack::JoinKeywords(EnabledKeywords(p.sets, ex->layout, k)));
        EXPECT_FALSE(diags.has_errors());
        return out;
    };
    // No materials: only the all-off shader_feature combination, times the multi_compile set.
    EXPECT_EQ(described({}), (std::set<std::string>{"A", "B"}));
    // One material with both keywords: that combination, not the product of the two sets.
    VariantRequest both;
    both.feature_combinations = {{"_NORMALMAP", "_EMISSION"}};
    EXPECT_EQ(described(both), (std::set<std::string>{"A", "B", "A _NORMALMAP _EMISSION",
                                                      "B _NORMALMAP _EMISSION"}));
    // Two materials give two combinations; keywords no set declares are ignored.
    VariantRequest two;
    two.feature_combinations = {{"_NORMALMAP"}, {"_EMISSION", "UNRELATED"}, {"_NORMALMAP"}};
    DiagnosticList diags;
    auto ex = ExpandVariants(p, two, "P", "t", {}, diags);
    EXPECT_EQ(ex->keys.size(), 6u);
    EXPECT_EQ(ex->feature_combinations, 3u);
    EXPECT_EQ(ex->permutations, 6u);
    // --all-features: the full product.
    VariantRequest all;
    all.all_features = true;
    EXPECT_EQ(described(all).size(), 8u);
}

// The variants a shortcut gives (--strict-variants: every combination its rules allow; else the
// default stripping profile's).
std::set<std::string> ExpandShortcut(const std::string& pragma,
                                     bool strict,
                                     DiagnosticList& diags) {
    PassPragmas p;
    auto shortcut = BuiltinShortcut(pragma);
    EXPECT_TRUE(shortcut) << pragma;
    for (const auto& kws : shortcut->sets)
        p.sets.push_back(Set(kws));
    p.rules = shortcut->rules;
    VariantRequest request;
    request.strict_variants = strict;
    std::set<std::string> out;
    const auto ex = ExpandVariants(p, request, "P", "t", {}, diags);
    for (auto k : ex->keys)
        out.insert(pack::JoinKeywords(EnabledKeywords(p.sets, ex->layout, k)));
    return out;
}

TEST(Expand, ShortcutRulesLeaveUnitysVariantList) {
    DiagnosticList diags;
    auto expand = [&](const std::string& pragma) { return ExpandShortcut(pragma, true, diags); };
    const auto fullshadows = expand("multi_compile_fwdadd_fullshadows");
    EXPECT_EQ(fullshadows.size(), 47u);  // 5 lights x 3 + 8 shadowed x 4 mixing choices
    EXPECT_TRUE(fullshadows.count("SPOT SHADOWS_DEPTH SHADOWS_SOFT"));
    EXPECT_TRUE(fullshadows.count("POINT_COOKIE SHADOWS_CUBE"));
    EXPECT_TRUE(fullshadows.count("DIRECTIONAL SHADOWS_SCREEN"));
    EXPECT_TRUE(fullshadows.count("DIRECTIONAL SHADOWS_SHADOWMASK LIGHTMAP_SHADOW_MIXING"));
    EXPECT_FALSE(fullshadows.count("DIRECTIONAL SHADOWS_DEPTH"));  // Unity never builds it
    EXPECT_FALSE(fullshadows.count("DIRECTIONAL SHADOWS_SCREEN SHADOWS_SOFT"));
    EXPECT_FALSE(fullshadows.count("POINT LIGHTMAP_SHADOW_MIXING"));
    EXPECT_EQ(expand("multi_compile_lightpass"), fullshadows);
    EXPECT_EQ(expand("multi_compile_fwdadd").size(), 5u);
    const auto base = expand("multi_compile_fwdbase");
    EXPECT_EQ(base.size(), 112u);
    EXPECT_TRUE(base.count("DIRECTIONAL LIGHTPROBE_SH VERTEXLIGHT_ON"));
    EXPECT_FALSE(base.count("DIRECTIONAL LIGHTMAP_ON VERTEXLIGHT_ON"));
    EXPECT_FALSE(base.count("DIRECTIONAL DIRLIGHTMAP_COMBINED"));
    EXPECT_EQ(expand("multi_compile_shadowcaster"),
              (std::set<std::string>{"SHADOWS_DEPTH", "SHADOWS_CUBE"}));
    EXPECT_EQ(expand("multi_compile_prepassfinal").size(), 88u);
    EXPECT_FALSE(diags.has_errors());
}

// Unity's stripping with default Graphics Settings and no scene (variants/strip_profile.h): no
// lightmap, mixed-lighting, fog or instancing variant; what the runtime asks for stays.
TEST(Expand, TheDefaultProfileLeavesOutWhatUnityStripsWithoutAScene) {
    DiagnosticList diags;
    const auto base = ExpandShortcut("multi_compile_fwdbase", false, diags);
    EXPECT_EQ(
        base,
        (std::set<std::string>{
            "DIRECTIONAL", "DIRECTIONAL LIGHTPROBE_SH", "DIRECTIONAL LIGHTPROBE_SH VERTEXLIGHT_ON",
            "DIRECTIONAL SHADOWS_SCREEN", "DIRECTIONAL SHADOWS_SCREEN LIGHTPROBE_SH",
            "DIRECTIONAL SHADOWS_SCREEN LIGHTPROBE_SH VERTEXLIGHT_ON",
            "DIRECTIONAL SHADOWS_SCREEN VERTEXLIGHT_ON", "DIRECTIONAL VERTEXLIGHT_ON"}));
    // 5 lights without shadows, and 8 shadowed ones: no SHADOWS_SHADOWMASK, no mixing.
    const auto add = ExpandShortcut("multi_compile_fwdadd_fullshadows", false, diags);
    EXPECT_EQ(add.size(), 13u);
    EXPECT_TRUE(add.count("SPOT SHADOWS_DEPTH SHADOWS_SOFT"));
    EXPECT_EQ(ExpandShortcut("multi_compile_fog", false, diags),
              (std::set<std::string>{"(no keywords)"}));
    EXPECT_EQ(ExpandShortcut("multi_compile_instancing", false, diags),
              (std::set<std::string>{"(no keywords)"}));
    EXPECT_FALSE(diags.has_errors());

    // A set that would keep no choice keeps them all; a keyword a material asks for is kept.
    PassPragmas p;
    p.sets = {Set({"FOG_LINEAR", "FOG_EXP"}), Set({"", "LIGHTMAP_ON"}), Set({"", "INSTANCING_ON"})};
    VariantRequest request;
    request.feature_combinations = {{"INSTANCING_ON"}};
    const auto ex = ExpandVariants(p, request, "P", "t", {}, diags);
    ASSERT_TRUE(ex);
    EXPECT_EQ(ex->keys.size(), 4u);  // 2 fog modes x (_, INSTANCING_ON)
    EXPECT_EQ(ex->profile_stripped, 4u);
    EXPECT_EQ(ex->profile_keywords, (std::vector<std::string>{"LIGHTMAP_ON"}));
}

TEST(Expand, SkipVariantsRemovesEveryVariantWithTheKeyword) {
    PassPragmas p;
    p.sets = {Set({"DIRECTIONAL", "POINT", "SPOT"}), Set({"", "SHADOWS"})};
    p.skip_variants = {{"SPOT", {}}};
    DiagnosticList diags;
    auto ex = ExpandVariants(p, {}, "P", "t", {}, diags);
    ASSERT_TRUE(ex);
    EXPECT_EQ(ex->keys.size(), 4u);
    p.skip_variants = {{"DIRECTIONAL", {}}, {"POINT", {}}, {"SPOT", {}}};
    EXPECT_FALSE(ExpandVariants(p, {}, "\"FORWARD\"", "t", {}, diags));
    EXPECT_EQ(test::Summarize(diags),
              "K4013 1:1 error: skip_variants removes every variant of pass \"FORWARD\"\n");
}

TEST(Expand, MaxVariantsErrorShowsTheMultiplication) {
    PassPragmas p;
    p.sets = {Set({"A", "B", "C"}), Set({"", "X"}), Set({"", "Y"}), Set({"", "F1", "F2", "F3"}),
              Set({"ALWAYS"})};
    VariantRequest r;
    r.max_variants = 40;
    DiagnosticList diags;
    EXPECT_FALSE(ExpandVariants(p, r, "\"FORWARD\"", "t.shader", {}, diags));
    ASSERT_EQ(diags.all().size(), 1u);
    EXPECT_EQ(diags.all()[0].message,
              "3 x 2 x 2 x 4 = 48 variants in pass \"FORWARD\", over the limit of 40 "
              "(--max-variants)");
    EXPECT_EQ(diags.all()[0].notes.size(), 4u);
    r.max_variants = 48;
    DiagnosticList ok;
    EXPECT_EQ(ExpandVariants(p, r, "\"FORWARD\"", "t.shader", {}, ok)->keys.size(), 48u);
}

TEST(Expand, MaxVariantsCountsWhatTheRulesLeave) {
    // 3 x 2 x 2 x 4 = 48 combinations; the rule keeps X only with B or C and skip_variants drops
    // F3: 48 - 8 (A with X) = 40 - 10 (F3 among them) = 30 variants.
    PassPragmas p;
    p.sets = {Set({"A", "B", "C"}), Set({"", "X"}), Set({"", "Y"}), Set({"", "F1", "F2", "F3"})};
    p.rules = {{"X", {"B", "C"}, {}, "multi_compile_test"}};
    p.skip_variants = {{"F3", {}}};
    VariantRequest r;
    r.max_variants = 30;
    DiagnosticList ok;
    auto ex = ExpandVariants(p, r, "\"FORWARD\"", "t.shader", {}, ok);
    ASSERT_TRUE(ex);
    EXPECT_EQ(ex->keys.size(), 30u);
    r.max_variants = 29;
    DiagnosticList diags;
    EXPECT_FALSE(ExpandVariants(p, r, "\"FORWARD\"", "t.shader", {}, diags));
    ASSERT_EQ(diags.all().size(), 1u);
    EXPECT_EQ(diags.all()[0].message,
              "30 variants in pass \"FORWARD\" (3 x 2 x 2 x 4 = 48 keyword combinations, less "
              "those the shortcut rules and skip_variants exclude), over the limit of 29 "
              "(--max-variants)");
}

TEST(Expand, KeyWiderThan64BitsIsRejected) {
    PassPragmas p;
    for (int i = 0; i < 65; ++i)
        p.sets.push_back(Set({"", "K" + std::to_string(i)}));
    DiagnosticList diags;
    EXPECT_FALSE(ExpandVariants(p, {}, "P", "t", {}, diags));
    EXPECT_EQ(diags.all()[0].code, DiagCode::kVariantKeyTooWide);
}

TEST(ExpandRequested, BuildsExactlyTheRequestedKeysAndSaysWhyOthersAreNot) {
    PassPragmas p;
    auto shortcut = BuiltinShortcut("multi_compile_fwdadd_fullshadows");
    for (const auto& kws : shortcut->sets)
        p.sets.push_back(Set(kws));
    p.rules = shortcut->rules;
    for (auto& r : p.rules)
        r.pragma = "multi_compile_fwdadd_fullshadows";
    p.sets.push_back(Set({"", "_NORMALMAP"}, pack::KeywordSetKind::kShaderFeature));
    p.skip_variants = {{"SPOT", {}}};
    DiagnosticList diags;
    std::vector<ExcludedRequest> excluded;
    const auto ex = ExpandRequested(p,
                                    {{"POINT", "_NORMALMAP"},
                                     {"POINT", "_NORMALMAP", "NOT_DECLARED"},  // the same key
                                     {"SPOT"},
                                     {"DIRECTIONAL", "SHADOWS_DEPTH"},
                                     {}},
                                    4096, "P", "t", {}, diags, excluded);
    ASSERT_TRUE(ex);
    EXPECT_FALSE(diags.has_errors());
    std::vector<std::string> kept;
    for (auto k : ex->keys)
        kept.push_back(pack::JoinKeywords(EnabledKeywords(p.sets, ex->layout, k)));
    // {} is the key of every set's first choice: POINT (the shortcut's first light type).
    EXPECT_EQ(kept, (std::vector<std::string>{"POINT", "POINT _NORMALMAP"}));
    ASSERT_EQ(excluded.size(), 2u);
    EXPECT_EQ(excluded[0].request, 2u);
    EXPECT_EQ(excluded[0].reason, "'#pragma skip_variants' names 'SPOT'");
    EXPECT_EQ(excluded[1].reason,
              "'#pragma multi_compile_fwdadd_fullshadows' never builds SHADOWS_DEPTH without one "
              "of SPOT");
    EXPECT_EQ(ex->permutations, 5u * 4 * 2 * 2 * 2 * 2);
}

// 2^40 declared combinations: the expansion works from the requests alone (enumerating the
// product would not finish).
TEST(ExpandRequested, NeverEnumeratesTheProduct) {
    PassPragmas p;
    for (int i = 0; i < 40; ++i)
        p.sets.push_back(Set({"", "K" + std::to_string(i)}));
    DiagnosticList diags;
    std::vector<ExcludedRequest> excluded;
    const auto ex = ExpandRequested(p, {{"K3", "K39"}}, 4096, "P", "t", {}, diags, excluded);
    ASSERT_TRUE(ex);
    ASSERT_EQ(ex->keys.size(), 1u);
    EXPECT_EQ(ex->permutations, uint64_t{1} << 40);
    EXPECT_EQ(EnabledKeywords(p.sets, ex->layout, ex->keys[0]),
              (std::vector<std::string>{"K3", "K39"}));
    EXPECT_FALSE(ExpandRequested(p, {{"K1"}, {"K2"}}, 1, "\"P\"", "t", {}, diags, excluded));
    EXPECT_EQ(diags.all().back().message,
              "2 variants requested for pass \"P\", over the limit of 1 (--max-variants)");
}

// The compiler maps a recorded lookup back to a key as the pack reader does (Pack::KeyFor).
TEST(ExpandRequested, KeysAgreeWithThePackReader) {
    test::ScratchDir dir;
    const std::string shader = dir.Write(
        "k.shader",
        "Shader \"K\" { SubShader { Pass { CGPROGRAM\n#pragma vertex v\n#pragma fragment f\n"
        "#pragma multi_compile DIRECTIONAL POINT SPOT\n#pragma multi_compile _ A B\n"
        "#pragma shader_feature C\nfloat4 v(float4 p : POSITION) : SV_POSITION { return p; }\n"
        "float4 f() : SV_Target { return 0; }\nENDCG } } }\n");
    CompileOptions options;
    options.all_features = true;
    const test::CompileRun run = test::Compile({shader}, options);
    ASSERT_TRUE(run.out.ok) << test::Summarize(run.diags);
    pack::Pack pk;
    ASSERT_TRUE(test::OpenInto(run.out.pack, pk));
    DiagnosticList diags;
    const PassPragmas p = [&] {
        PassPragmas out;
        out.sets = {Set({"DIRECTIONAL", "POINT", "SPOT"}), Set({"", "A", "B"}),
                    Set({"", "C"}, pack::KeywordSetKind::kShaderFeature)};
        return out;
    }();
    const auto layout = LayoutSets(p.sets);
    ASSERT_TRUE(layout);
    for (const std::vector<std::string>& request :
         std::vector<std::vector<std::string>>{{},
                                               {"SPOT", "B", "C"},
                                               {"A", "POINT"},
                                               {"C", "X", "DIRECTIONAL", "POINT"},
                                               {"B", "A"}}) {
        EXPECT_EQ(KeyForKeywords(p.sets, *layout, request).bits(), pk.KeyFor(0, request).bits())
            << pack::JoinKeywords(request);
    }
}

}  // namespace
}  // namespace kiln::variants
