// kiln report --scaling: the lecture's trade-off between the forward and the deferred path,
// measured (docs/performance.md, "Forward against deferred"). The forward path draws each object
// once plus once per pixel light that reaches it; the deferred path draws each object once into
// the G-buffer, then each light once over the pixels it reaches. A generated scene, a grid of N
// spheres over a floor lit by M ranged point lights (ScalingScene), is drawn on both paths for
// every N and M; the table gives GPU and CPU milliseconds per frame and draws, and for each N the
// crossover: the light count from which the deferred path is faster.
#ifndef KILN_TOOLS_SCALING_H_
#define KILN_TOOLS_SCALING_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kiln/result.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "kiln/tools/accuracy_report.h"

namespace kiln::tools {

// A grid of `objects` spheres (radius 0.5, two units apart, in rows of ceil(sqrt(objects))) on a
// floor, lit by `lights` point lights of range 3 (each reaches about a dozen spheres whatever the
// grid's size) at heights 0.8 to 2.4, placed and coloured by a fixed pseudo-random sequence of
// `seed`; one camera above the grid's near edge looking across it. Every object draws with the
// glTF default material (Kiln/StandardMetallic, which has both paths' passes); no directional
// light. Deterministic: the same arguments give the same scene.
runtime::Scene ScalingScene(uint32_t objects, uint32_t lights, uint64_t seed = 1);

struct ScalingOptions {
    std::vector<uint32_t> objects = {10, 100, 1000, 10000};
    std::vector<uint32_t> lights = {1, 4, 16, 64, 256};
    uint32_t width = 640, height = 360;
    // Per scene, after each path's first frame: `warmup` untimed and `frames` timed rounds of one
    // frame of each path in turn (forward, deferred, forward, ...).
    uint32_t warmup = 1, frames = 5;
};

struct ScalingRow {
    uint32_t objects = 0, lights = 0;  // spheres (the floor is one more object), point lights
    std::string path;                  // "forward" or "deferred"
    Spread gpu_ms, cpu_ms;             // per frame (FrameStats::gpu_ms, cpu_ms)
    uint32_t draws = 0;                // every draw of the frame
    double first_frame_ms = 0;         // the path's first frame on the scene, wall time
};

struct ScalingReport {
    std::string device;
    uint32_t width = 0, height = 0, frames = 0, warmup = 0;
    std::vector<ScalingRow> rows;  // per object count, per light count: forward, then deferred
};

// Draws every scene on both paths with `renderer`.
Result<ScalingReport> RunScalingReport(runtime::Renderer& renderer,
                                       const runtime::ColorPipeline& color,
                                       const ScalingOptions& options);

// For `objects`: the smallest light count from which the deferred path's GPU time (CPU where
// there is none) is below the forward path's at that count and every larger one measured; none
// when the forward path stays faster at the largest.
std::optional<uint32_t> Crossover(const ScalingReport& report, uint32_t objects);

// Writes scaling.md, scaling.csv, scaling.json and the plot (scaling.svg, scaling.png: GPU time
// against light count, one line per path and object count, both axes logarithmic) into `dir`.
Status WriteScalingReport(const ScalingReport& report, const std::string& dir);

// The plot alone.
std::string ScalingPlotSvg(const ScalingReport& report);
std::vector<uint8_t> ScalingPlotImage(const ScalingReport& report, uint32_t width, uint32_t height);

}  // namespace kiln::tools

#endif  // KILN_TOOLS_SCALING_H_
