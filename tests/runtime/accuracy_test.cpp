// kiln report's measures and runner (kiln/tools/image_error.h, flip.h, accuracy_report.h): the
// metrics on images with known answers, FLIP's bounds, and reports on lavapipe whose ordering is
// known (the reference against itself; per-vertex against per-pixel lighting on a coarse mesh).
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <random>

#include <nlohmann/json.hpp>

#include "kiln/tools/accuracy_report.h"
#include "kiln/tools/flip.h"
#include "kiln/tools/image_error.h"
#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

std::vector<float> Uniform(uint32_t w, uint32_t h, float v) {
    std::vector<float> rgba(size_t(w) * h * 4, v);
    for (size_t i = 3; i < rgba.size(); i += 4) {
        rgba[i] = 1;
    }
    return rgba;
}

// A display-referred image with edges, gradients and noise (a fixed seed).
std::vector<float> Busy(uint32_t w, uint32_t h) {
    std::vector<float> rgba(size_t(w) * h * 4, 1.0f);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> noise(0.0f, 0.1f);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            float* p = &rgba[(size_t(y) * w + x) * 4];
            p[0] = float(x) / float(w);
            p[1] = ((x / 8 + y / 8) % 2) ? 0.8f : 0.2f;
            p[2] = 0.5f + noise(rng);
        }
    }
    return rgba;
}

TEST(Flip, AnImageAgainstItselfIsZero) {
    const std::vector<float> img = Busy(64, 48);
    Result<tools::FlipMap> f = tools::Flip(64, 48, img, img);
    ASSERT_TRUE(f) << f.error().message;
    EXPECT_EQ(f.value().mean, 0.0);
    for (float e : f.value().error) {
        ASSERT_EQ(e, 0.0f);
    }
}

TEST(Flip, BlackAgainstWhiteIsCloseToOne) {
    // Colour term alone (no features in flat images): HyAB(white, black)^0.7 = 100^0.7 lies past
    // the knee 0.4 cmax, so the error is 0.95 + a share of the last 0.05: about 0.967.
    Result<tools::FlipMap> f =
        tools::Flip(32, 32, Uniform(32, 32, 0.0f), Uniform(32, 32, 1.0f));
    ASSERT_TRUE(f) << f.error().message;
    EXPECT_GT(f.value().mean, 0.95);
    EXPECT_LE(f.value().mean, 1.0);
}

TEST(Flip, GrowsWithTheDifference) {
    const std::vector<float> ref = Busy(64, 48);
    std::vector<float> slight = ref, strong = ref;
    for (size_t i = 0; i < ref.size(); i += 4) {
        slight[i] = std::min(1.0f, ref[i] + 0.02f);
        strong[i] = std::min(1.0f, ref[i] + 0.2f);
    }
    Result<tools::FlipMap> a = tools::Flip(64, 48, ref, slight);
    Result<tools::FlipMap> b = tools::Flip(64, 48, ref, strong);
    ASSERT_TRUE(a && b);
    EXPECT_GT(a.value().mean, 0.0);
    EXPECT_LT(a.value().mean, b.value().mean);
    EXPECT_LT(b.value().mean, 1.0);
}

TEST(Flip, RefusesImagesOfTheWrongSize) {
    Result<tools::FlipMap> f = tools::Flip(8, 8, Uniform(8, 8, 0), Uniform(8, 4, 0));
    ASSERT_FALSE(f);
    EXPECT_NE(f.error().message.find("8x8"), std::string::npos) << f.error().message;
}

runtime::LinearImage Linear(uint32_t w, uint32_t h, float v) {
    return {w, h, Uniform(w, h, v)};
}

TEST(ImageError, KnownDifferences) {
    Result<tools::ImageError> same =
        tools::CompareLinear(Linear(4, 4, 0.5f), Linear(4, 4, 0.5f));
    ASSERT_TRUE(same);
    EXPECT_EQ(same.value().rmse, 0.0);
    EXPECT_TRUE(std::isinf(same.value().psnr));
    // A uniform 0.1 difference: RMSE and max 0.1, PSNR 10 log10(1 / 0.01) = 20 dB (peak 1).
    Result<tools::ImageError> off =
        tools::CompareLinear(Linear(4, 4, 0.5f), Linear(4, 4, 0.6f));
    ASSERT_TRUE(off);
    EXPECT_NEAR(off.value().rmse, 0.1, 1e-6);
    EXPECT_NEAR(off.value().max_abs, 0.1, 1e-6);
    EXPECT_NEAR(off.value().psnr, 20.0, 1e-4);
    EXPECT_FALSE(tools::CompareLinear(Linear(4, 4, 0), Linear(4, 2, 0)));
}

TEST(ImageError, DownsampleAveragesBlocks) {
    runtime::LinearImage img = Linear(4, 2, 0.0f);
    img.rgba[0] = 1.0f;  // pixel (0, 0) red: its 2x2 block averages to 0.25
    Result<runtime::LinearImage> small = tools::Downsample(img, 2);
    ASSERT_TRUE(small);
    EXPECT_EQ(small.value().width, 2u);
    EXPECT_EQ(small.value().height, 1u);
    EXPECT_FLOAT_EQ(small.value().rgba[0], 0.25f);
    EXPECT_FLOAT_EQ(small.value().rgba[4], 0.0f);
    EXPECT_FALSE(tools::Downsample(img, 3));
}

TEST(ImageError, HeatMapRunsFromBlackToPaleYellow) {
    const std::vector<uint8_t> map = tools::HeatMap({0.0f, 1.0f});
    EXPECT_LT(map[0] + map[1] + map[2], 10);
    EXPECT_GT(map[4], 240);
    EXPECT_GT(map[5], 240);
    EXPECT_GT(map[6], 150);
}

// A coarse sphere (8 x 4 quads) on the floor, lit by two point lights close to it.
runtime::Scene CoarseSphere() {
    runtime::Scene scene = SphereOnFloor(RuntimeData("light_modes.material"));
    scene.meshes[0].primitives[0] = SpherePrimitive(1.0f, 8, 4);
    for (const glm::vec3& p : {glm::vec3(1.2f, 1.8f, 1.5f), glm::vec3(-1.5f, 0.6f, 1.0f)}) {
        runtime::Light l;
        l.type = runtime::LightType::kPoint;
        l.position = p;
        l.color = {1, 0.9f, 0.8f};
        l.intensity = 12;
        scene.lights.push_back(l);
    }
    return scene;
}

tools::AccuracyConfig Named(const std::string& name, runtime::LightMode mode) {
    tools::AccuracyConfig c;
    c.name = name;
    c.settings.light_mode = mode;
    c.settings.pixel_lights = 8;
    return c;
}

TEST_F(RuntimeTest, TheReferenceHasNoErrorAgainstItself) {
    // The reference's own settings, drawn by the reference's renderer without supersampling:
    // the same image, so every measure is exactly zero.
    tools::AccuracyOptions options;
    options.width = 96;
    options.height = 64;
    options.supersample = 1;
    options.frames = 2;
    options.default_light = false;
    options.configs = {Named("same", runtime::LightMode::kPixel)};
    options.configs[0].settings.pixel_lights = 64;
    runtime::Renderer* drawing[] = {&renderer_};
    const std::string labels[] = {"test"};
    Result<tools::AccuracyReport> r =
        tools::RunAccuracyReport(renderer_, drawing, labels, CoarseSphere(), color_, options);
    ASSERT_TRUE(r) << r.error().message;
    const tools::AccuracyRow& row = r.value().rows.at(0);
    EXPECT_EQ(row.error.rmse, 0.0);
    EXPECT_EQ(row.error.max_abs, 0.0);
    EXPECT_EQ(row.flip, 0.0);
    EXPECT_TRUE(row.pareto);
    EXPECT_GT(row.cpu_ms.median, 0.0);
    ASSERT_GE(row.gpu_ms.median, 0.0) << "lavapipe has timestamps";
    ASSERT_EQ(row.pass_ms.size(), 1u);
    EXPECT_EQ(row.pass_ms[0].pass, "forward");
}

TEST_F(RuntimeTest, PerVertexLightingHasLargerErrorThanPerPixelOnACoarseMesh) {
    tools::AccuracyOptions options;
    options.width = 160;
    options.height = 120;
    options.supersample = 2;
    options.frames = 2;
    options.default_light = false;
    options.configs = {Named("pixel", runtime::LightMode::kPixel),
                       Named("vertex", runtime::LightMode::kVertex)};
    runtime::Renderer* drawing[] = {&renderer_};
    const std::string labels[] = {"test"};
    Result<tools::AccuracyReport> r =
        tools::RunAccuracyReport(renderer_, drawing, labels, CoarseSphere(), color_, options);
    ASSERT_TRUE(r) << r.error().message;
    const tools::AccuracyRow& pixel = r.value().rows.at(0);
    const tools::AccuracyRow& vertex = r.value().rows.at(1);
    // Per pixel differs from the reference only by its antialiasing; per vertex also by the
    // lighting interpolated across eight-sided facets.
    EXPECT_GT(pixel.flip, 0.0);
    EXPECT_GT(vertex.flip, 2 * pixel.flip) << "pixel " << pixel.flip << " vertex " << vertex.flip;
    EXPECT_GT(vertex.error.rmse, pixel.error.rmse);
    EXPECT_TRUE(pixel.pareto);  // faster or as fast, and more accurate

    const std::string dir =
        (std::filesystem::temp_directory_path() / ("kiln_accuracy_" + std::to_string(getpid())))
            .string();
    std::filesystem::remove_all(dir);
    Status written = tools::WriteAccuracyReport(r.value(), color_, dir);
    ASSERT_TRUE(Ok(written));
    for (const char* f : {"report.md", "report.csv", "plot.svg", "plot.png", "reference.png",
                          "heat/pixel.png", "heat/vertex.png", "render/vertex.png"}) {
        EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / f)) << f;
    }
    std::ifstream json(std::filesystem::path(dir) / "report.json");
    const nlohmann::json j = nlohmann::json::parse(json);
    ASSERT_EQ(j["configurations"].size(), 2u);
    EXPECT_EQ(j["configurations"][1]["configuration"], "vertex");
    EXPECT_NEAR(j["configurations"][1]["flip_mean"].get<double>(), vertex.flip, 1e-9);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace kiln::test
