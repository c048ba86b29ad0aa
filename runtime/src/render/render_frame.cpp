// RenderFrame: one frame along the path FrameSettings::path names (render/render_path.h). What
// every path shares is here: the settings' checks, the camera, the frame debugger's observer
// (which records the frame as drawn: shadow passes and MSAA included), the DrawBuilder, and
// recording the built Frame. What a path draws is the path's: its plan and its frame's targets
// and passes.
#include "kiln/runtime/frame_capture.h"
#include "render/capture.h"
#include "render/render_path.h"
#include "render/renderer_state.h"

namespace kiln::runtime {
namespace {

Status CheckSettings(const Renderer::State& s, const Scene& scene, const FrameSettings& settings) {
    if (settings.width == 0 || settings.height == 0 || settings.width > 16384 ||
        settings.height > 16384) {
        return Error{DiagCode::kBadScene, "image size must be between 1x1 and 16384x16384"};
    }
    if (s.packs.empty()) {
        return Error{DiagCode::kRenderFailed, "no variant pack loaded"};
    }
    if (settings.msaa != 1 && settings.msaa != 2 && settings.msaa != 4 && settings.msaa != 8) {
        return Error{DiagCode::kBadScene, "msaa must be 1, 2, 4 or 8 samples per pixel (got " +
                                              std::to_string(settings.msaa) + ")"};
    }
    if (scene.instances.empty()) {
        return Error{DiagCode::kBadScene,
                     (scene.path.empty() ? std::string("the scene") : scene.path) +
                         ": nothing to draw (no node of the scene has a mesh)"};
    }
    return {};
}

// The device draws `samples` per pixel into its colour and depth formats.
Status CheckSamples(const Renderer::State& s, uint32_t samples) {
    const VkSampleCountFlags supported = s.context.properties.limits.framebufferColorSampleCounts &
                                         s.context.properties.limits.framebufferDepthSampleCounts;
    if (supported & VkSampleCountFlags(samples)) {
        return {};
    }
    std::string counts;
    for (uint32_t n = 1; n <= 64; n *= 2) {
        counts += supported & n ? (counts.empty() ? "" : ", ") + std::to_string(n) : "";
    }
    return Error{DiagCode::kRenderFailed,
                 "device '" + std::string(s.context.properties.deviceName) + "' cannot render " +
                     std::to_string(samples) + " samples per pixel (it has " + counts + ")"};
}

}  // namespace

Status DrawPlan(Renderer::State& s,
                SceneResources& resources,
                const Scene& scene,
                const FrameSettings& settings,
                const CameraSetup& camera,
                const PathPlan& plan,
                LinearImage& out,
                FrameStats& stats,
                const StepObserver* observer,
                std::chrono::steady_clock::time_point started) {
    Frame frame;
    frame.width = settings.width;
    frame.height = settings.height;
    DrawBuilder builder(s, resources, scene, FrameValues(scene, settings, camera), stats,
                        observer != nullptr);
    BuildInputs in{s, resources, builder, scene, settings, camera, stats};
    if (Status e = plan.Build(in, frame); !e.ok()) {
        return e;
    }
    stats.objects = plan.Objects();
    frame.uniforms = builder.TakeUniforms();
    return RecordFrame(s, frame, out, stats, observer, started);
}

Status RenderFrame(Renderer::State& s,
                   const Scene& scene,
                   const FrameSettings& settings,
                   const ColorPipeline& color,
                   LinearImage& out,
                   FrameStats& stats,
                   FrameCapture* capture) {
    const auto started = std::chrono::steady_clock::now();
    if (Status e = CheckSettings(s, scene, settings); !e.ok()) {
        return e;
    }
    const PathRenderer* path = FindPathRenderer(settings.path.name);
    if (!path) {
        return UnknownPath(settings.path.name);
    }
    SceneResources& resources = s.ResourcesFor(scene, color);
    const bool automatic = scene.cameras.empty() || settings.camera == FrameSettings::kCameraAuto;
    if (!resources.bounds && automatic) {  // the automatic camera frames them
        resources.bounds = SceneBounds(scene);
    }
    CameraSetup camera;
    if (Status e =
            ChooseCamera(scene, settings, camera, resources.bounds ? &*resources.bounds : nullptr);
        !e.ok()) {
        return e;
    }
    stats.camera = camera.name;

    const uint32_t uploads = resources.uploads;
    const size_t materials = resources.materials.size();
    StepObserver observer;
    FrameSettings drawn = settings;
    if (capture) {
        *capture = FrameCapture{};
        capture->scene = scene.path.empty() ? std::string("(scene)") : scene.path;
        capture->path = std::string(path->Name());
        observer = CaptureObserver(camera.projection, color, *capture);
    }
    path->Adjust(drawn, scene, stats.warnings);
    if (Status e = CheckSamples(s, drawn.msaa); !e.ok()) {
        return e;
    }
    if (drawn.shadows != Shadows::kOff && !resources.bounds) {
        resources.bounds = SceneBounds(scene);
    }
    const std::vector<const pack::Pack*> packs = s.PackList();
    const PlanInputs in{packs, scene, drawn, camera, color, resources.materials, stats.warnings};
    Result<std::unique_ptr<PathPlan>> planned = path->Plan(in);
    if (!planned) {
        return planned.error();
    }
    const PathPlan& plan = *planned.value();
    std::vector<const MaterialInstance*> used;
    plan.Materials(used);
    s.NoteMaterials(used);
    stats.materials_resolved = uint32_t(resources.materials.size() - materials);

    const Status drawn_frame = DrawPlan(s, resources, scene, drawn, camera, plan, out, stats,
                                        capture ? &observer : nullptr, started);
    stats.path_counts = path->Counts(stats);
    stats.buffers_uploaded = resources.uploads - uploads;
    return drawn_frame;
}

}  // namespace kiln::runtime
