// kiln stability through the CLI on lavapipe with the validation layer: the shipped templates on
// the adversarial grids and the shipped materials under extreme set-ups are clean; an unguarded
// GGX planted in front of the templates and the lecture's two traps are caught and named with
// the inputs that break them.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

// Replaces `from` (which must be there) by `to` in `text`.
void Plant(std::string& text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << "the shipped KilnBRDF.cginc no longer has: " << from;
    text.replace(at, from.size(), to);
}

TEST(StabilityCli, TheShippedTemplatesPassEveryGrid) {
    const RunResult r = RunKiln("stability");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    for (const char* name : {"BRDF1_Unity_PBS", "GGX terms", "BRDF choices", "Blinn-Phong",
                             "Attenuation ", "Attenuation_SpotCone", "SH_Irradiance",
                             "Unity half terms", "Lambert (Fd_Lambert)", "GGX, Smith, F = 1"}) {
        EXPECT_NE(r.out.find(name), std::string::npos) << name << "\n" << r.out;
    }
    // Both builds by default: the 32-bit one and the binary16 one (lavapipe has shaderFloat16).
    EXPECT_NE(r.out.find("32-bit-precision build (--precision full)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("binary16-precision build (--precision half)"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("16 grid cases and 2 white-furnace checks in 2 builds"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(": 0 failed"), std::string::npos) << r.out;
}

TEST(StabilityCli, AnUnclampedGgxPlantedBeforeTheTemplatesIsCaughtWithItsInput) {
    const std::string dir = FreshTempDir("kiln_stability_planted");
    std::string brdf = ReadFile(DataPath("../templates/KilnBRDF.cginc"));
    Plant(brdf, "clamp(perceptualRoughness, KILN_MIN_PERCEPTUAL_ROUGHNESS, 1.0)",
          "perceptualRoughness");
    Plant(brdf, "max(d * d, 1e-20)", "(d * d)");
    WriteFile(dir + "/KilnBRDF.cginc", brdf);
    const RunResult r = RunKiln("stability -I " + dir);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    // D = 0 / 0 at n . h = 1 and roughness 0: NaN, named with the grid point.
    EXPECT_NE(r.err.find("GGX terms: 8 of 360 values are not finite, the first at n . h = n . v 1, "
                         "n . l 0, perceptual roughness 0: r = NaN [K0028]"),
              std::string::npos)
        << r.err;
    // In the full BRDF the clamp to the binary16 range hides the NaN on lavapipe (min(NaN, x) is
    // x there); the error against the reference still names the point.
    EXPECT_NE(r.err.find("BRDF1_Unity_PBS: relative error"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("perceptual roughness 0"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

// Unity's own guard in SmithVisibilityTerm, 1 / (x + 1e-5): 1e5 at k = 0 is beyond binary16. On
// lavapipe the binary16 build does not overflow (its compiler folds the quarter into the
// quotient), but the guard is caught against the reference in both builds, with its input.
TEST(StabilityCli, UnitysSmithGuardPlantedBeforeTheTemplatesIsCaughtInBothBuilds) {
    const std::string dir = FreshTempDir("kiln_stability_smith");
    std::string brdf = ReadFile(DataPath("../templates/UnityStandardBRDF.cginc"));
    Plant(brdf, "1.0 / max(gL * gV, KILN_HALF_MIN)", "1.0 / (gL * gV + 1e-5f)");
    WriteFile(dir + "/UnityStandardBRDF.cginc", brdf);
    const RunResult r = RunKiln("stability -I " + dir);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    for (const char* build : {"full", "half"}) {
        EXPECT_NE(
            r.err.find(std::string("--precision ") + build + ": Unity half terms: relative error"),
            std::string::npos)
            << r.err;
    }
    EXPECT_NE(r.err.find("at n . v 0, n . l 0, perceptual roughness 0, l . h 0: g = "),
              std::string::npos)
        << r.err;
    fs::remove_all(dir);
}

TEST(StabilityCli, TheShippedMaterialsStayFiniteInPlainAndStrictBuilds) {
    std::string args;
    for (const char* m :
         {"Unlit", "Lambert", "LambertAmbient", "BlinnPhong", "BlinnPhongTextured",
          "EnergyConserving", "Standard", "StandardMetallic", "MultiLight", "Deferred"}) {
        args += std::string(" --material ") + DataPath("../materials/") + m + ".material";
    }
    const RunResult plain = RunKiln("stability" + args);
    ASSERT_EQ(plain.exit_code, 0) << plain.out << plain.err;
    EXPECT_NE(plain.out.find("10 materials, 17 variants"), std::string::npos) << plain.out;
    EXPECT_NE(plain.out.find(": 0 findings"), std::string::npos) << plain.out;
    std::string sources;
    for (const fs::directory_entry& e : fs::directory_iterator(DataPath("../materials"))) {
        if (e.path().extension() == ".shader")
            sources += " --source " + e.path().string();
    }
    const RunResult strict = RunKiln("stability" + args + sources);
    ASSERT_EQ(strict.exit_code, 0) << strict.out << strict.err;
    EXPECT_NE(strict.out.find("strict: pow(x, y)"), std::string::npos) << strict.out;
    EXPECT_NE(strict.out.find(": 0 findings"), std::string::npos) << strict.out;
}

TEST(StabilityCli, TheLecturesTwoTrapsAreNamedWithTheirInputs) {
    const std::string dir = FreshTempDir("kiln_stability_lecture");
    WriteFile(dir + "/ec.material",
              R"({"kiln_material": 1, "shader": "Lecture/EnergyConservation", "properties": {}})");
    const RunResult r =
        RunKiln("stability --source " + DataPath("lecture/06_EnergyConservation.shader") +
                " --material " + dir + "/ec.material");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    // normalize(lightDir + viewDir) with the light exactly opposite the view: the centre pixel.
    EXPECT_NE(r.err.find("normalize of a zero (or within-rounding-of-zero) vector (--precision "
                         "full): pass "
                         "'ForwardBase' variant '(no keywords)' with (material), directional light "
                         "from behind the surface (n . l = -1): 3 non-finite values, the first at "
                         "pixel (16, 16) where n . l = -1, n . v = 1, l . v = -1 (l = -v)"),
              std::string::npos)
        << r.err;
    // pow(DotClamped(...), _Smoothness * 100) at smoothness 0 where n . h <= 0: pow(0, 0).
    EXPECT_NE(r.err.find("pow(x, y) with x < 0, or x = 0 and y <= 0 (undefined in SPIR-V) "
                         "(--precision full): pass "
                         "'ForwardBase' variant '(no keywords)' with _Smoothness = 0 (Range min), "
                         "directional light from behind the surface"),
              std::string::npos)
        << r.err;
    // Smoothness 0.5 (the material's) never meets pow's undefined case.
    EXPECT_EQ(r.err.find("(undefined in SPIR-V) (--precision full): pass 'ForwardBase' variant "
                         "'(no keywords)' with (material)"),
              std::string::npos)
        << r.err;
    fs::remove_all(dir);
}

TEST(StabilityCli, AMaterialWhoseShaderIsNotLoadedIsAClearError) {
    const std::string dir = FreshTempDir("kiln_stability_bad");
    WriteFile(dir + "/x.material",
              R"({"kiln_material": 1, "shader": "Kiln/BlinPhong", "properties": {}})");
    const RunResult r = RunKiln("stability --material " + dir + "/x.material");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.err.find("shader 'Kiln/BlinPhong' is in none of the loaded packs"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("did you mean 'Kiln/BlinnPhong'?"), std::string::npos)
        << "closest name: " << r.err;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln::test
