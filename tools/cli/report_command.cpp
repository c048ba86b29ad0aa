// kiln report [SCENE.gltf] -o DIR: error against run time of the renderer's approximations
// (kiln/tools/accuracy_report.h, docs/accuracy.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "kiln/tools/accuracy_report.h"
#include "kiln/tools/scaling.h"
#include "render_setup.h"

namespace kiln::cli {
namespace {

struct ReportArgs {
    std::string scene, output, materials, device;
    std::vector<std::string> packs, compare, only;
    tools::AccuracyOptions options;
    runtime::ColorOptions color;
    bool validation = false, no_default_light = false, no_fp16 = false;
    bool scaling = false;  // the forward/deferred sweep instead (kiln/tools/scaling.h)
    tools::ScalingOptions sweep;
};

// kiln report --scaling: both paths on generated scenes of every object and light count.
int RunScaling(const ReportArgs& a, CommandDiagnostics& run) {
    runtime::RendererOptions options;
    options.validation = a.validation;
    options.device_filter = a.device;
    Result<runtime::Renderer> made =
        MakeRenderer(options, a.packs.empty() ? std::vector{ShippedPackPath()} : a.packs);
    if (!made) {
        return run.Fail(made.error());
    }
    Result<runtime::ColorPipeline> color = runtime::ColorPipeline::Create(a.color);
    if (!color) {
        return run.Fail(color.error());
    }
    tools::ScalingOptions sweep = a.sweep;
    sweep.width = a.options.width;
    sweep.height = a.options.height;
    Result<tools::ScalingReport> report =
        tools::RunScalingReport(made.value(), color.value(), sweep);
    if (!report) {
        return run.Fail(report.error());
    }
    for (const std::string& m : made.value().ValidationMessages()) {
        run.diags.Error(DiagCode::kRenderFailed, "", kNoPosition, "validation: " + m);
    }
    if (run.diags.has_errors()) {
        return run.Finish(int(kExitInputError));
    }
    if (Status written = tools::WriteScalingReport(report.value(), a.output); !written.ok()) {
        return run.Fail(written.error(), a.output);
    }
    std::printf("%8s %7s %-9s %8s %12s %12s\n", "objects", "lights", "path", "draws", "GPU ms",
                "CPU ms");
    for (const tools::ScalingRow& row : report.value().rows) {
        std::printf("%8u %7u %-9s %8u %12.3f %12.3f\n", row.objects, row.lights, row.path.c_str(),
                    row.draws, row.gpu_ms.median, row.cpu_ms.median);
    }
    for (uint32_t n : sweep.objects) {
        const std::optional<uint32_t> c = tools::Crossover(report.value(), n);
        std::printf("%u objects: %s\n", n,
                    c ? ("deferred faster from " + std::to_string(*c) + " lights").c_str()
                      : "forward faster at every light count");
    }
    std::printf("%s/scaling.md: %zu frames measured, device '%s'\n", a.output.c_str(),
                report.value().rows.size(), report.value().device.c_str());
    return run.Finish(int(kExitOk));
}

// With the shipped packs, the fp16 configuration: auto-4 drawn with the shipped shaders compiled
// with --precision half, where the device has shaderFloat16 (a warning where it has none).
constexpr const char* kFp16Config = "auto-4-fp16";
Status AddFp16Comparison(ReportArgs& a, DiagnosticList& diags) {
    // --only means only: the fp16 configuration too when it is named.
    const bool named = std::find(a.only.begin(), a.only.end(), kFp16Config) != a.only.end();
    if (!a.packs.empty() || a.no_fp16 || (!a.only.empty() && !named))
        return {};
    const std::string half = ShippedPackPath(kShippedHalfPack);
    if (!std::filesystem::exists(half))
        return {};
    runtime::RendererOptions options;
    options.device_filter = a.device;
    Result<runtime::Renderer> probe = runtime::Renderer::Create(options);
    if (!probe)
        return probe.error();
    if (!probe.value().HasFloat16()) {
        diags.Warning(DiagCode::kRenderFailed, "", kNoPosition,
                      "the fp16 configuration is left out: device '" + probe.value().DeviceName() +
                          "' has no shaderFloat16");
        return {};
    }
    a.compare.insert(a.compare.begin(), "fp16=" + half);
    return {};
}

// "LABEL=PACK" -> {LABEL, PACK}; an empty label when there is no '='.
std::pair<std::string, std::string> SplitCompare(const std::string& text) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0) {
        return {"", text};
    }
    return {text.substr(0, eq), text.substr(eq + 1)};
}

// The configurations asked for: the defaults (or those --only names), then the automatic
// light mode once per --compare pack set.
Result<std::vector<tools::AccuracyConfig>> Configs(const ReportArgs& a) {
    std::vector<tools::AccuracyConfig> all = tools::DefaultAccuracyConfigs(), out;
    std::vector<std::string> names;
    for (const tools::AccuracyConfig& c : all) {
        names.push_back(c.name);
    }
    names.push_back(kFp16Config);
    for (const std::string& want : a.only) {
        const bool found = std::find(names.begin(), names.end(), want) != names.end();
        if (!found) {
            std::string list;
            for (const std::string& n : names) {
                list += (list.empty() ? "" : ", ") + n;
            }
            return Error{DiagCode::kBadCommandLine,
                         "--only: unknown configuration '" + want + "' (one of " + list + ")"};
        }
    }
    for (const tools::AccuracyConfig& c : all) {
        if (a.only.empty() || std::find(a.only.begin(), a.only.end(), c.name) != a.only.end()) {
            out.push_back(c);
        }
    }
    for (size_t i = 0; i < a.compare.size(); ++i) {
        tools::AccuracyConfig c = all[1];  // auto-4: Unity's default
        c.group = "packs";
        c.renderer = i + 1;
        c.name += "-" + SplitCompare(a.compare[i]).first;
        c.description = c.name == kFp16Config
                            ? "auto-4 with the shipped shaders compiled with --precision half "
                              "(binary16 where the templates say half)"
                            : "auto-4 with the shaders of " + SplitCompare(a.compare[i]).second;
        out.push_back(c);
    }
    return out;
}

}  // namespace

std::function<int()> AddReportCommand(CLI::App* cmd, const GlobalOptions& global) {
    auto a = std::make_shared<ReportArgs>();
    cmd->add_option("scene", a->scene,
                    ".gltf or .glb file (default: the demo scene of the build tree)");
    cmd->add_option("-o,--output", a->output, "Folder for the tables, plot and images")->required();
    cmd->add_option("--pack", a->packs,
                    "Variant packs the reference and the configurations use, searched in order "
                    "(default: the shipped materials.kpack)");
    cmd->add_option("--compare", a->compare,
                    "Also render the automatic light mode with PACK searched before the --pack "
                    "packs, as LABEL=PACK (repeatable; e.g. O0=materials-O0.kpack, or a pack of "
                    "one shader built with -D KILN_BRDF_F_EXACT)")
        ->option_text("LABEL=PACK");
    cmd->add_option("--only", a->only,
                    "Only these configurations (repeatable): default ones by name, or "
                    "auto-4-fp16; nothing else is drawn");
    cmd->add_flag("--no-fp16", a->no_fp16,
                  "Leave out the fp16 configuration (the shipped shaders compiled with "
                  "--precision half, drawn where the device has shaderFloat16)");
    cmd->add_option("--width", a->options.width, "Image width (default 640)")
        ->check(CLI::Range(1, 4096).description(""));
    cmd->add_option("--height", a->options.height, "Image height (default 360)")
        ->check(CLI::Range(1, 4096).description(""));
    cmd->add_option("--supersample", a->options.supersample,
                    "The reference's samples per pixel along each axis (default 4)")
        ->check(CLI::Range(1, 8).description(""));
    CLI::Option* frames =
        cmd->add_option("--frames", a->options.frames,
                        "Timed frames per configuration (default 10; --scaling: 5 per path)")
            ->check(CLI::Range(1, 1000).description(""));
    CLI::Option* warmup =
        cmd->add_option("--warmup", a->options.warmup,
                        "Frames before the timed ones (default 2; --scaling: 1 per path)")
            ->check(CLI::Range(1, 100).description(""));
    cmd->add_option("--materials", a->materials,
                    "Material sidecar (default: <scene>.kiln.json when present)");
    cmd->add_option("--exposure", a->color.exposure, "Exposure in stops before the view");
    cmd->add_flag("--no-default-light", a->no_default_light,
                  "Do not add a directional light to scenes that have none");
    cmd->add_flag("--validation", a->validation,
                  "Enable VK_LAYER_KHRONOS_validation; any message fails the report");
    cmd->add_option("--device", a->device, "Use a Vulkan device whose name contains this");
    cmd->add_flag("--scaling", a->scaling,
                  "Time the forward and deferred paths on generated scenes of N objects and M "
                  "lights instead (scaling.md, .csv, .json, .svg, .png)");
    cmd->add_option("--scaling-objects", a->sweep.objects,
                    "Object counts of --scaling (default 10,100,1000,10000)")
        ->delimiter(',')
        ->check(CLI::Range(1u, 100000u));
    cmd->add_option("--scaling-lights", a->sweep.lights,
                    "Light counts of --scaling (default 1,4,16,64,256)")
        ->delimiter(',')
        ->check(CLI::Range(1u, 4096u));
    return [a, &global, frames, warmup] {
        if (frames->count() > 0) {
            a->sweep.frames = a->options.frames;
        }
        if (warmup->count() > 0) {
            a->sweep.warmup = a->options.warmup;
        }
        CommandDiagnostics run(global);
        DiagnosticList& diags = run.diags;
        if (a->scaling) {
            if (!a->scene.empty()) {
                diags.Error(DiagCode::kBadCommandLine, "", kNoPosition,
                            "--scaling draws generated scenes: give no scene file");
                return run.Finish(int(kExitUsageError));
            }
            return RunScaling(*a, run);
        }
        if (a->scene.empty()) {
            a->scene = DemoScenePath();
            if (a->scene.empty()) {
                return run.Fail(Error{DiagCode::kBadCommandLine,
                                      "no scene given, and the demo scene is not beside this kiln "
                                      "(give a .gltf or .glb file)"});
            }
        }
        if (Status fp16 = AddFp16Comparison(*a, diags); !fp16.ok()) {
            return run.Fail(fp16.error());
        }
        Result<std::vector<tools::AccuracyConfig>> configs = Configs(*a);
        if (!configs) {
            return run.Fail(configs.error());
        }
        a->options.configs = std::move(configs).value();
        a->options.default_light = !a->no_default_light;
        Result<runtime::Scene> loaded = runtime::LoadGltf(a->scene, diags);
        if (!loaded) {
            return run.Fail(loaded.error());
        }
        runtime::Scene scene = std::move(loaded).value();
        if (!a->materials.empty()) {
            if (Status read = runtime::LoadMaterialSidecar(a->materials, scene); !read.ok()) {
                return run.Fail(read.error());
            }
        }
        Result<runtime::ColorPipeline> made_color = runtime::ColorPipeline::Create(a->color);
        if (!made_color) {
            return run.Fail(made_color.error());
        }
        const runtime::ColorPipeline color = std::move(made_color).value();
        if (a->packs.empty()) {
            a->packs.push_back(ShippedPackPath());
        }
        // The reference's renderer (fp32 targets), then one per pack set.
        std::vector<std::vector<std::string>> pack_sets{a->packs, a->packs};
        std::vector<std::string> labels{"default"};
        for (const std::string& c : a->compare) {
            const auto [label, path] = SplitCompare(c);
            if (label.empty() || path.empty()) {
                return run.Fail(
                    Error{DiagCode::kBadCommandLine, "--compare '" + c + "': expected LABEL=PACK"});
            }
            pack_sets.push_back({path});  // its shaders first; the others from --pack
            pack_sets.back().insert(pack_sets.back().end(), a->packs.begin(), a->packs.end());
            labels.push_back(label);
        }
        std::vector<runtime::Renderer> renderers;
        for (size_t i = 0; i < pack_sets.size(); ++i) {
            runtime::RendererOptions options;
            options.validation = a->validation;
            options.device_filter = a->device;
            options.float32_target = i == 0;
            Result<runtime::Renderer> made = MakeRenderer(options, pack_sets[i]);
            if (!made) {
                return run.Fail(made.error());
            }
            renderers.push_back(std::move(made).value());
        }
        std::vector<runtime::Renderer*> drawing;
        for (size_t i = 1; i < renderers.size(); ++i) {
            drawing.push_back(&renderers[i]);
        }
        Result<tools::AccuracyReport> report =
            tools::RunAccuracyReport(renderers[0], drawing, labels, scene, color, a->options);
        if (!report) {
            return run.Fail(report.error());
        }
        diags.Append(report.value().warnings);
        for (runtime::Renderer& r : renderers) {
            for (const std::string& m : r.ValidationMessages()) {
                diags.Error(DiagCode::kRenderFailed, "", kNoPosition, "validation: " + m);
            }
        }
        if (diags.has_errors()) {
            return run.Finish(int(kExitInputError));
        }
        if (Status written = tools::WriteAccuracyReport(report.value(), color, a->output);
            !written.ok()) {
            return run.Fail(written.error(), a->output);
        }
        std::printf("%-24s %-8s %10s %10s %12s %12s\n", "configuration", "packs", "FLIP", "RMSE",
                    "GPU ms", "CPU ms");
        for (const tools::AccuracyRow& row : report.value().rows) {
            std::printf("%-24s %-8s %10.4f %10.3g %12.3f %12.3f%s\n", row.config.name.c_str(),
                        row.config.label.c_str(), row.flip, row.error.rmse, row.gpu_ms.median,
                        row.cpu_ms.median, row.pareto ? "  pareto" : "");
        }
        std::printf("%s/report.md: %zu configurations against the reference, device '%s'\n",
                    a->output.c_str(), report.value().rows.size(), report.value().device.c_str());
        return run.Finish(int(kExitOk));
    };
}

}  // namespace kiln::cli
