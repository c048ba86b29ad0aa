// The runtime's CPU cost per frame as an engine pays it (issue 42): planning, building and
// recording a frame's draws (FrameStats::cpu_ms, to the submission; not the GPU's time nor the
// read-back), on the generated scaling scene (kiln/tools/scaling.h) with 100 and with 1,000
// spheres and 4 ranged point lights on the forward path (every light per pixel). Counters: the
// draws, the CPU microseconds per draw, and the Vulkan objects the timed frames created (0:
// steady-state frames allocate nothing). bench/check_targets.py requires the cost per draw at
// 1,000 objects to be at most 1.6 times that at 100: recording is linear in draws (a quadratic
// step would make it 7.6; the larger frame's data outgrowing the caches makes it above 1).
#include <benchmark/benchmark.h>

#include <memory>

#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/tools/scaling.h"

namespace {

using kiln::runtime::ColorPipeline;
using kiln::runtime::Renderer;

struct Fixture {
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<ColorPipeline> color;
    Fixture() {
        auto made = Renderer::Create({});
        if (!made || !made.value().AddPack(KILN_MATERIALS_PACK).ok()) {
            return;
        }
        auto c = ColorPipeline::Create({});
        if (!c) {
            return;
        }
        renderer = std::make_unique<Renderer>(std::move(made).value());
        color = std::make_unique<ColorPipeline>(std::move(c).value());
    }
};

Fixture& Shared() {
    static Fixture f;
    return f;
}

void FrameCpu(benchmark::State& state, uint32_t objects) {
    Fixture& f = Shared();
    if (!f.renderer) {
        state.SkipWithError("no Vulkan device or no materials pack");
        return;
    }
    const kiln::runtime::Scene scene = kiln::tools::ScalingScene(objects, 4);
    kiln::runtime::FrameSettings settings;
    settings.width = 320;
    settings.height = 180;
    settings.light_mode = kiln::runtime::LightMode::kPixel;
    settings.pixel_lights = 4;
    kiln::runtime::LinearImage image;
    kiln::runtime::FrameStats stats;
    for (int i = 0; i < 2; ++i) {  // the first frame (pipelines, uploads) and one more
        if (!f.renderer->Render(scene, settings, *f.color, image, stats).ok()) {
            state.SkipWithError("the frame failed");
            return;
        }
    }
    double cpu_ms = 0, draws = 0, allocations = 0;
    for (auto _ : state) {
        stats = {};
        if (!f.renderer->Render(scene, settings, *f.color, image, stats).ok()) {
            state.SkipWithError("the frame failed");
            return;
        }
        state.SetIterationTime(stats.cpu_ms / 1000.0);
        cpu_ms += stats.cpu_ms;
        draws += double(stats.base_passes + stats.add_passes);
        allocations += stats.allocations;
    }
    const double n = double(state.iterations());
    state.counters["draws"] = draws / n;
    state.counters["per_draw_us"] = 1000.0 * cpu_ms / draws;
    state.counters["allocations"] = allocations;
}

void BM_FrameCpu100Objects(benchmark::State& state) {
    FrameCpu(state, 100);
}
BENCHMARK(BM_FrameCpu100Objects)->Unit(benchmark::kMillisecond)->UseManualTime()->Repetitions(3);

void BM_FrameCpu1000Objects(benchmark::State& state) {
    FrameCpu(state, 1000);
}
BENCHMARK(BM_FrameCpu1000Objects)->Unit(benchmark::kMillisecond)->UseManualTime()->Repetitions(3);

}  // namespace
