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

TEST(Expand, ShaderFeatureVariantsOnlyWhenAskedFor) {
    PassPragmas p;
    p.sets = {Set({"A", "B"}), Set({"", "_NORMALMAP"}, pack::KeywordSetKind::kShaderFeature),
              Set({"", "_EMISSION"}, pack::KeywordSetKind::kShaderFeature)};
    DiagnosticList diags;
    EXPECT_EQ(ExpandVariants(p, {}, "P", "t", {}, diags)->keys.size(), 8u);  // no information: all
    VariantRequest none;
    none.shader_features = std::set<std::string>{};
    EXPECT_EQ(ExpandVariants(p, none, "P", "t", {}, diags)->keys.size(), 2u);
    VariantRequest normal;
    normal.shader_features = std::set<std::string>{"_NORMALMAP"};
    EXPECT_EQ(ExpandVariants(p, normal, "P", "t", {}, diags)->keys.size(), 4u);
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
