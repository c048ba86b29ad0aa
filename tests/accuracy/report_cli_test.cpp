// kiln report through the CLI on lavapipe with the validation layer: the demo scene's tables,
// plot and images for a few configurations, and the mistakes a user can make on its command line.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

TEST(ReportCli, WritesTheTablesPlotAndHeatMapsOfTheDemoScene) {
    const std::string dir = FreshTempDir("kiln_report_cli");
    const RunResult r = RunKiln("report " + DataPath("../scenes/demo/demo.gltf") + " -o " + dir +
                                " --only pixel --only vertex --only deferred-rgba8-oct"
                                " --only auto-4-fp16"
                                " --width 192 --height 108 --supersample 2 --frames 2"
                                " --validation");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("deferred-rgba8-oct"), std::string::npos) << r.out;
    for (const char* f :
         {"report.md", "report.csv", "report.json", "plot.svg", "plot.png", "reference.png",
          "heat/pixel.png", "heat/vertex.png", "heat/deferred-rgba8-oct.png", "render/pixel.png"}) {
        EXPECT_TRUE(fs::exists(fs::path(dir) / f)) << f;
    }
    const nlohmann::json j = nlohmann::json::parse(ReadFile(dir + "/report.json"));
    // The four asked for, fp16 among them (auto-4 with materials-half.kpack: lavapipe has
    // shaderFloat16).
    ASSERT_EQ(j["configurations"].size(), 4u);
    EXPECT_EQ(j["configurations"][3]["configuration"], "auto-4-fp16");
    // Binary16 where the templates say half changes the image little: auto-4 is pixel's image
    // here, and fp16 stays within 0.01 FLIP of it (0.0055 against 0.0060 at full size).
    EXPECT_NEAR(j["configurations"][3]["flip_mean"].get<double>(),
                j["configurations"][0]["flip_mean"].get<double>(), 0.01);
    for (const nlohmann::json& c : j["configurations"]) {
        const double flip = c["flip_mean"].get<double>();
        EXPECT_GE(flip, 0.0);
        EXPECT_LT(flip, 0.5) << c["configuration"];  // approximations, not different scenes
        EXPECT_FALSE(c["gpu_ms"].is_null()) << "lavapipe has timestamps";
    }
    EXPECT_TRUE(j["configurations"][2]["gpu_ms_per_pass"].contains("lighting"));
    const std::string svg = ReadFile(dir + "/plot.svg");
    EXPECT_NE(svg.find("Pareto"), std::string::npos);
    const std::string md = ReadFile(dir + "/report.md");
    EXPECT_NE(md.find("| 3 | deferred-rgba8-oct |"), std::string::npos);
    // Each configuration explained in one line, and how the Pareto flags are decided.
    EXPECT_NE(md.find("1. `pixel`: forward, every light per pixel"), std::string::npos) << md;
    EXPECT_NE(md.find("3. `deferred-rgba8-oct`: the deferred path, G-buffer normals RGBA8, "
                      "octahedral encoding."),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("4. `auto-4-fp16`: auto-4 with the shipped shaders compiled with "
                      "--precision half"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("Pareto: no other configuration is both faster and more accurate, each "
                      "beyond the measurements' noise"),
              std::string::npos);
    fs::remove_all(dir);
}

TEST(ReportCli, ABrdfChoiceBuiltIntoOnePackIsComparedWithTheDefaultModel) {
    // StandardMetallic alone, with the Blinn-Phong NDF instead of GGX; the demo scene's other
    // shaders come from the shipped pack.
    const std::string dir = FreshTempDir("kiln_report_brdf");
    const RunResult built =
        RunKiln("compile " + DataPath("../materials/StandardMetallic.shader") +
                " --all-features -D KILN_BRDF_D_BLINN_PHONG -o " + dir + "/blinn.kpack");
    ASSERT_EQ(built.exit_code, 0) << built.err;
    const RunResult r = RunKiln("report " + DataPath("../scenes/demo/demo.gltf") + " -o " + dir +
                                "/out --only pixel --compare blinn-phong-ndf=" + dir +
                                "/blinn.kpack --width 192 --height 108 --supersample 2 --frames 2"
                                " --no-fp16");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(ReadFile(dir + "/out/report.json"));
    ASSERT_EQ(j["configurations"].size(), 2u);
    EXPECT_EQ(j["configurations"][1]["configuration"], "auto-4-blinn-phong-ndf");
    // The reference is GGX: another distribution adds error beyond the per-pixel forward path's
    // (0.022 against 0.038 FLIP here; auto-4 alone matches pixel on this scene).
    EXPECT_GT(j["configurations"][1]["flip_mean"].get<double>(),
              j["configurations"][0]["flip_mean"].get<double>() + 0.005);
    fs::remove_all(dir);
}

// kiln report --scaling: both paths on generated scenes; the table, the crossover and the plot.
TEST(ReportCli, ScalingWritesTheTableTheCrossoverAndThePlot) {
    const std::string dir = FreshTempDir("kiln_report_scaling");
    const RunResult r = RunKiln(
        "report --scaling --scaling-objects 10,40 --scaling-lights 1,8 "
        "--width 96 --height 54 --frames 1 -o " +
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("10 objects: "), std::string::npos) << r.out;
    const nlohmann::json j = nlohmann::json::parse(ReadFile(dir + "/scaling.json"));
    ASSERT_EQ(j["rows"].size(), 8u);  // 2 object counts x 2 light counts x 2 paths
    EXPECT_EQ(j["frames"], 1);
    EXPECT_EQ(j["rows"][0]["path"], "forward");
    EXPECT_EQ(j["rows"][1]["path"], "deferred");
    EXPECT_TRUE(j["crossover"].contains("10"));
    const std::string md = ReadFile(dir + "/scaling.md");
    EXPECT_NE(md.find("| objects | lights | path | draws | GPU ms | CPU ms |"), std::string::npos);
    EXPECT_NE(md.find("Crossover"), std::string::npos);
    EXPECT_GT(fs::file_size(dir + "/scaling.png"), 1000u);
    EXPECT_NE(ReadFile(dir + "/scaling.svg").find("<title>Frame time against lights"),
              std::string::npos);
    // A scene file with --scaling is a mistake, said as one.
    const RunResult both =
        RunKiln("report " + DataPath("../scenes/demo/demo.gltf") + " --scaling -o " + dir + "/x");
    EXPECT_EQ(both.exit_code, 2) << both.err;
    EXPECT_NE(both.err.find("--scaling draws generated scenes"), std::string::npos) << both.err;
    fs::remove_all(dir);
}

// --only means only: without auto-4-fp16 among its names, the fp16 configuration is not drawn.
TEST(ReportCli, OnlyMeansOnly) {
    const std::string dir = FreshTempDir("kiln_report_only");
    const RunResult r = RunKiln("report " + DataPath("../scenes/demo/demo.gltf") + " -o " + dir +
                                " --only sh --width 64 --height 36 --supersample 1 --frames 1");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(ReadFile(dir + "/report.json"));
    ASSERT_EQ(j["configurations"].size(), 1u);
    EXPECT_EQ(j["configurations"][0]["configuration"], "sh");
    fs::remove_all(dir);
}

TEST(ReportCli, AnUnknownConfigurationIsNamedWithTheValidOnes) {
    const RunResult r = RunKiln("report " + DataPath("../scenes/demo/demo.gltf") + " -o " +
                                FreshTempDir("kiln_report_bad") + " --only vertx");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("unknown configuration 'vertx'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("vertex"), std::string::npos) << r.err;
}

TEST(ReportCli, ACompareWithoutALabelIsRefused) {
    const RunResult r = RunKiln("report " + DataPath("../scenes/demo/demo.gltf") + " -o " +
                                FreshTempDir("kiln_report_bad") + " --compare other.kpack");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("expected LABEL=PACK"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace kiln::test
