#include "variants/expand.h"

#include <gtest/gtest.h>

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
        seen.insert(DescribeKeywords(EnabledKeywords(p.sets, ex->layout, k)));
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
            out.insert(DescribeKeywords(EnabledKeywords(p.sets, ex->layout, k)));
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

TEST(Expand, ShortcutRulesLeaveUnitysVariantList) {
    DiagnosticList diags;
    auto expand = [&](const std::string& pragma) {
        PassPragmas p;
        auto shortcut = BuiltinShortcut(pragma);
        EXPECT_TRUE(shortcut) << pragma;
        for (const auto& kws : shortcut->sets)
            p.sets.push_back(Set(kws));
        p.rules = shortcut->rules;
        std::set<std::string> out;
        const auto ex = ExpandVariants(p, {}, "P", "t", {}, diags);
        for (auto k : ex->keys)
            out.insert(DescribeKeywords(EnabledKeywords(p.sets, ex->layout, k)));
        return out;
    };
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

}  // namespace
}  // namespace kiln::variants
