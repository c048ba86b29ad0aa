// kiln report --scaling's scenes and sweep (kiln/tools/scaling.h): the generated scene has the
// objects and lights asked for, the same every time; both paths draw it alike; the sweep counts
// the draws each path's cost model predicts (forward: each object once plus once per light that
// reaches it; deferred: each object once plus one light pass per light); the crossover is the
// first light count from which the deferred path stays faster.
#include <gtest/gtest.h>

#include <cmath>

#include "kiln/tools/scaling.h"
#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

TEST(ScalingScene, HasWhatWasAskedForTheSameEveryTime) {
    const runtime::Scene a = tools::ScalingScene(100, 16), b = tools::ScalingScene(100, 16);
    ASSERT_EQ(a.instances.size(), 101u);  // the spheres and the floor
    ASSERT_EQ(a.lights.size(), 16u);
    for (size_t i = 0; i < a.lights.size(); ++i) {
        EXPECT_EQ(a.lights[i].position, b.lights[i].position);
        EXPECT_EQ(a.lights[i].color, b.lights[i].color);
        EXPECT_GT(a.lights[i].range, 0.0f);
    }
    EXPECT_NE(tools::ScalingScene(100, 16, 2).lights[0].position, a.lights[0].position);
    EXPECT_NE(a.id, b.id);  // each a scene of its own to the renderer's caches
}

// The forward and deferred paths light the scaling scene alike (the tolerance of
// tests/runtime/deferred_test.cpp: the G-buffer's 8-bit colours and 10-bit normals).
TEST_F(RuntimeTest, BothPathsDrawTheScalingSceneAlike) {
    const runtime::Scene scene = tools::ScalingScene(16, 8);
    runtime::FrameSettings settings;
    settings.width = 160;
    settings.height = 90;
    settings.light_mode = runtime::LightMode::kPixel;
    settings.pixel_lights = 8;
    const runtime::LinearImage forward = Render(scene, settings);
    settings.path = runtime::RenderPath::kDeferred;
    const runtime::LinearImage deferred = Render(scene, settings);
    ASSERT_EQ(forward.rgba.size(), deferred.rgba.size());
    double sum = 0, brightest = 0;
    for (size_t i = 0; i < forward.rgba.size(); i += 4) {
        for (size_t c = 0; c < 3; ++c) {
            sum += std::abs(forward.rgba[i + c] - deferred.rgba[i + c]);
            brightest = std::max(brightest, double(forward.rgba[i + c]));
        }
    }
    EXPECT_GT(brightest, 0.05);  // lit
    EXPECT_LT(sum / double(forward.rgba.size() / 4 * 3), 0.01);
}

TEST_F(RuntimeTest, TheSweepCountsEachPathsDraws) {
    tools::ScalingOptions options;
    options.objects = {9, 100};
    options.lights = {1, 16};
    options.width = 160;
    options.height = 90;
    options.warmup = 1;
    options.frames = 2;
    Result<tools::ScalingReport> r = tools::RunScalingReport(renderer_, color_, options);
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r.value().rows.size(), 8u);
    for (size_t i = 0; i < r.value().rows.size(); i += 2) {
        const tools::ScalingRow& forward = r.value().rows[i];
        const tools::ScalingRow& deferred = r.value().rows[i + 1];
        EXPECT_EQ(forward.path, "forward");
        EXPECT_EQ(deferred.path, "deferred");
        const uint32_t objects = forward.objects + 1;  // and the floor
        // Forward: every object once, and once more per light reaching it.
        EXPECT_GE(forward.draws, objects);
        EXPECT_LE(forward.draws, objects * (1 + forward.lights));
        // Deferred: every object into the G-buffer, one light pass per light (all in view).
        EXPECT_EQ(deferred.draws, objects + deferred.lights);
        EXPECT_GT(forward.gpu_ms.median, 0.0);
        EXPECT_GT(deferred.cpu_ms.median, 0.0);
    }
    // More lights, more forward draws; the same G-buffer.
    EXPECT_GT(r.value().rows[2].draws, r.value().rows[0].draws);
}

tools::ScalingRow Row(uint32_t lights, const char* path, double ms) {
    tools::ScalingRow r;
    r.objects = 10;
    r.lights = lights;
    r.path = path;
    r.gpu_ms = {ms, ms, ms};
    return r;
}

TEST(Scaling, TheCrossoverIsWhereDeferredStaysFaster) {
    tools::ScalingReport r;
    r.rows = {Row(1, "forward", 1),    Row(1, "deferred", 2), Row(4, "forward", 3),
              Row(4, "deferred", 2.5), Row(16, "forward", 9), Row(16, "deferred", 4)};
    EXPECT_EQ(tools::Crossover(r, 10), 4u);
    r.rows[3].gpu_ms = {3.5, 3.5, 3.5};  // deferred slower at 4: the crossover moves to 16
    EXPECT_EQ(tools::Crossover(r, 10), 16u);
    r.rows[5].gpu_ms = {10, 10, 10};  // and nowhere
    EXPECT_FALSE(tools::Crossover(r, 10));
    EXPECT_FALSE(tools::Crossover(r, 99));  // no such rows
}

}  // namespace
}  // namespace kiln::test
