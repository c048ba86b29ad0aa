// `#pragma surface` read into a SurfaceDirective (surface/directive.h): Unity's own lines, every
// line of the compatibility corpora, and the mistakes a user makes in one.
#include "surface/directive.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "shaderlab/program_scan.h"
#include "support/test_support.h"

namespace kiln::surface {
namespace {

namespace fs = std::filesystem;

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

// Every `#pragma surface` line of Unity's built-in shaders (three LTS lines) and of the tutorial
// corpus reads without a diagnostic: the options Kiln knows are the options real shaders use.
TEST(SurfaceDirective, EveryLineOfTheCorporaReads) {
    const fs::path shared(KILN_SHARED_DIR);
    size_t lines = 0;
    for (const char* corpus : {"unity-builtin-2022.3", "unity-builtin-2018.4",
                               "unity-builtin-6000.0", "ronja-tutorials"}) {
        if (!fs::exists(shared / corpus))
            continue;
        for (const auto& entry : fs::recursive_directory_iterator(shared / corpus)) {
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || (ext != ".shader" && ext != ".cginc"))
                continue;
            std::ifstream in(entry.path());
            std::stringstream text;
            text << in.rdbuf();
            for (const shaderlab::Pragma& p : shaderlab::ScanPragmas(text.str(), {0, 1, 1})) {
                if (p.name != "surface")
                    continue;
                DiagnosticList diags;
                EXPECT_TRUE(ParseSurfaceDirective(p, entry.path().string(), diags))
                    << entry.path() << ": " << test::Summarize(diags);
                ++lines;
            }
        }
    }
    if (lines == 0)
        GTEST_SKIP() << shared << " holds no corpus (../shared not checked out)";
    EXPECT_GT(lines, 200u);
}

}  // namespace
}  // namespace kiln::surface
