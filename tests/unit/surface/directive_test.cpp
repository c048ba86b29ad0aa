// `#pragma surface` read into a SurfaceDirective (surface/directive.h): Unity's own lines and the
// mistakes a user makes in one; tests/unit/surface/corpus_test.cpp reads every line of the corpora.
#include "surface/directive.h"

#include <gtest/gtest.h>

#include "shaderlab/program_scan.h"
#include "support/test_support.h"

namespace kiln::surface {
namespace {

std::optional<SurfaceDirective> Parse(const std::string& line, DiagnosticList& diags) {
    const std::vector<shaderlab::Pragma> pragmas = shaderlab::ScanPragmas(line, {0, 1, 1});
    EXPECT_EQ(pragmas.size(), 1u) << line;
    return pragmas.empty() ? std::nullopt : ParseSurfaceDirective(pragmas[0], "t.shader", diags);
}

TEST(SurfaceDirective, ReadsTheTerrainAddPassLine) {
    DiagnosticList diags;
    const auto d = Parse(
        "#pragma surface surf Lambert decal:add vertex:SplatmapVert "
        "finalcolor:SplatmapFinalColor finalgbuffer:SplatmapFinalGBuffer fullforwardshadows nometa",
        diags);
    ASSERT_TRUE(d) << test::Summarize(diags);
    EXPECT_EQ(d->function.text, "surf");
    EXPECT_EQ(d->lighting.text, "Lambert");
    EXPECT_TRUE(d->BuiltinLighting());
    EXPECT_FALSE(d->PhysicallyBased());
    EXPECT_EQ(d->decal, DecalMode::kAdd);
    ASSERT_TRUE(d->vertex);
    EXPECT_EQ(d->vertex->text, "SplatmapVert");
    EXPECT_EQ(d->vertex->range.begin.column, 47u);  // after "vertex:"
    EXPECT_EQ(d->final_color->text, "SplatmapFinalColor");
    EXPECT_EQ(d->final_gbuffer->text, "SplatmapFinalGBuffer");
    EXPECT_FALSE(d->final_prepass);
    EXPECT_EQ(d->flags, (std::set<std::string>{"fullforwardshadows", "nometa"}));
    EXPECT_TRUE(diags.all().empty());
}

TEST(SurfaceDirective, AlphaModesCutoutAndExcludedPaths) {
    DiagnosticList diags;
    EXPECT_EQ(Parse("#pragma surface surf Standard alpha", diags)->alpha, AlphaMode::kAuto);
    EXPECT_EQ(Parse("#pragma surface surf Standard alpha:fade", diags)->alpha, AlphaMode::kFade);
    EXPECT_EQ(Parse("#pragma surface surf Standard alpha:premul", diags)->alpha,
              AlphaMode::kPremul);
    EXPECT_EQ(Parse("#pragma surface surf Lambert", diags)->alpha, AlphaMode::kOpaque);
    const auto d = Parse(
        "#pragma surface surf ToonRamp alphatest:_Cutoff exclude_path:deferred "
        "exclude_path:prepass keepalpha",
        diags);
    ASSERT_TRUE(d);
    EXPECT_FALSE(d->BuiltinLighting());  // LightingToonRamp, the shader's own
    EXPECT_EQ(d->alpha_test->text, "_Cutoff");
    EXPECT_EQ(d->excluded_paths, (std::set<std::string>{"deferred", "prepass"}));
    EXPECT_TRUE(d->Has("keepalpha"));
    EXPECT_TRUE(diags.all().empty()) << test::Summarize(diags);
}

TEST(SurfaceDirective, MistakesNameTheClosestOption) {
    DiagnosticList diags;
    EXPECT_FALSE(Parse("#pragma surface surf Lambert fullforwardshadow nofogg", diags));
    EXPECT_EQ(test::Summarize(diags),
              "K4016 1:30 error: unknown surface shader option 'fullforwardshadow'; did you mean "
              "'fullforwardshadows'?\n"
              "K4016 1:48 error: unknown surface shader option 'nofogg'; did you mean 'nofog'?\n");
    diags = {};
    EXPECT_FALSE(Parse("#pragma surface surf Standard alpha:fad vertx:vert", diags));
    EXPECT_EQ(test::Summarize(diags),
              "K4016 1:37 error: 'alpha:fad': expected auto, blend, fade or premul; did you mean "
              "'fade'?\n"
              "K4016 1:41 error: unknown surface shader option 'vertx:vert'; did you mean "
              "'vertex:'?\n");
    diags = {};
    EXPECT_FALSE(Parse("#pragma surface surf", diags));
    EXPECT_EQ(test::Summarize(diags),
              "K4009 1:1 error: '#pragma surface' needs a lighting model after the surface "
              "function (#pragma surface surf Lambert)\n");
    diags = {};
    EXPECT_FALSE(Parse("#pragma surface surf Lambert vertex:", diags));
    EXPECT_EQ(test::Summarize(diags),
              "K4009 1:30 error: surface option 'vertex:' needs a value after the colon\n");
}

}  // namespace
}  // namespace kiln::surface
