// kiln report's timing (kiln/tools/accuracy_report.h): the configurations' frames interleaved
// (A B A B ...) after warm-up rounds, on frames that create no Vulkan object. Two identical
// configurations measure alike whichever is first: on an NVIDIA H200 the first configuration of
// a report read 0.90 ms and an identical one after it 3.9-4.9 ms when each was timed back to
// back after per-frame allocations and a pause for the error computations (issue 42). And two
// runs of a report on one machine agree on the Pareto front.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "kiln/base/sanitizer.h"
#include "kiln/tools/accuracy_report.h"
#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

constexpr bool kInstrumented = base::kAddressSanitizer;

// The demo-like scene of the accuracy tests, heavier: a finer sphere and four lights.
runtime::Scene TimedScene() {
    runtime::Scene scene = SphereOnFloor(RuntimeData("light_modes.material"));
    scene.id = runtime::NewSceneId();
    for (const glm::vec3& p : {glm::vec3(1.2f, 1.8f, 1.5f), glm::vec3(-1.5f, 0.6f, 1.0f),
                               glm::vec3(0.3f, 2.5f, -1.2f), glm::vec3(-0.8f, 1.0f, 2.0f)}) {
        runtime::Light l;
        l.type = runtime::LightType::kPoint;
        l.position = p;
        l.intensity = 8;
        scene.lights.push_back(l);
    }
    return scene;
}

tools::AccuracyConfig Config(const std::string& name, runtime::RenderPath path) {
    tools::AccuracyConfig c;
    c.name = name;
    c.settings.path = path;
    c.settings.light_mode = runtime::LightMode::kPixel;
    c.settings.pixel_lights = 8;
    return c;
}

tools::AccuracyOptions Options() {
    tools::AccuracyOptions options;
    options.width = 320;
    options.height = 180;
    options.supersample = 1;
    options.warmup = 3;
    options.frames = 31;
    options.default_light = false;
    return options;
}

// The medians of two identical configurations agree within 10% in either order, GPU and CPU.
// An order effect is systematic (on the H200 every report read 4 to 5 times more for the second
// of two identical configurations); lavapipe's jitter is not: on this two-core machine one
// comparison of 31 interleaved frames each exceeded 10% about once in 60 (a busy neighbour).
// So each order gets another report when one disagrees; a systematic effect fails them all. A
// fresh-clone CI run beside other tests (ctest -j 2) read GPU 15% apart, then CPU 14% (0.059 ms)
// apart, b first: each order now gets three reports, as under the sanitizers.
// Under the sanitizers the neighbours are instrumented tests sharing the two cores (ctest -j 2),
// and one fresh-clone CI run read 15% and then 48% apart: there the GPU medians must agree
// within 2x over three reports, which still fails the 4-5x order effect, and Kiln's
// instrumented CPU times are not compared.
TEST_F(RuntimeTest, IdenticalConfigurationsTimeAlikeInEitherOrder) {
    const runtime::Scene scene = TimedScene();
    runtime::Renderer* drawing[] = {&renderer_};
    const std::string labels[] = {"test"};
    for (bool swapped : {false, true}) {
        tools::AccuracyOptions options = Options();
        options.configs = {Config("a", runtime::RenderPath::kDeferred),
                           Config("b", runtime::RenderPath::kDeferred)};
        if (swapped) {
            std::swap(options.configs[0], options.configs[1]);
        }
        const double tolerance = kInstrumented ? 2.0 : 1.10;
        const int attempts = 3;
        bool agreed = false;
        for (int attempt = 0; attempt < attempts && !agreed; ++attempt) {
            Result<tools::AccuracyReport> r =
                tools::RunAccuracyReport(renderer_, drawing, labels, scene, color_, options);
            ASSERT_TRUE(r) << r.error().message;
            const tools::AccuracyRow& x = r.value().rows.at(0);
            const tools::AccuracyRow& y = r.value().rows.at(1);
            ASSERT_GT(x.gpu_ms.median, 0.0) << "lavapipe has timestamps";
            ASSERT_EQ(x.flip, y.flip);  // the same image
            const double gpu = std::max(x.gpu_ms.median, y.gpu_ms.median) /
                               std::min(x.gpu_ms.median, y.gpu_ms.median);
            const double cpu = std::max(x.cpu_ms.median, y.cpu_ms.median) /
                               std::min(x.cpu_ms.median, y.cpu_ms.median);
            std::cout << (swapped ? "b, a" : "a, b") << ": GPU " << x.gpu_ms.median << " and "
                      << y.gpu_ms.median << " ms (ratio " << gpu << "), CPU " << x.cpu_ms.median
                      << " and " << y.cpu_ms.median << " ms (ratio " << cpu << ")\n";
            agreed = gpu <= tolerance;
            if (!kInstrumented) {
                // CPU times of a fraction of a millisecond: within 10%, or 0.05 ms.
                agreed =
                    agreed && (cpu <= 1.10 || std::abs(x.cpu_ms.median - y.cpu_ms.median) <= 0.05);
            }
        }
        EXPECT_TRUE(agreed) << "identical configurations timed apart in every report, "
                            << (swapped ? "b first" : "a first");
    }
}

// Two runs of the same report mark the same configurations as on the Pareto front.
TEST_F(RuntimeTest, TwoRunsAgreeOnTheParetoFront) {
    const runtime::Scene scene = TimedScene();
    runtime::Renderer* drawing[] = {&renderer_};
    const std::string labels[] = {"test"};
    tools::AccuracyOptions options = Options();
    options.frames = 9;
    // (Not the deferred path: with this material, which has no Deferred pass, it draws the same
    // image as "pixel" about 10% slower, a difference as large as the frames' jitter, which no
    // tolerance can call the same way every time.)
    options.configs = {Config("pixel", runtime::RenderPath::kForward)};
    for (runtime::LightMode mode : {runtime::LightMode::kVertex, runtime::LightMode::kSH}) {
        tools::AccuracyConfig c = Config(mode == runtime::LightMode::kSH ? "sh" : "vertex",
                                         runtime::RenderPath::kForward);
        c.settings.light_mode = mode;
        options.configs.push_back(c);
    }
    std::vector<bool> first;
    for (int run = 0; run < 2; ++run) {
        Result<tools::AccuracyReport> r =
            tools::RunAccuracyReport(renderer_, drawing, labels, scene, color_, options);
        ASSERT_TRUE(r) << r.error().message;
        std::vector<bool> flags;
        for (const tools::AccuracyRow& row : r.value().rows) {
            flags.push_back(row.pareto);
            std::cout << "run " << run + 1 << ": " << row.config.name << " GPU "
                      << row.gpu_ms.median << " (" << row.gpu_ms.min << "-" << row.gpu_ms.max
                      << ") ms, FLIP " << row.flip << (row.pareto ? ", Pareto" : "") << "\n";
        }
        if (run == 0) {
            first = flags;
            EXPECT_NE(std::count(flags.begin(), flags.end(), true), 0);
        } else {
            EXPECT_EQ(flags, first);
        }
    }
}

}  // namespace
}  // namespace kiln::test
