// RunAccuracyReport: the reference, then each configuration rendered, timed and compared.
#include "kiln/tools/accuracy_report.h"

#include <algorithm>
#include <chrono>
#include <set>

namespace kiln::tools {

using runtime::ColorPipeline;
using runtime::FrameSettings;
using runtime::FrameStats;
using runtime::GBufferSettings;
using runtime::LightMode;
using runtime::LinearImage;
using runtime::Renderer;
using runtime::RenderPath;
using runtime::Scene;
namespace {

constexpr uint32_t kEveryLight = 64;  // pixel lights per object: more than any scene asks for

AccuracyConfig Config(std::string name,
                      std::string group,
                      LightMode mode,
                      uint32_t pixel_lights,
                      std::string description) {
    AccuracyConfig c;
    c.name = std::move(name);
    c.group = std::move(group);
    c.settings.light_mode = mode;
    c.settings.pixel_lights = pixel_lights;
    c.description = std::move(description);
    return c;
}

AccuracyConfig Deferred(std::string name,
                        GBufferSettings::Normals normals,
                        bool octahedral,
                        std::string normals_text) {
    AccuracyConfig c = Config(std::move(name), "path", LightMode::kPixel, kEveryLight,
                              "the deferred path, G-buffer normals " + normals_text +
                                  (octahedral ? ", octahedral encoding" : ", xyz encoding"));
    c.settings.path = RenderPath::kDeferred;
    c.settings.gbuffer.normals = normals;
    c.settings.gbuffer.octahedral = octahedral;
    return c;
}

Spread SpreadOf(std::vector<double> v) {
    Spread s;
    if (v.empty()) {
        return s;
    }
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    s.min = v.front();
    s.max = v.back();
    return s;
}

using Clock = std::chrono::steady_clock;
double MillisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Time: GPU where measured, else CPU.
double TimeOf(const AccuracyRow& row) {
    return row.gpu_ms.median >= 0 ? row.gpu_ms.median : row.cpu_ms.median;
}

struct State {
    const Scene& scene;
    const ColorPipeline& color;
    const AccuracyOptions& options;
    AccuracyReport& report;
    std::set<std::string> warned;

    FrameSettings SettingsOf(const AccuracyConfig& c) const {
        FrameSettings s = c.settings;
        s.width = options.width;
        s.height = options.height;
        s.camera = options.camera;
        s.default_light = options.default_light;
        return s;
    }
    Status Frame(Renderer& r, const FrameSettings& s, LinearImage& out, FrameStats& stats) {
        stats = FrameStats{};
        if (Status e = r.Render(scene, s, color, out, stats); !e.ok()) {
            return e;
        }
        for (const Diagnostic& d : stats.warnings.all()) {
            if (warned.insert(d.message).second) {
                Diagnostic& copy =
                    report.warnings.Add(d.severity, d.code, d.file, d.range, d.message);
                copy.notes = d.notes;
            }
        }
        return {};
    }
    Status Row(Renderer& r, const AccuracyConfig& config, AccuracyRow& row);
};

Status State::Row(Renderer& r, const AccuracyConfig& config, AccuracyRow& row) {
    row.config = config;
    const FrameSettings settings = SettingsOf(config);
    FrameStats stats;
    std::vector<double> gpu, cpu;
    std::vector<std::vector<double>> passes;
    const uint32_t total = std::max(options.warmup, 1u) + std::max(options.frames, 1u);
    for (uint32_t i = 0; i < total; ++i) {
        const Clock::time_point start = Clock::now();
        if (Status e = Frame(r, settings, row.image, stats); !e.ok()) {
            return e;
        }
        const double ms = MillisecondsSince(start);
        if (i == 0) {
            row.first_frame_ms = ms;
            row.first_pipelines = stats.pipelines_created;
        }
        if (i < std::max(options.warmup, 1u)) {
            continue;
        }
        cpu.push_back(ms);
        if (stats.gpu_ms >= 0) {
            gpu.push_back(stats.gpu_ms);
        }
        passes.resize(std::max(passes.size(), stats.pass_times.size()));
        for (size_t p = 0; p < stats.pass_times.size(); ++p) {
            passes[p].push_back(stats.pass_times[p].gpu_ms);
        }
    }
    row.cpu_ms = SpreadOf(cpu);
    row.gpu_ms = SpreadOf(gpu);
    for (size_t p = 0; p < passes.size() && p < stats.pass_times.size(); ++p) {
        row.pass_ms.push_back({stats.pass_times[p].pass, SpreadOf(passes[p]).median});
    }
    Result<ImageError> error = CompareLinear(report.reference, row.image);
    if (!error) {
        return error.error();
    }
    row.error = error.value();
    std::vector<float> ref = report.reference.rgba, test = row.image.rgba;
    color.ApplyDisplay(ref);
    color.ApplyDisplay(test);
    Result<FlipMap> flip = Flip(options.width, options.height, ref, test, options.flip);
    if (!flip) {
        return flip.error();
    }
    row.flip = flip.value().mean;
    row.flip_map = std::move(flip.value().error);
    return {};
}

}  // namespace

// Half the spread (max - min) of a row's frame times: what a difference in time must exceed to
// count. Timed on lavapipe, frames vary by a few milliseconds from run to run.
double TimeNoise(const AccuracyRow& row) {
    const Spread& s = row.gpu_ms.median >= 0 ? row.gpu_ms : row.cpu_ms;
    return s.max >= s.min ? 0.5 * (s.max - s.min) : 0.0;
}

// A configuration is on the Pareto front unless another is at least as fast and as accurate and
// better on one, each beyond its noise: time by the larger of the two rows' TimeNoise, FLIP by
// kParetoFlipTolerance. Differences inside the noise are ties, so the flags do not change
// between runs with the timings' jitter.
void MarkParetoFront(std::vector<AccuracyRow>& rows) {
    for (AccuracyRow& a : rows) {
        a.pareto = true;
        for (const AccuracyRow& b : rows) {
            const double tol = std::max(TimeNoise(a), TimeNoise(b));
            const bool no_slower = TimeOf(b) <= TimeOf(a) + tol;
            const bool no_worse = b.flip <= a.flip + kParetoFlipTolerance;
            const bool better =
                TimeOf(b) < TimeOf(a) - tol || b.flip < a.flip - kParetoFlipTolerance;
            if (&a != &b && no_slower && no_worse && better) {
                a.pareto = false;
                break;
            }
        }
    }
}

std::vector<AccuracyConfig> DefaultAccuracyConfigs() {
    using N = GBufferSettings::Normals;
    auto automatic = [](const char* name, uint32_t n) {
        return Config(name, "light mode", LightMode::kAuto, n,
                      "forward, Unity's ranking: the brightest " + std::to_string(n) +
                          " lights per pixel, 4 point lights per vertex, the rest in SH" +
                          (n == 4 ? " (Unity's default)" : ""));
    };
    return {Config("pixel", "light mode", LightMode::kPixel, kEveryLight,
                   "forward, every light per pixel (the reference's lighting, without "
                   "supersampling)"),
            automatic("auto-4", 4),
            automatic("auto-2", 2),
            automatic("auto-1", 1),
            automatic("auto-0", 0),
            Config("vertex", "light mode", LightMode::kVertex, 0,
                   "forward, the main light per pixel, 4 point lights per vertex, the rest in SH"),
            Config("sh", "light mode", LightMode::kSH, 0,
                   "forward, the main light per pixel, every other light in SH"),
            Deferred("deferred-rgb10a2", N::kRGB10A2, false, "RGB10A2 (Unity's)"),
            Deferred("deferred-rgba8", N::kRGBA8, false, "RGBA8"),
            Deferred("deferred-rgba16f", N::kRGBA16F, false, "RGBA16F"),
            Deferred("deferred-rgb10a2-oct", N::kRGB10A2, true, "RGB10A2"),
            Deferred("deferred-rgba8-oct", N::kRGBA8, true, "RGBA8")};
}

Result<AccuracyReport> RunAccuracyReport(Renderer& reference,
                                         std::span<Renderer* const> renderers,
                                         std::span<const std::string> labels,
                                         const Scene& scene,
                                         const ColorPipeline& color,
                                         const AccuracyOptions& options) {
    const uint32_t ss = options.supersample;
    if (options.width == 0 || options.height == 0 || ss == 0 || ss > 8 ||
        uint64_t(options.width) * ss > 16384 || uint64_t(options.height) * ss > 16384) {
        return Error{DiagCode::kBadCommandLine,
                     "the report's size times its supersampling (1 to 8) must be at most "
                     "16384x16384"};
    }
    const std::vector<AccuracyConfig> configs =
        options.configs.empty() ? DefaultAccuracyConfigs() : options.configs;
    for (const AccuracyConfig& c : configs) {
        if (c.renderer >= renderers.size() || renderers[c.renderer] == nullptr) {
            return Error{DiagCode::kBadCommandLine,
                         "configuration '" + c.name + "' names a renderer that is not given"};
        }
    }
    AccuracyReport report;
    report.scene = scene.path.empty() ? std::string("(scene)") : scene.path;
    report.device = renderers.empty() ? reference.DeviceName() : renderers[0]->DeviceName();
    report.width = options.width;
    report.height = options.height;
    report.supersample = ss;
    report.frames = std::max(options.frames, 1u);
    report.renderer_labels.assign(labels.begin(), labels.end());
    State state{scene, color, options, report, {}};

    AccuracyConfig ref = Config("reference", "reference", LightMode::kPixel, kEveryLight, "");
    FrameSettings settings = state.SettingsOf(ref);
    settings.width *= ss;
    settings.height *= ss;
    LinearImage big;
    FrameStats stats;
    const Clock::time_point start = Clock::now();
    if (Status e = state.Frame(reference, settings, big, stats); !e.ok()) {
        return e.error();
    }
    report.reference_ms = MillisecondsSince(start);
    Result<LinearImage> small = Downsample(big, ss);
    if (!small) {
        return small.error();
    }
    report.reference = std::move(small.value());

    for (const AccuracyConfig& c : configs) {
        AccuracyRow& row = report.rows.emplace_back();
        if (Status e = state.Row(*renderers[c.renderer], c, row); !e.ok()) {
            return e.error();
        }
        if (row.config.label.empty() && c.renderer < labels.size()) {
            row.config.label = labels[c.renderer];
        }
    }
    MarkParetoFront(report.rows);
    return report;
}

}  // namespace kiln::tools
