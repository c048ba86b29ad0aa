// kiln test as CI runs it: every variant of the shipped materials passes every check of the
// harness; a deliberately broken shader fails, each failure naming the keyword set, the property
// values and the check, with its render kept as a PNG.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

TEST(KilnTest, EveryVariantOfTheShippedMaterialsPasses) {
    const RunResult r = RunKiln("test --json " + std::string(KILN_MATERIALS_PACK));
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
    const nlohmann::json report = nlohmann::json::parse(r.out);
    EXPECT_TRUE(report["passed"].get<bool>());
    EXPECT_TRUE(report["failures"].empty()) << report["failures"].dump(1);
    // Every variant of every pass is tested (forward passes, G-buffer passes, ShadowCaster
    // passes, the screen-space shadow collector) but the deferred light pass's combinations no
    // frame draws. Its LIGHT and LIGHT_BOUNDED passes have 3 light types x 2 normal encodings x
    // 4 shadow keywords (none, SCREEN, DEPTH, CUBE) x 2 (SHADOWS_SOFT) = 48 variants each; a
    // frame draws per encoding DIRECTIONAL with none or SCREEN, POINT with none, CUBE or CUBE
    // SOFT, SPOT with none, DEPTH or DEPTH SOFT: 16 in LIGHT, and the 12 of point and spot
    // lights in LIGHT_BOUNDED; its LIGHT_MASK has 1. So 97 - 29 = 68 are never drawn.
    pack::MappedFile file;
    pack::Pack pk;
    ASSERT_TRUE(MapInto(KILN_MATERIALS_PACK, file));
    ASSERT_TRUE(OpenInto(file.bytes(), pk));
    const size_t all = pk.Count(pack::SectionTag::kVariants);
    EXPECT_EQ(report["variants"].get<size_t>() + report["skipped_variants"].get<size_t>(), all);
    EXPECT_EQ(report["skipped_variants"].get<size_t>(), 68u);
    ASSERT_FALSE(report["skipped"].empty());
    for (const auto& line : report["skipped"]) {
        const std::string s = line.get<std::string>();
        EXPECT_EQ(s.rfind("shader \"Hidden/Internal-DeferredShading\" pass \"LIGHT", 0), 0u) << s;
        EXPECT_NE(s.find(": never drawn: "), std::string::npos) << s;
    }
    // Defaults, intensity 0, no light, then each Range() property at both ends for the forward
    // passes; one frame for each other pass (two for a shadowed light pass).
    EXPECT_GT(report["renders"].get<size_t>(), 3 * report["variants"].get<size_t>());
}

// The passes other paths draw fail their own checks: a ShadowCaster whose depth is NaN, moved or
// flat, and a Deferred pass that writes NaN or a short normal; the healthy variants pass.
TEST(KilnTest, ABrokenShadowCasterAndDeferredPassFail) {
    ScratchDir dir;
    const std::string pack = dir.path() + "/broken.kpack";
    ASSERT_EQ(
        RunKiln("compile " + DataPath("harness/BrokenPasses.shader") + " --no-cache -o " + pack)
            .exit_code,
        0);
    // The shipped pack lights the G-buffer (its internal light pass).
    const RunResult r =
        RunKiln("test --json " + pack + " " + KILN_MATERIALS_PACK +
                " --shader Test/BrokenPasses --keep-failures " + dir.path() + "/failures");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    const nlohmann::json report = nlohmann::json::parse(r.out);
    EXPECT_EQ(report["variants"], 12);  // 1 forward, 3 Deferred, 2 x 4 ShadowCaster
    EXPECT_EQ(report["skipped_variants"], 0);
    std::set<std::string> seen;
    for (const auto& f : report["failures"]) {
        std::string keywords;
        for (const auto& k : f["keywords"]) {
            keywords += (keywords.empty() ? "" : " ") + k.get<std::string>();
        }
        seen.insert(f["pass"].get<std::string>() + " " + keywords + ": " +
                    f["check"].get<std::string>());
    }
    const std::set<std::string> expected = {
        "DEFERRED NAN_EMISSION: finite",
        "DEFERRED NAN_EMISSION: lit",
        "DEFERRED SHORT_NORMAL: normal",
        "ShadowCaster SHADOWS_DEPTH NAN_DEPTH: coverage",
        "ShadowCaster SHADOWS_CUBE NAN_DEPTH: coverage",
        "ShadowCaster SHADOWS_DEPTH SHIFTED: coverage",
        "ShadowCaster SHADOWS_DEPTH SHIFTED: depth",
        "ShadowCaster SHADOWS_CUBE SHIFTED: coverage",
        "ShadowCaster SHADOWS_CUBE SHIFTED: depth",
        "ShadowCaster SHADOWS_DEPTH FLAT_DEPTH: depth",
        "ShadowCaster SHADOWS_CUBE FLAT_DEPTH: depth",
    };
    EXPECT_EQ(seen, expected) << report["failures"].dump(1);
}

TEST(KilnTest, ABrokenShaderFailsNamingKeywordsPropertyValuesAndCheck) {
    ScratchDir dir;
    const std::string pack = dir.path() + "/broken.kpack", keep = dir.path() + "/failures";
    ASSERT_EQ(RunKiln("compile " + DataPath("harness/Broken.shader") + " --no-cache -o " + pack)
                  .exit_code,
              0);
    const RunResult r = RunKiln("test " + pack + " --keep-failures " + keep);
    EXPECT_EQ(r.exit_code, 1);
    for (const char* expected :
         {"shader 'Test/Broken' pass 'FORWARD' variant 'BRIGHT' with _Exponent = 0 (Range min): "
          "finite: ",
          "shader 'Test/Broken' pass 'FORWARD' variant 'LEAK' with (defaults), light intensity 0: "
          "no-light: a light of intensity 0 changes the image",
          "shader 'Test/Broken' pass 'FORWARD_DELTA' variant 'POINT' with (defaults): additive: "
          "the pass darkens what was drawn before it"}) {
        EXPECT_NE(r.err.find(expected), std::string::npos) << expected << "\n" << r.err;
    }
    // The healthy variants pass: no failure names them.
    EXPECT_EQ(r.err.find("variant '(no keywords)'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("variant 'DIRECTIONAL'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("variant 'BRIGHT' with (defaults)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("[K0027]"), std::string::npos);
    size_t pngs = 0;
    for (const auto& e : fs::directory_iterator(keep))
        pngs += e.path().extension() == ".png";
    EXPECT_GE(pngs, 3u);
}

TEST(KilnTest, ASeededSampleIsRepeatable) {
    const std::string args = "test --json --sample 5 --seed 7 " + std::string(KILN_MATERIALS_PACK);
    const RunResult a = RunKiln(args), b = RunKiln(args);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    EXPECT_EQ(nlohmann::json::parse(a.out)["variants"], 5);
    EXPECT_EQ(a.out, b.out);
}

}  // namespace
}  // namespace kiln::test
