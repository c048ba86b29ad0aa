// kiln render SCENE.gltf -o OUT.png: the runtime library driven from the command line.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "commands.h"
#include "kiln/base/files.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/plan.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "kiln/tools/frame_debug.h"
#include "render_setup.h"
#include "render_watch.h"

namespace kiln::cli {
namespace {

// --camera: "auto" or an index from 0.
std::string ParseCamera(const std::string& text, int& camera) {
    if (text == "auto") {
        camera = runtime::FrameSettings::kCameraAuto;
        return "";
    }
    char* end = nullptr;
    const long n = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || n < 0 || n > 1000000)
        return "expected a camera index from 0, or auto";
    camera = int(n);
    return "";
}

// --ambient: "R,G,B" (one linear colour) or "SKY:EQUATOR:GROUND", each R,G,B (Unity's gradient).
// The procedural sky's default colours (linear radiance): a clear day, bright enough beside the
// default light's pi lux to read as daylight ambient.
constexpr glm::vec3 kSkyZenith{0.10f, 0.18f, 0.38f};
constexpr glm::vec3 kSkyHorizon{0.32f, 0.35f, 0.40f};
constexpr glm::vec3 kSkyGround{0.08f, 0.07f, 0.06f};

// `--ambient IMAGE.hdr`: the same as --sky IMAGE.hdr.
bool IsSkyImage(const std::string& text) {
    return text.size() > 4 && (text.compare(text.size() - 4, 4, ".hdr") == 0 ||
                               text.compare(text.size() - 4, 4, ".HDR") == 0);
}

std::string ParseAmbient(const std::string& text, runtime::Scene* scene) {
    if (IsSkyImage(text)) {
        return "";  // read when the scene is (LoadSky)
    }
    // flat:R,G,B: one colour, spelled out (the default before the sky was).
    if (text.rfind("flat:", 0) == 0) {
        if (text.find(':', 5) != std::string::npos ||
            !ParseAmbient(text.substr(5), nullptr).empty())
            return "expected flat:R,G,B (one linear, non-negative colour)";
        return ParseAmbient(text.substr(5), scene);
    }
    // Kiln's procedural sky, with its default clear-day colours or ZENITH:HORIZON:GROUND.
    if (text == "sky" || text.rfind("sky:", 0) == 0) {
        runtime::Scene colours;
        if (text != "sky") {
            if (std::string e = ParseAmbient(text.substr(4), &colours); !e.empty()) {
                return "expected sky or sky:ZENITH:HORIZON:GROUND of R,G,B each";
            }
            if (colours.ambient_mode != runtime::AmbientMode::kTrilight) {
                return "expected sky or sky:ZENITH:HORIZON:GROUND of R,G,B each";
            }
        } else {
            colours.ambient = kSkyZenith;
            colours.ambient_equator = kSkyHorizon;
            colours.ambient_ground = kSkyGround;
        }
        if (scene) {
            scene->ambient_mode = runtime::AmbientMode::kSky;
            scene->sky = runtime::ProceduralSky(colours.ambient, colours.ambient_equator,
                                                colours.ambient_ground);
        }
        return "";
    }
    std::vector<glm::vec3> colours;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = std::min(text.find(':', start), text.size());
        const std::string part = text.substr(start, end - start);
        glm::vec3 c(0.0f);
        char tail = 0;
        if (std::sscanf(part.c_str(), "%f,%f,%f%c", &c.r, &c.g, &c.b, &tail) != 3 ||
            !std::isfinite(c.r + c.g + c.b) || c.r < 0 || c.g < 0 || c.b < 0) {
            return "expected R,G,B (linear, non-negative), SKY:EQUATOR:GROUND of R,G,B each, or "
                   "sky[:ZENITH:HORIZON:GROUND]";
        }
        colours.push_back(c);
        start = end + 1;
    }
    if (colours.size() != 1 && colours.size() != 3) {
        return "expected one colour (flat) or three, SKY:EQUATOR:GROUND (a gradient)";
    }
    if (scene) {
        scene->ambient_mode =
            colours.size() == 3 ? runtime::AmbientMode::kTrilight : runtime::AmbientMode::kFlat;
        scene->ambient = colours[0];
        scene->ambient_equator = colours[colours.size() == 3 ? 1 : 0];
        scene->ambient_ground = colours[colours.size() == 3 ? 2 : 0];
    }
    return "";
}

struct RenderArgs {
    std::string scene, output = "out.png", exr, materials, usage, pipeline_cache;
    std::vector<std::string> packs;
    runtime::FrameSettings frame;
    runtime::ColorOptions color;
    bool validation = false, closest = false, no_default_light = false, trust = false;
    bool dry_run = false, allow_missing = false, watch = false;
    std::string device, camera, ambient, frame_debug, sky;
    float sky_intensity = 1;
};

// --dry-run: the frame's lookups without a device (kiln/runtime/plan.h), written to --usage.
int DryRun(const RenderArgs& a,
           const runtime::Scene& scene,
           const runtime::ColorPipeline& color,
           DiagnosticList& diags,
           const GlobalOptions& global) {
    auto finish = [&](int code) {
        PrintDiagnostics(diags, {}, global);
        return code;
    };
    std::vector<std::unique_ptr<pack::MappedFile>> files;
    std::vector<std::unique_ptr<pack::Pack>> packs;
    std::vector<const pack::Pack*> views;
    for (const std::string& path : a.packs) {
        Result<pack::MappedFile> mapped = pack::MappedFile::Map(path);
        if (!mapped) {
            diags.Error(mapped.error().code, path, kNoPosition, mapped.error().message);
            return finish(int(kExitInputError));
        }
        files.push_back(std::make_unique<pack::MappedFile>(std::move(mapped).value()));
        Result<pack::Pack> opened = pack::Pack::Open(files.back()->bytes());
        if (!opened) {
            diags.Error(opened.error().code, path, kNoPosition, opened.error().message);
            return finish(int(kExitInputError));
        }
        packs.push_back(std::make_unique<pack::Pack>(std::move(opened).value()));
        views.push_back(packs.back().get());
    }
    Result<runtime::ScenePlan> planned = runtime::PlanScene(views, scene, a.frame, color, diags);
    if (!planned) {
        diags.Error(planned.error().code, a.scene, kNoPosition, planned.error().message);
        return finish(int(kExitInputError));
    }
    const runtime::ScenePlan& plan = planned.value();
    if (!a.allow_missing) {
        diags.Append(plan.missing);
    }
    if (!a.usage.empty()) {
        if (Status written = pack::WriteUsageFile(a.usage, plan.usage); !written.ok()) {
            diags.Error(written.error().code, a.usage, kNoPosition, written.error().message);
            return finish(int(kExitInputError));
        }
    }
    std::fprintf(a.usage == base::kStandardStream ? stderr : stdout,
                 "%s: dry run, %u objects, %u draws, %zu distinct lookups, %zu missing\n",
                 a.scene.c_str(), plan.objects, plan.draws, plan.usage.lookups.size(),
                 plan.missing.all().size());
    return finish(ExitCodeFor(diags));
}

}  // namespace

std::function<int()> AddRenderCommand(CLI::App* cmd, const GlobalOptions& global) {
    auto a = std::make_shared<RenderArgs>();
    cmd->add_option("scene", a->scene, ".gltf or .glb file")->required();
    cmd->add_option("--pack", a->packs,
                    "Variant packs to take shaders from, searched in order (default: the "
                    "shipped materials.kpack)");
    cmd->add_option("-o,--output", a->output, "PNG to write (8-bit, display-encoded)");
    cmd->add_option("--exr", a->exr, "Also write the linear image as 32-bit float OpenEXR");
    cmd->add_option("--width", a->frame.width, "Image width, 1 to 16384 (default 960)")
        ->check(CLI::Range(1, 16384).description(""))
        ->option_text("W");
    cmd->add_option("--height", a->frame.height, "Image height, 1 to 16384 (default 540)")
        ->check(CLI::Range(1, 16384).description(""))
        ->option_text("H");
    cmd->add_option("--camera", a->camera,
                    "Scene camera index from 0, or auto: one framing the scene (default: the "
                    "first camera, else auto)")
        ->check(CLI::Validator(
            [](std::string& v) {
                int ignored = 0;
                return ParseCamera(v, ignored);
            },
            ""))
        ->option_text("N|auto");
    cmd->add_option("--pixel-lights", a->frame.pixel_lights,
                    "Additive per-light passes per object at most (default 4)");
    cmd->add_option("--light-mode", a->frame.light_mode,
                    "How lights other than the main directional one light an object: auto "
                    "(Unity's: --pixel-lights per pixel, 4 point lights per vertex, the rest "
                    "in SH), pixel, vertex or sh (default auto)")
        ->transform(
            CLI::CheckedTransformer(
                std::map<std::string, runtime::LightMode>{{"auto", runtime::LightMode::kAuto},
                                                          {"pixel", runtime::LightMode::kPixel},
                                                          {"vertex", runtime::LightMode::kVertex},
                                                          {"sh", runtime::LightMode::kSH}},
                CLI::ignore_case)
                .description(""))
        ->option_text("auto|pixel|vertex|sh");
    AddPathOption(*cmd, a->frame.path.name);
    cmd->add_option("--msaa", a->frame.msaa,
                    "Samples per pixel on the forward path, resolved before the display "
                    "transform (default 1; the deferred path draws 1)")
        ->check(CLI::IsMember({1u, 2u, 4u, 8u}).description(""))
        ->option_text("1|2|4|8");
    cmd->add_option("--shadows", a->frame.shadows,
                    "Real-time shadows of the pixel lights from the objects' ShadowCaster "
                    "passes: off, hard, or soft (SHADOWS_SOFT) "
                    "(default off)")
        ->transform(CLI::CheckedTransformer(
                        std::map<std::string, runtime::Shadows>{{"off", runtime::Shadows::kOff},
                                                                {"hard", runtime::Shadows::kHard},
                                                                {"soft", runtime::Shadows::kSoft}},
                        CLI::ignore_case)
                        .description(""))
        ->option_text("off|hard|soft");
    cmd->add_option("--shadow-resolution", a->frame.shadow_resolution,
                    "Texels a side of each shadow map, 16 to 8192 (default 2048; a point "
                    "light's cube faces half that)")
        ->check(CLI::Range(16u, 8192u).description(""))
        ->option_text("N");
    cmd->add_option("--gbuffer-normals", a->frame.gbuffer.normals,
                    "Deferred path: the G-buffer normal target's format (default rgb10a2, "
                    "Unity's)")
        ->transform(CLI::CheckedTransformer(
                        std::map<std::string, runtime::GBufferSettings::Normals>{
                            {"rgb10a2", runtime::GBufferSettings::Normals::kRGB10A2},
                            {"rgba8", runtime::GBufferSettings::Normals::kRGBA8},
                            {"rgba16f", runtime::GBufferSettings::Normals::kRGBA16F}},
                        CLI::ignore_case)
                        .description(""))
        ->option_text("rgb10a2|rgba8|rgba16f");
    cmd->add_flag("--gbuffer-octahedral", a->frame.gbuffer.octahedral,
                  "Deferred path: store normals octahedrally encoded (keyword "
                  "_GBUFFER_NORMALS_OCT)");
    cmd->add_option("--exposure", a->color.exposure, "Exposure in stops before the view");
    cmd->add_option("--time", a->frame.time, "Seconds, for _Time (default 0)")
        ->check(CLI::Validator(
            [](std::string& v) -> std::string {
                char* end = nullptr;
                const double t = std::strtod(v.c_str(), &end);
                if (end == v.c_str() || *end != '\0' || !std::isfinite(t) || std::fabs(t) > 1e9)
                    return "must be a finite number of seconds (at most 1e9 either way)";
                return "";
            },
            ""))
        ->option_text("SECONDS");
    cmd->add_option("--ambient", a->ambient,
                    "Ambient light, linear: one colour (R,G,B or flat:R,G,B), Unity's gradient "
                    "SKY:EQUATOR:GROUND, Kiln's procedural sky, or a sky image as --sky "
                    "(default: the sidecar's, else the procedural sky, as a new Unity scene)")
        ->check(CLI::Validator([](std::string& v) { return ParseAmbient(v, nullptr); }, ""))
        ->option_text("R,G,B|flat:R,G,B|R,G,B:R,G,B:R,G,B|sky[:R,G,B:R,G,B:R,G,B]|IMAGE.hdr");
    cmd->add_option("--sky", a->sky,
                    "Ambient light from an equirectangular HDR image (Radiance .hdr; row 0 "
                    "straight up, the centre looking down -Z), projected to SH")
        ->option_text("IMAGE.hdr");
    cmd->add_option("--sky-intensity", a->sky_intensity,
                    "Scale of the --sky image's radiance (default 1)")
        ->check(CLI::Range(0.0f, 1e6f).description(""))
        ->option_text("S");
    cmd->add_flag("--no-default-light", a->no_default_light,
                  "Do not add a directional light to scenes that have none");
    cmd->add_option("--ocio-config", a->color.config_path,
                    "OpenColorIO config (default: $OCIO, else Kiln's built-in sRGB config)");
    cmd->add_option("--display", a->color.display, "OpenColorIO display");
    cmd->add_option("--view", a->color.view, "OpenColorIO view");
    cmd->add_option("--materials", a->materials,
                    "Material sidecar assigning .material files to glTF materials by name "
                    "(default: <scene>.kiln.json when present)");
    cmd->add_flag("--validation", a->validation,
                  "Enable VK_LAYER_KHRONOS_validation; any message fails the render");
    cmd->add_flag("--closest-variant", a->closest,
                  "Take the closest variant (with a warning) when one was stripped");
    cmd->add_option("--usage", a->usage, "Write every variant lookup to this JSON file");
    cmd->add_flag("--dry-run", a->dry_run,
                  "Plan the frame without a GPU: make every variant lookup a render makes (and "
                  "write them to --usage), draw nothing; a variant the packs lack is an error");
    cmd->add_flag("--allow-missing", a->allow_missing,
                  "With --dry-run: record lookups of variants the packs lack without failing "
                  "(planning against packs not built yet, as kiln compile --scene does)");
    cmd->add_option("--frame-debug", a->frame_debug,
                    "Draw the frame one step at a time and write each pass's and draw's record "
                    "and an image of every target it writes after each step, with an index.html "
                    "to step through in a browser, into this folder")
        ->option_text("DIR");
    cmd->add_flag("--watch", a->watch,
                  "Render again whenever a pack, the scene, its --materials sidecar, a material "
                  "file or the --sky image changes: a pack is replaced in the running renderer "
                  "(unchanged variants keep their pipelines), the images and the --frame-debug "
                  "page are written again (the page reloads itself); until interrupted");
    cmd->add_option("--pipeline-cache", a->pipeline_cache, "Persist the VkPipelineCache here");
    cmd->add_option("--device", a->device, "Use a Vulkan device whose name contains this");
    cmd->add_flag("--trust-packs", a->trust,
                  "Hand the packs' SPIR-V to the driver without validating it first (only for "
                  "packs you built yourself)");
    return [a, &global] {
        // Every warning and error goes into one list, printed once (one JSON array).
        DiagnosticList diags = global.NewDiagnostics();
        auto finish = [&](int code) {
            PrintDiagnostics(diags, {}, global);
            return code;
        };
        auto fail = [&](const kiln::Error& e, std::string file = "") {
            std::string message = e.message;
            const std::string prefix = a->scene + ": ";
            if (file.empty() && message.rfind(prefix, 0) == 0) {
                file = a->scene;  // "scene.gltf: what" -> a diagnostic in scene.gltf
                message.erase(0, prefix.size());
            } else if (!file.empty() && message.rfind(file + ": ", 0) == 0) {
                message.erase(0, file.size() + 2);  // the file is the diagnostic's already
            }
            diags.Error(e.code, file, kNoPosition, message);
            return finish(int(kExitInputError));
        };
        a->frame.default_light = !a->no_default_light;
        // Outputs that are inputs, directories or devices are refused before any work.
        std::vector<std::string> inputs = a->packs;
        inputs.push_back(a->scene);
        if (!a->materials.empty())
            inputs.push_back(a->materials);
        // One output may be standard output ("-"); the summary then goes to stderr.
        int to_stdout = 0;
        for (const std::string* out : {&a->output, &a->exr, &a->usage})
            to_stdout += *out == base::kStandardStream;
        if (to_stdout > 1 || a->pipeline_cache == base::kStandardStream) {
            diags.Error(DiagCode::kBadCommandLine, "", kNoPosition,
                        to_stdout > 1 ? "only one of -o, --exr and --usage can be - (standard "
                                        "output)"
                                      : "--pipeline-cache is read as well as written: it "
                                        "cannot be - (standard output)");
            return finish(int(kExitUsageError));
        }
        if (a->watch && (to_stdout > 0 || a->dry_run)) {
            diags.Error(DiagCode::kBadCommandLine, "", kNoPosition,
                        "--watch writes its images again on every change: it takes no - "
                        "(standard output) and no --dry-run");
            return finish(int(kExitUsageError));
        }
        FILE* const summary = to_stdout ? stderr : stdout;
        if (Status distinct = base::CheckDistinctOutputs({{"-o", a->output},
                                                          {"--exr", a->exr},
                                                          {"--usage", a->usage},
                                                          {"--pipeline-cache", a->pipeline_cache}});
            !distinct.ok()) {
            diags.Error(DiagCode::kCannotWriteFile, "", kNoPosition, distinct.error().message);
            return finish(int(kExitInputError));
        }
        // Checked again once the scene, its sidecar and the sky are read (their buffers, images
        // and materials are then in the input guard's list), and once more as each is written.
        auto outputs_refused = [&]() {
            for (const std::string* out : {&a->output, &a->exr, &a->usage, &a->pipeline_cache}) {
                if (out->empty())
                    continue;
                if (Result<std::string> ok = base::CheckOutputPath(*out, inputs); !ok) {
                    diags.Error(DiagCode::kCannotWriteFile, *out, kNoPosition, ok.error().message);
                    return true;
                }
            }
            return false;
        };
        if (outputs_refused())
            return finish(int(kExitInputError));
        if (!a->camera.empty())
            ParseCamera(a->camera, a->frame.camera);  // validated by the option's check
        // The scene, its sidecar and sky: loaded again on a change with --watch. An error is
        // the exit code of the command (printed); none when it loaded.
        runtime::Scene scene;
        bool default_sky = false;
        auto load_scene = [&]() -> std::optional<int> {
            Result<runtime::Scene> loaded = runtime::LoadGltf(a->scene, diags);
            if (!loaded) {
                return fail(loaded.error());
            }
            scene = std::move(loaded).value();
            if (!a->materials.empty()) {
                if (Status read = runtime::LoadMaterialSidecar(a->materials, scene); !read.ok()) {
                    return fail(read.error());
                }
            }
            if (IsSkyImage(a->ambient) && a->sky.empty()) {
                a->sky = std::exchange(a->ambient, "");  // --ambient IMAGE.hdr is --sky IMAGE.hdr
            }
            if (!a->ambient.empty() && !a->sky.empty()) {
                diags.Error(DiagCode::kBadScene, "", kNoPosition,
                            "--ambient and --sky both set the ambient light; give one");
                return finish(int(kExitInputError));
            }
            if (!a->ambient.empty()) {
                ParseAmbient(a->ambient, &scene);  // validated by the option's check
            }
            // A scene that says nothing of its environment gets a new Unity scene's: the
            // procedural sky as ambient and reflection source.
            default_sky = a->ambient.empty() && a->sky.empty() && !scene.ambient_given;
            if (default_sky)
                ParseAmbient("sky", &scene);
            if (!a->sky.empty()) {
                Result<std::shared_ptr<const runtime::Sky>> sky =
                    runtime::LoadSky(a->sky, a->sky_intensity);
                if (!sky) {
                    return fail(sky.error(), a->sky);
                }
                scene.ambient_mode = runtime::AmbientMode::kSky;
                scene.sky = std::move(sky).value();
            }
            return std::nullopt;
        };
        if (const std::optional<int> failed = load_scene())
            return *failed;
        Result<runtime::ColorPipeline> made_color = runtime::ColorPipeline::Create(a->color);
        if (!made_color) {
            return fail(made_color.error());
        }
        if (outputs_refused())
            return finish(int(kExitInputError));
        const runtime::ColorPipeline color = std::move(made_color).value();
        if (a->packs.empty()) {
            a->packs.push_back(ShippedPackPath());
        }
        if (a->dry_run) {
            return DryRun(*a, scene, color, diags, global);
        }
        runtime::RendererOptions options;
        options.validation = a->validation;
        options.device_filter = a->device;
        options.pipeline_cache = a->pipeline_cache;
        options.trust_packs = a->trust;
        options.missing_variant =
            a->closest ? pack::MissingVariantPolicy::kClosest : pack::MissingVariantPolicy::kError;
        Result<runtime::Renderer> made = MakeRenderer(options, a->packs);
        if (!made) {
            return fail(made.error());
        }
        runtime::Renderer renderer = std::move(made).value();
        // One frame: rendered, its images (and pages) written, its summary printed; the exit
        // code (diagnostics printed).
        std::string live_stamp;  // --watch with --frame-debug: the page reloads on a new one
        auto draw = [&]() -> int {
            runtime::LinearImage image;
            runtime::FrameStats stats;
            runtime::FrameCapture capture;
            const Status rendered = renderer.Render(scene, a->frame, color, image, stats,
                                                    a->frame_debug.empty() ? nullptr : &capture);
            diags.Append(stats.warnings);
            if (!a->usage.empty()) {
                if (Status written = renderer.WriteUsage(a->usage); !written.ok()) {
                    return fail(written.error());
                }
            }
            if (!rendered.ok()) {
                return fail(rendered.error());
            }
            const std::vector<std::string> messages = renderer.ValidationMessages();
            for (const std::string& m : messages) {
                diags.Error(DiagCode::kRenderFailed, "", kNoPosition, "validation: " + m);
            }
            if (!messages.empty())
                return finish(int(kExitInputError));  // no image from a render the layer rejected
            if (!a->exr.empty()) {
                if (Status written = runtime::WriteExr(a->exr, image); !written.ok()) {
                    return fail(written.error(), a->exr);
                }
            }
            if (Status written = runtime::WriteDisplayPng(a->output, image, color); !written.ok()) {
                return fail(written.error(), a->output);
            }
            if (!a->frame_debug.empty()) {
                if (Status written = tools::WriteFrameDebug(a->frame_debug, capture, live_stamp);
                    !written.ok()) {
                    return fail(written.error(), a->frame_debug);
                }
                std::fprintf(summary, "%s/index.html: %zu steps\n", a->frame_debug.c_str(),
                             capture.steps.size());
            }
            std::string deferred;
            if (!stats.path_counts.empty()) {
                deferred = stats.path_counts + ", ";
            }
            if (stats.shadow_draws > 0) {
                deferred += std::to_string(stats.shadow_draws) + " shadow draws, ";
            }
            if (stats.grab_copies > 0) {
                deferred += std::to_string(stats.grab_copies) + " GrabPass cop" +
                            (stats.grab_copies == 1 ? "y, " : "ies, ");
            }
            std::fprintf(summary,
                         "%s: %ux%u, camera '%s', %u objects, %s%u base + %u additive passes (%u "
                         "with vertex "
                         "lights, %u with SH lights), %u pipelines, device '%s', %s%s%s\n",
                         a->output.c_str(), image.width, image.height, stats.camera.c_str(),
                         stats.objects, deferred.c_str(), stats.base_passes, stats.add_passes,
                         stats.vertex_lit, stats.sh_lit, stats.pipelines_created,
                         renderer.DeviceName().c_str(), color.description().c_str(),
                         a->validation ? ", validation messages: 0" : "",
                         default_sky ? ", ambient: the default sky (the scene sets none; --ambient "
                                       "flat:R,G,B for one colour)"
                                     : "");
            return finish(int(kExitOk));
        };
        if (a->watch && !a->frame_debug.empty())
            live_stamp = "1";
        const int first = draw();
        if (!a->watch)
            return first;
        WatchedScene watched;
        watched.packs = a->packs;
        watched.files = [&] {
            std::vector<std::string> files = {a->scene};
            for (const std::string* f : {&a->materials, &a->sky}) {
                if (!f->empty())
                    files.push_back(*f);
            }
            for (const auto& [name, file] : scene.material_files)
                files.push_back(file);
            return files;
        };
        watched.load_scene = load_scene;
        watched.draw = draw;
        watched.next_frame = [&] {
            diags = global.NewDiagnostics();  // each frame prints its own
            if (!live_stamp.empty())
                live_stamp = std::to_string(std::stoul(live_stamp) + 1);
        };
        watched.report = [&](const Error& e, const std::string& file) {
            diags.Error(e.code, file, kNoPosition, e.message);
            PrintDiagnostics(diags, {}, global);
            diags = global.NewDiagnostics();
        };
        return WatchScene(renderer, watched, summary);
    };
}

}  // namespace kiln::cli
