// RenderFrame and the lecture's forward path. The draw list (render/forward_plan.h: passes,
// lights and keywords per primitive) becomes draws (render/draw_builder.h): the variant each asks
// for, its pipeline, uniform bytes and descriptors, decided on the CPU; then one command buffer
// records them all. Render dispatches to the deferred path (render/deferred.cpp) from here too.
#include <algorithm>

#include "kiln/runtime/frame_capture.h"
#include "render/capture.h"
#include "render/deferred_plan.h"
#include "render/draw_builder.h"
#include "render/forward_plan.h"
#include "render/frame.h"
#include "render/frame_values.h"
#include "render/grab_pass.h"
#include "render/renderer_state.h"
#include "render/shadow_passes.h"

namespace kiln::runtime {

Status RenderFrame(Renderer::State& s,
                   const Scene& scene,
                   const FrameSettings& settings,
                   const ColorPipeline& color,
                   LinearImage& out,
                   FrameStats& stats,
                   FrameCapture* capture) {
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
    SceneResources& resources = s.ResourcesFor(scene, color);
    const bool automatic = scene.cameras.empty() || settings.camera == FrameSettings::kCameraAuto;
    if (!resources.bounds && automatic) {  // the automatic camera frames them
        resources.bounds = SceneBounds(scene);
    }
    render::CameraSetup camera;
    if (Status e = render::ChooseCamera(scene, settings, camera,
                                        resources.bounds ? &*resources.bounds : nullptr);
        !e.ok()) {
        return e;
    }
    stats.camera = camera.name;

    const uint32_t uploads = resources.uploads;
    const size_t materials = resources.materials.size();
    StepObserver observer;
    if (capture) {
        *capture = FrameCapture{};
        capture->scene = scene.path.empty() ? std::string("(scene)") : scene.path;
        capture->path = settings.path == RenderPath::kDeferred ? "deferred" : "forward";
        observer = CaptureObserver(camera.projection, color, *capture);
    }
    const StepObserver* step = capture ? &observer : nullptr;
    // One sample per pixel where MSAA does not apply, as in Unity: the deferred path's G-buffer
    // (its light pass reads one sample), and the frame debugger, which reads every target back.
    FrameSettings sampled = settings;
    if (settings.msaa > 1 && (settings.path == RenderPath::kDeferred || capture)) {
        sampled.msaa = 1;
        stats.warnings.Warning(
            DiagCode::kRenderWarning, scene.path, kNoPosition,
            std::string("MSAA is off for ") +
                (capture ? "the frame debugger, which reads every target back"
                         : "the deferred path, whose light pass reads one G-buffer sample") +
                ": drawn with 1 sample per pixel");
    }
    const VkSampleCountFlags supported = s.context.properties.limits.framebufferColorSampleCounts &
                                         s.context.properties.limits.framebufferDepthSampleCounts;
    if (!(supported & VkSampleCountFlags(sampled.msaa))) {
        std::string counts;
        for (uint32_t n = 1; n <= 64; n *= 2) {
            counts += supported & n ? (counts.empty() ? "" : ", ") + std::to_string(n) : "";
        }
        return Error{DiagCode::kRenderFailed,
                     "device '" + std::string(s.context.properties.deviceName) +
                         "' cannot render " + std::to_string(sampled.msaa) +
                         " samples per pixel (it has " + counts + ")"};
    }
    // Shadows are drawn on the forward path only (Unity's deferred path has them in its light
    // pass, which Kiln's does not yet), and not for the frame debugger, which reads every
    // target back at the frame's size.
    if (sampled.shadows != Shadows::kOff && (settings.path == RenderPath::kDeferred || capture)) {
        sampled.shadows = Shadows::kOff;
        stats.warnings.Warning(DiagCode::kRenderWarning, scene.path, kNoPosition,
                               std::string("shadows are off for ") +
                                   (capture ? "the frame debugger" : "the deferred path") +
                                   ": drawn without them");
    }
    if (sampled.shadows != Shadows::kOff && !resources.bounds) {
        resources.bounds = SceneBounds(scene);
    }
    // After planning: the materials for the usage file and what the frame resolved and uploaded.
    auto draw = [&](const render::DrawList& list, auto&& record) -> Status {
        s.NoteMaterials(list);
        stats.materials_resolved = uint32_t(resources.materials.size() - materials);
        const Status drawn = record();
        stats.buffers_uploaded = resources.uploads - uploads;
        return drawn;
    };
    if (settings.path == RenderPath::kDeferred) {
        render::DeferredPlan plan;
        if (Status e = render::PlanDeferred(s.PackList(), scene, settings, camera.position, color,
                                            resources.materials, plan, stats.warnings);
            !e.ok()) {
            return e;
        }
        return draw(plan.list, [&] {
            return DrawDeferred(s, resources, scene, settings, camera, plan, out, stats, step);
        });
    }
    render::ForwardPlan plan;
    if (Status e = render::PlanForward(s.PackList(), scene, sampled, camera.position, color,
                                       resources.materials, plan, stats.warnings);
        !e.ok()) {
        return e;
    }
    return draw(plan.list, [&] {
        return DrawPlan(s, resources, scene, sampled, camera, plan, out, stats, step);
    });
}

Status DrawPlan(Renderer::State& s,
                SceneResources& resources,
                const Scene& scene,
                const FrameSettings& settings,
                const render::CameraSetup& camera,
                const render::ForwardPlan& plan,
                LinearImage& out,
                FrameStats& stats,
                const StepObserver* observer) {
    // The forward path's frame: one pass into the colour target and the depth buffer; with MSAA
    // both have settings.msaa samples per pixel and the colour is resolved (averaged) into a
    // single-sample target at the end of the pass, before the display transform reads it.
    const uint32_t samples = settings.msaa;
    Frame frame;
    frame.width = settings.width;
    frame.height = settings.height;
    DrawBuilder builder(s, resources, scene, render::FrameValues(scene, settings, camera), stats,
                        observer != nullptr);
    // The shadow passes first (their targets after the forward pass's three).
    ShadowFrame shadows;
    const bool shadowed = !plan.shadows.lights.empty();
    FrameTarget color_target{"color", s.color_format, false, {}};
    // Alpha 0: not covered (the frame's alpha is coverage; resolved, the covered fraction).
    color_target.clear.color = {
        {settings.background.r, settings.background.g, settings.background.b, 0}};
    color_target.samples = VkSampleCountFlagBits(samples);
    FrameTarget depth_target{"depth", s.depth_format, true, {}};
    depth_target.clear.depthStencil = {1.0f, 0};
    depth_target.samples = VkSampleCountFlagBits(samples);
    frame.targets = {color_target, depth_target};
    frame.output = 0;
    if (samples > 1) {
        FrameTarget resolved{"color (resolved)", s.color_format, false, {}};
        frame.targets.push_back(resolved);
        frame.output = 2;
    }
    if (shadowed) {
        if (Status e = AddShadowPasses(s, builder, settings, plan.shadows, *resources.bounds, frame,
                                       shadows);
            !e.ok()) {
            return e;
        }
    }
    FramePass forward;
    forward.name = "forward";
    forward.colors = {0};
    forward.depth = 1;
    if (samples > 1) {
        forward.resolves = {2};
    }
    forward.sampled = shadows.sampled;
    // Each receiver binds its light's shadow and reads its values.
    std::vector<render::DrawRequest> shadowed_requests;
    if (shadowed) {
        shadowed_requests = plan.draws;
        for (render::DrawRequest& r : shadowed_requests) {
            if (auto it = shadows.receivers.find(r.light);
                r.light && it != shadows.receivers.end()) {
                r.shadow_map = int(it->second.target);
                r.values = it->second.values;
            }
        }
    }
    if (Status e = BuildForwardPasses(builder, frame, forward, frame.output,
                                      shadowed ? shadowed_requests : plan.draws, stats);
        !e.ok()) {
        return e;
    }
    stats.shadow_draws = shadows.draws;
    stats.objects = plan.objects;
    frame.uniforms = builder.TakeUniforms();
    return RecordFrame(s, frame, out, stats, observer);
}

}  // namespace kiln::runtime
