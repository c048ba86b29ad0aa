// Kiln's include layer follows --unity-version (hlsl/unity_versions.h): the files that release
// ships, what half and fixed are on its Vulkan back end, and the names only some releases
// declare (docs/unity-compat.md, "Unity versions").
#include <gtest/gtest.h>

#include <string>

#include "support/test_support.h"

namespace kiln::test {
namespace {

std::string Program(const std::string& includes, const std::string& fragment_body) {
    return R"(Shader "T/Versions" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex v
    #pragma fragment f
    #include "UnityCG.cginc"
)" + includes +
           R"(
    float4 v(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
    fixed4 f() : SV_Target {
)" + fragment_body +
           R"(
    }
    ENDCG
} } })";
}

TEST(UnityVersion, AFileOnlyLaterReleasesShipIsMissingForAnEarlierOne) {
    const std::string dir = FreshTempDir("unity_version_files");
    WriteFile(dir + "/gamut.shader",
              Program("    #include \"UnityColorGamut.cginc\"",
                      "        return fixed4(LinearToSRGB(float3(0.5, 0.5, 0.5)), 1);"));
    RunResult r = RunKiln("compile " + dir + "/gamut.shader -o " + dir + "/a.kpack");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = RunKiln("compile " + dir + "/gamut.shader --unity-version 2018.4 -o " + dir + "/b.kpack");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("gamut.shader:6:15: error: cannot find include file "
                         "'UnityColorGamut.cginc' [K5001]"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("note: Unity 2018.4 does not ship 'UnityColorGamut.cginc' (Unity 2019.1 "
                         "and later do; --unity-version selects the release)"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("(Kiln's templates, Unity 2018.4's files)"), std::string::npos) << r.err;

    // A file of Unity's that Kiln's layer does not have says so, and where to get it.
    WriteFile(dir + "/indirect.shader",
              Program("    #include \"UnityIndirect.cginc\"", "        return 1;"));
    r = RunKiln("compile " + dir + "/indirect.shader -o " + dir + "/c.kpack");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("note: 'UnityIndirect.cginc' is part of Unity 2019.1 and later, not of "
                         "Kiln's include layer: compile against Unity's own CGIncludes (-I) for "
                         "it"),
              std::string::npos)
        << r.err;
}

TEST(UnityVersion, TheLightPrePassFormsExistOnlyWhereUnityShippedThem) {
    const std::string dir = FreshTempDir("unity_version_prepass");
    WriteFile(dir + "/prepass.shader",
              Program("    #include \"Lighting.cginc\"",
                      "        SurfaceOutput s = (SurfaceOutput)0;\n"
                      "        s.Albedo = 1;\n"
                      "        s.Gloss = 1;\n"
                      "        return LightingLambert_PrePass(s, half4(0.5, 0.5, 0.5, 1)) +\n"
                      "               LightingBlinnPhong_PrePass(s, half4(0.5, 0.5, 0.5, 1));"));
    RunResult r =
        RunKiln("compile " + dir + "/prepass.shader --unity-version 2018.4 -o " + dir + "/a.kpack");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = RunKiln("compile " + dir + "/prepass.shader --unity-version 2022.3 -o " + dir + "/b.kpack");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("error: unknown function 'LightingLambert_PrePass'"), std::string::npos)
        << r.err;
}

// Unity 2018 made half and fixed min16float on every Vulkan target; 2019 and later only on
// mobile ones. Without --precision the pack records the release's choice.
TEST(UnityVersion, HalfIsWhatTheReleaseMadeItOnDesktopVulkan) {
    const std::string dir = FreshTempDir("unity_version_precision");
    WriteFile(dir + "/p.shader", Program("", "        half h = 0.5;\n        return h;"));
    for (const auto& [options, precision] :
         {std::pair<std::string, std::string>{"--unity-version 2018.4", "relaxed"},
          {"--unity-version 2022.3", "full"},
          {"", "full"},
          {"--unity-version 2018.4 --precision full", "full"},
          {"--unity-version 6000.0 --precision relaxed", "relaxed"}}) {
        RunResult r =
            RunKiln("compile " + dir + "/p.shader " + options + " -o " + dir + "/p.kpack");
        ASSERT_EQ(r.exit_code, 0) << options << ": " << r.err;
        r = RunKiln("info " + dir + "/p.kpack");
        EXPECT_NE(r.out.find("precision " + precision + "\n"), std::string::npos)
            << options << ": " << r.out;
    }
}

}  // namespace
}  // namespace kiln::test
