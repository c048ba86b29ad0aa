// kiln test as CI runs it: every variant of the shipped materials passes every check of the
// harness; a deliberately broken shader fails, each failure naming the keyword set, the property
// values and the check, with its render kept as a PNG.
#include <gtest/gtest.h>

#include <filesystem>

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
    // Every variant of every pass the forward path draws; the G-buffer passes, the deferred
    // path's light pass, the ShadowCaster pass and the screen-space shadow collector are listed
    // as skipped, and are every variant not tested.
    pack::MappedFile file;
    pack::Pack pk;
    ASSERT_TRUE(MapInto(KILN_MATERIALS_PACK, file));
    ASSERT_TRUE(OpenInto(file.bytes(), pk));
    size_t untested = 0, casters = 0;
    for (uint32_t p = 0; p < pk.Count(pack::SectionTag::kPasses); ++p) {
        casters += pack::LightModeOf(pk, p) == pack::kLightModeShadowCaster;
        const pack::PassRec rec = pk.Pass(p).value();
        const pack::ShaderRec sr = pk.Shader(rec.shader).value();
        if (pack::LightModeOf(pk, p) == pack::kLightModeDeferred ||
            pack::LightModeOf(pk, p) == pack::kLightModeShadowCaster ||
            pk.String(sr.name) == pack::kShaderDeferredShading ||
            pk.String(sr.name) == pack::kShaderScreenSpaceShadows) {
            untested += rec.variant_count;
        }
    }
    EXPECT_EQ(report["variants"].get<size_t>() + untested, pk.Count(pack::SectionTag::kVariants));
    EXPECT_EQ(report["skipped_variants"].get<size_t>(), untested);  // the summary counts them
    // The two Deferred passes, the two internal shaders and one line per ShadowCaster pass.
    ASSERT_EQ(report["skipped"].size(), 4u + casters) << report["skipped"].dump(1);
    std::string skipped;
    for (const auto& line : report["skipped"]) {
        skipped += line.get<std::string>() + "\n";
    }
    for (const char* expected :
         {"shader \"Kiln/Deferred\" pass \"DEFERRED\": LightMode Deferred",
          "shader \"Kiln/StandardMetallic\" pass \"DEFERRED\": LightMode Deferred",
          "shader \"Hidden/Internal-DeferredShading\": the deferred path's light pass",
          "shader \"Kiln/StandardMetallic\" pass \"ShadowCaster\": LightMode ShadowCaster",
          "shader \"Hidden/Internal-ScreenSpaceShadows\": the screen-space shadow collector"}) {
        EXPECT_NE(skipped.find(expected), std::string::npos) << expected << "\n" << skipped;
    }
    // Defaults, intensity 0, no light, then each Range() property at both ends.
    EXPECT_GT(report["renders"].get<size_t>(), 3 * report["variants"].get<size_t>());
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
