// MSAA (FrameSettings::msaa, kiln render --msaa): the forward path draws into multisampled
// colour and depth targets and resolves the colour before the display transform; edges get
// fractional coverage and come closer to a supersampled reference; where MSAA does not apply
// (the deferred path) the frame is drawn with one sample and a warning; bad counts are errors.
#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

// The sphere on its floor, lit, seen so that silhouettes cross the background.
runtime::Scene EdgeScene() {
    runtime::Scene scene = SphereOnFloor(RuntimeData("lambert_white.material"));
    runtime::Light key;
    key.type = runtime::LightType::kDirectional;
    key.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.4f));
    key.intensity = 3.0f;
    scene.lights = {key};
    return scene;
}

size_t Fractional(const runtime::LinearImage& image) {
    size_t n = 0;
    for (size_t i = 3; i < image.rgba.size(); i += 4) {
        n += image.rgba[i] > 0.01f && image.rgba[i] < 0.99f ? 1 : 0;
    }
    return n;
}

// The mean absolute RGB difference between `image` and `big` box-filtered by `factor`.
double ErrorAgainstSupersampled(const runtime::LinearImage& image,
                                const runtime::LinearImage& big,
                                uint32_t factor) {
    double sum = 0;
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            for (uint32_t c = 0; c < 3; ++c) {
                double mean = 0;
                for (uint32_t dy = 0; dy < factor; ++dy) {
                    for (uint32_t dx = 0; dx < factor; ++dx) {
                        mean +=
                            big.rgba[((size_t(y) * factor + dy) * big.width + x * factor + dx) * 4 +
                                     c];
                    }
                }
                mean /= double(factor * factor);
                sum += std::abs(image.rgba[(size_t(y) * image.width + x) * 4 + c] - mean);
            }
        }
    }
    return sum / double(image.width * image.height * 3);
}

// 4 samples: silhouettes get coverage between 0 and 1 (the frame's alpha is coverage), and the
// image is closer to an 8x8-supersampled render than the 1-sample one: less than 60% of its
// mean error (interiors shade once per pixel either way; the difference is at the edges).
TEST_F(RuntimeTest, FourSamplesSmoothTheEdgesTowardsASupersampledReference) {
    const runtime::Scene scene = EdgeScene();
    runtime::FrameSettings settings;
    settings.width = 96;
    settings.height = 72;
    const runtime::LinearImage one = Render(scene, settings);
    EXPECT_EQ(Fractional(one), 0u);
    settings.msaa = 4;
    runtime::FrameStats stats;
    const runtime::LinearImage four = Render(scene, settings, &stats);
    EXPECT_GT(Fractional(four), 50u);
    EXPECT_TRUE(stats.warnings.all().empty());
    runtime::FrameSettings big = settings;
    big.msaa = 1;
    big.width *= 8;
    big.height *= 8;
    const runtime::LinearImage reference = Render(scene, big);
    const double e1 = ErrorAgainstSupersampled(one, reference, 8);
    const double e4 = ErrorAgainstSupersampled(four, reference, 8);
    EXPECT_LT(e4, 0.6 * e1) << "1 sample: " << e1 << ", 4 samples: " << e4;
}

TEST_F(RuntimeTest, MsaaOnTheDeferredPathIsOneSampleWithAWarning) {
    const runtime::Scene scene = EdgeScene();
    runtime::FrameSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.path = runtime::RenderPath::kDeferred;
    settings.msaa = 4;
    runtime::FrameStats stats;
    const runtime::LinearImage image = Render(scene, settings, &stats);
    EXPECT_EQ(Fractional(image), 0u);
    ASSERT_FALSE(stats.warnings.all().empty());
    EXPECT_EQ(stats.warnings.all()[0].code, DiagCode::kRenderWarning);
    EXPECT_NE(stats.warnings.all()[0].message.find("MSAA is off for the deferred path"),
              std::string::npos);
}

TEST_F(RuntimeTest, SampleCountsOtherThanOneTwoFourOrEightAreErrors) {
    const runtime::Scene scene = EdgeScene();
    runtime::FrameSettings settings;
    settings.width = 16;
    settings.height = 16;
    settings.msaa = 3;
    runtime::LinearImage image;
    runtime::FrameStats stats;
    const Status e = renderer_.Render(scene, settings, color_, image, stats);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, DiagCode::kBadScene);
    EXPECT_NE(e.error().message.find("msaa must be 1, 2, 4 or 8"), std::string::npos);
    // 8 renders where the device has it, else the error names the counts it has.
    settings.msaa = 8;
    const Status eight = renderer_.Render(scene, settings, color_, image, stats);
    if (!eight.ok()) {
        EXPECT_NE(eight.error().message.find("cannot render 8 samples per pixel (it has 1"),
                  std::string::npos)
            << eight.error().message;
    }
}

}  // namespace
}  // namespace kiln::test
