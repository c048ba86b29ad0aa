// `kiln report`: what an approximation costs in accuracy and buys in time (docs/accuracy.md). A
// scene is rendered as a reference (every light per pixel, fp32 targets, supersampled) and in
// each configuration (light modes, paths and G-buffer formats, other packs such as other
// optimizer levels); each is compared with the reference (kiln/tools/image_error.h, FLIP) and
// timed (GPU timestamps per pass and frame, CPU time per frame, the first frame apart).
#ifndef KILN_TOOLS_ACCURACY_REPORT_H_
#define KILN_TOOLS_ACCURACY_REPORT_H_

#include <span>
#include <string>
#include <vector>

#include "kiln/result.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "kiln/tools/flip.h"
#include "kiln/tools/image_error.h"

namespace kiln::tools {

using runtime::ColorPipeline;
using runtime::FrameSettings;
using runtime::FrameStats;
using runtime::LinearImage;
using runtime::Renderer;
using runtime::Scene;
struct AccuracyConfig {
    std::string name;         // "auto-4", "deferred-rgba8-oct", ... (also a file name)
    std::string group;        // what it varies: "light mode", "path", "pack"
    FrameSettings settings;   // its size and camera are the report's
    size_t renderer = 0;      // which of the renderers draws it
    std::string label;        // which packs, for the tables: the renderer's label
    std::string description;  // one line for report.md: what the configuration draws
};

// The configurations a report compares by default, drawn by renderer 0: the light modes (every
// light per pixel; Unity's automatic ranking with 4, 2, 1 and 0 pixel lights; per vertex; in
// spherical harmonics) and the deferred path with each G-buffer normal format and encoding.
std::vector<AccuracyConfig> DefaultAccuracyConfigs();

struct AccuracyOptions {
    uint32_t width = 640, height = 360;
    uint32_t supersample = 4;  // the reference's samples per pixel along each axis
    // Rounds of one frame of every configuration in turn (A B C A B C ...): `warmup` untimed,
    // then `frames` timed; each configuration's first frame is timed apart before them.
    uint32_t warmup = 2;
    uint32_t frames = 10;
    int camera = FrameSettings::kCameraDefault;
    bool default_light = true;
    std::vector<AccuracyConfig> configs;  // empty: DefaultAccuracyConfigs()
    FlipOptions flip;
};

struct Spread {
    double median = -1, min = -1, max = -1;  // negative: not measured
    double q1 = -1, q3 = -1;                 // the quartiles (negative: not known)
};
// The spread of `values` (all negative when there are none).
Spread SpreadOf(std::vector<double> values);

struct AccuracyRow {
    AccuracyConfig config;
    ImageError error;                           // linear, against the reference
    double flip = 0;                            // mean FLIP on the display-transformed images
    Spread gpu_ms;                              // timestamps around the frame's passes
    std::vector<FrameStats::PassTime> pass_ms;  // each pass's median
    Spread cpu_ms;  // FrameStats::cpu_ms: planning, building and recording, to the submission
    double first_frame_ms = 0;     // the first frame's CPU time, pipelines included
    uint32_t first_pipelines = 0;  // pipelines the first frame created (new to its renderer)
    // No other configuration is both faster and more accurate, beyond the measurements' noise:
    // faster by more than TimeTolerance, more accurate by more than kParetoFlipTolerance
    // (MarkParetoFront, report.cpp).
    bool pareto = false;
    LinearImage image;
    std::vector<float> flip_map;  // per pixel, for the heat map
};

// Time differences between two rows below this are ties for the Pareto front: the larger of their
// frame times' interquartile ranges (half their spread, max - min, where the quartiles are not
// known) and kParetoTimeFraction of the slower median. The quartiles, unlike the extremes, do not
// move with one slow frame; the fraction covers the medians' own jitter on a busy machine.
inline constexpr double kParetoTimeFraction = 0.05;
double TimeTolerance(const AccuracyRow& a, const AccuracyRow& b);

// FLIP differences below this are ties for the Pareto front (FLIP is deterministic for one
// device and build; this is a fraction of the smallest difference between the light modes).
inline constexpr double kParetoFlipTolerance = 1e-4;

struct AccuracyReport {
    std::string scene, device;
    uint32_t width = 0, height = 0, supersample = 1, frames = 0, warmup = 0;
    LinearImage reference;  // downsampled to width x height
    double reference_ms = 0;
    std::vector<std::string> renderer_labels;
    std::vector<AccuracyRow> rows;
    DiagnosticList warnings;  // what the frames did not render as asked, each once
};

// `reference` draws the reference (create it with float32_target); `renderers` the
// configurations (AccuracyConfig::renderer indexes them; `labels` names them).
Result<AccuracyReport> RunAccuracyReport(Renderer& reference,
                                         std::span<Renderer* const> renderers,
                                         std::span<const std::string> labels,
                                         const Scene& scene,
                                         const ColorPipeline& color,
                                         const AccuracyOptions& options);

// How the report's times were measured, in words (report.md and report.json say it).
std::string TimingMethod(const AccuracyReport& report);

// Writes into `dir` (created): report.md, report.csv, report.json, plot.svg and plot.png (error
// against time, the Pareto front marked), reference.png, and per configuration render/NAME.png
// and heat/NAME.png (its FLIP map).
Status WriteAccuracyReport(const AccuracyReport& report,
                           const ColorPipeline& color,
                           const std::string& dir);

// Sets each row's `pareto` flag (AccuracyRow::pareto), with the tolerances said there.
void MarkParetoFront(std::vector<AccuracyRow>& rows);

// The plot alone: mean FLIP against time (GPU where measured, else CPU), one drawing (cairo)
// as an SVG document (960x600) and as an RGBA8 image of width x height.
std::string AccuracyPlotSvg(const AccuracyReport& report);
std::vector<uint8_t> AccuracyPlotImage(const AccuracyReport& report,
                                       uint32_t width,
                                       uint32_t height);

// A text the figure drew: what it is ("title", "x-axis", "y-axis", "legend", "label"), its words,
// its box in the figure's pixels (top-left origin; an axis title's box as it stands on the page)
// and, for a label, its table row (from 0).
struct PlotText {
    std::string kind, text;
    double x = 0, y = 0, width = 0, height = 0;
    size_t row = 0;
};
// The texts of the figure drawn at width x height, where AccuracyPlotImage draws them.
std::vector<PlotText> AccuracyPlotTexts(const AccuracyReport& report, double width, double height);

}  // namespace kiln::tools

#endif  // KILN_TOOLS_ACCURACY_REPORT_H_
