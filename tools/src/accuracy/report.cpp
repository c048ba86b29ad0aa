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
    // A configuration's first frame (timed apart, with the pipelines it creates) and its image.
    Status First(Renderer& r, AccuracyRow& row) {
        FrameStats stats;
        const Clock::time_point start = Clock::now();
        if (Status e = Frame(r, SettingsOf(row.config), row.image, stats); !e.ok()) {
            return e;
        }
        row.first_frame_ms = MillisecondsSince(start);
        row.first_pipelines = stats.pipelines_created;
        return {};
    }
    // The timed frames: `warmup` rounds, then `frames` rounds, each round one frame of every
    // configuration in turn (A B C A B C ...), so that every configuration is measured on a
    // device as warm as the others' and none is timed after a pause (the error computations
    // come after all of them).
    Status Time(std::span<Renderer* const> renderers, std::vector<AccuracyRow>& rows);
    // The row's errors against the reference.
    Status Compare(AccuracyRow& row);
};

Status State::Time(std::span<Renderer* const> renderers, std::vector<AccuracyRow>& rows) {
    const uint32_t warmup = std::max(options.warmup, 1u), frames = std::max(options.frames, 1u);
    std::vector<std::vector<double>> gpu(rows.size()), cpu(rows.size());
    std::vector<std::vector<std::vector<double>>> passes(rows.size());
    std::vector<std::vector<FrameStats::PassTime>> names(rows.size());
    LinearImage image;
    for (uint32_t round = 0; round < warmup + frames; ++round) {
        for (size_t k = 0; k < rows.size(); ++k) {
            FrameStats stats;
            if (Status e = Frame(*renderers[rows[k].config.renderer], SettingsOf(rows[k].config),
                                 image, stats);
                !e.ok()) {
                return e;
            }
            if (round < warmup) {
                continue;
            }
            cpu[k].push_back(stats.cpu_ms);
            if (stats.gpu_ms >= 0) {
                gpu[k].push_back(stats.gpu_ms);
            }
            passes[k].resize(std::max(passes[k].size(), stats.pass_times.size()));
            for (size_t p = 0; p < stats.pass_times.size(); ++p) {
                passes[k][p].push_back(stats.pass_times[p].gpu_ms);
            }
            names[k] = stats.pass_times;
        }
    }
    for (size_t k = 0; k < rows.size(); ++k) {
        rows[k].cpu_ms = SpreadOf(cpu[k]);
        rows[k].gpu_ms = SpreadOf(gpu[k]);
        for (size_t p = 0; p < passes[k].size() && p < names[k].size(); ++p) {
            rows[k].pass_ms.push_back({names[k][p].pass, SpreadOf(passes[k][p]).median});
        }
    }
    return {};
}

Status State::Compare(AccuracyRow& row) {
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
    // Quartiles interpolated between the sorted values (the usual definition): with three
    // frames the interquartile range is half the spread, not all of it.
    auto quantile = [&](double p) {
        const double h = double(n - 1) * p;
        const size_t i = size_t(h);
        return i + 1 < n ? v[i] + (h - double(i)) * (v[i + 1] - v[i]) : v[i];
    };
    s.q1 = quantile(0.25);
    s.q3 = quantile(0.75);
    return s;
}

namespace {

// What a row's frame times vary by: their interquartile range, or half their spread.
double TimeNoise(const AccuracyRow& row) {
    const Spread& s = row.gpu_ms.median >= 0 ? row.gpu_ms : row.cpu_ms;
    if (s.q1 >= 0 && s.q3 >= s.q1) {
        return s.q3 - s.q1;
    }
    return s.max >= s.min ? 0.5 * (s.max - s.min) : 0.0;
}

}  // namespace

double TimeTolerance(const AccuracyRow& a, const AccuracyRow& b) {
    return std::max(
        {TimeNoise(a), TimeNoise(b), kParetoTimeFraction * std::max(TimeOf(a), TimeOf(b))});
}

// A configuration is on the Pareto front unless another is at least as fast and as accurate and
// better on one, each beyond its noise: time by TimeTolerance, FLIP by kParetoFlipTolerance.
// Differences inside the noise are ties, so the flags do not change between runs with the
// timings' jitter.
void MarkParetoFront(std::vector<AccuracyRow>& rows) {
    for (AccuracyRow& a : rows) {
        a.pareto = true;
        for (const AccuracyRow& b : rows) {
            const double tol = TimeTolerance(a, b);
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
    report.warmup = std::max(options.warmup, 1u);
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
        row.config = c;
        if (row.config.label.empty() && c.renderer < labels.size()) {
            row.config.label = labels[c.renderer];
        }
        if (Status e = state.First(*renderers[c.renderer], row); !e.ok()) {
            return e.error();
        }
    }
    if (Status e = state.Time(renderers, report.rows); !e.ok()) {
        return e.error();
    }
    for (AccuracyRow& row : report.rows) {
        if (Status e = state.Compare(row); !e.ok()) {
            return e.error();
        }
    }
    MarkParetoFront(report.rows);
    return report;
}

}  // namespace kiln::tools
