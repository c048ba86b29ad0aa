// The engine-keyword stripping profile (variants/strip_profile.h): without a scene, Kiln builds
// the variants a Unity build with default Graphics Settings builds (no lightmap, mixed-lighting,
// fog or instancing variants), so tutorial code that is invalid only in SHADOWS_SHADOWMASK
// variants compiles, as in Unity; --strict-variants builds every combination and fails on them.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

TEST(Profile, AShadowmaskInvalidShaderCompilesUnderTheDefaultProfileAndFailsWhenStrict) {
    const std::string dir = FreshTempDir("profile_shadowmask");
    const std::string shader = DataPath("data/profile/shadowmask_tutorial.shader");
    RunResult r = RunKiln("compile " + shader + " -o " + dir + "/p.kpack --stats");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // multi_compile_fwdbase x multi_compile_fog: 112 x 4 = 448 with Unity's rules, of which the
    // profile keeps the 8 without lightmap, mixing or fog keywords.
    EXPECT_NE(r.out.find("variants 8 (440 more left out by the stripping profile)"),
              std::string::npos)
        << r.out;
    r = RunKiln("variants " + shader);
    EXPECT_NE(r.out.find("440 more left out by the default stripping profile (LIGHTMAP_ON "
                         "DIRLIGHTMAP_COMBINED DYNAMICLIGHTMAP_ON SHADOWS_SHADOWMASK "
                         "LIGHTMAP_SHADOW_MIXING FOG_LINEAR FOG_EXP FOG_EXP2; --strict-variants "
                         "builds them)"),
              std::string::npos)
        << r.out;

    r = RunKiln("compile " + shader + " -o " + dir + "/strict.kpack --strict-variants");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("shadowmask_tutorial.shader:41:39: error: no such field in structure "
                         "'lightmapUV' [K5001]"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("note: smallest failing keyword combination: DIRECTIONAL "
                         "SHADOWS_SHADOWMASK"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir + "/strict.kpack"));
}

TEST(Profile, WithUnitysIncludesTheTutorialShapeFailsOnlyInShadowmaskVariants) {
    const fs::path cgincludes =
        fs::path(KILN_SHARED_DIR) / "unity-builtin-2022.3" / "Shaders" / "CGIncludes";
    if (!fs::exists(cgincludes / "AutoLight.cginc"))
        GTEST_SKIP() << cgincludes << " is absent (../shared not checked out)";
    const std::string dir = FreshTempDir("profile_unity");
    const std::string shader = DataPath("data/profile/shadowmask_unity.shader");
    const std::string include = " -I " + cgincludes.string();
    RunResult r = RunKiln("compile " + shader + include + " -o " + dir + "/p.kpack");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = RunKiln("compile " + shader + include + " -o " + dir + "/strict.kpack --strict-variants");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("error: no such field in structure '_ShadowCoord' [K5001]"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("\"ForwardBase\": DIRECTIONAL SHADOWS_SHADOWMASK"), std::string::npos)
        << r.err;
}

// A keyword a material enables is built whatever the profile says, and --strict-variants does
// not go with --scene (the scene's lookups decide).
TEST(Profile, MaterialsKeepTheirKeywordsAndStrictVariantsIsNoSceneOption) {
    const std::string dir = FreshTempDir("profile_material");
    WriteFile(dir + "/fog.shader", R"(Shader "T/Fog" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex v
    #pragma fragment f
    #pragma multi_compile _ FOG_LINEAR
    float4 v(float4 p : POSITION) : SV_POSITION { return p; }
    float4 f() : SV_Target {
    #ifdef FOG_LINEAR
        return 0.5;
    #endif
        return 1;
    }
    ENDCG
} } })");
    WriteFile(dir + "/fog.material",
              R"({"kiln_material": 1, "shader": "T/Fog", "keywords": ["FOG_LINEAR"]})");
    RunResult r = RunKiln("compile " + dir + "/fog.shader -o " + dir + "/a.kpack --stats");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("variants 1 (1 more left out by the stripping profile)"),
              std::string::npos)
        << r.out;
    r = RunKiln("compile " + dir + "/fog.shader --materials " + dir + "/fog.material -o " + dir +
                "/b.kpack --stats");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("permutations 2, variants 2,"), std::string::npos) << r.out;
    r = RunKiln("compile " + dir + "/fog.shader --usage " + dir +
                "/none.json --strict-variants -o " + dir + "/c.kpack");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--strict-variants do not apply with --scene or --usage"),
              std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace kiln::test
