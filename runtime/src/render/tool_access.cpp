#include "render/tool_access.h"

#include <algorithm>
#include <tuple>

#include "render/frame_internal.h"
#include "render/render_path.h"
#include "render/renderer_state.h"

namespace kiln::runtime::tool_access {

std::vector<const pack::Pack*> Packs(const Renderer& renderer) {
    std::vector<const pack::Pack*> out;
    for (size_t i = 0; i < renderer.pack_count(); ++i) {
        out.push_back(&renderer.pack(i));
    }
    return out;
}

const std::string& PackPath(const Renderer& renderer, size_t index) {
    return renderer.internal_state().packs.at(index)->path;
}

void HarnessDrawList(const Scene& scene,
                     const MaterialInstance& material,
                     std::vector<Light> lights,
                     DrawList& out) {
    out.lights = std::move(lights);
    out.main = MainLight(out.lights);  // as BuildDrawList chooses it
    out.items.clear();
    for (const Instance& inst : scene.instances) {
        const Primitive& prim = scene.meshes[inst.mesh].primitives[0];
        DrawItem& item = out.items.emplace_back();
        item.instance = &inst;
        item.primitive = &prim;
        item.material = &material;
        std::tie(item.center, item.radius) = WorldSphere(prim, inst.world);
    }
    out.materials = {&material};
}

namespace {

// Keeps the last read-back of every target (and cube face) a frame wrote, decoded.
StepObserver KeepTargets(std::vector<TargetValues>& out) {
    return [&out](const Frame& frame, size_t, int, std::vector<CapturedTarget> targets,
                  double) -> Status {
        for (CapturedTarget& ct : targets) {
            const FrameTarget& t = frame.targets[ct.target];
            auto it = std::find_if(out.begin(), out.end(), [&](const TargetValues& v) {
                return v.name == t.name && v.layer == ct.layer;
            });
            TargetValues& v = it != out.end() ? *it : out.emplace_back();
            v.name = t.name;
            v.layer = ct.layer;
            v.width = ct.width;
            v.height = ct.height;
            v.depth = t.depth;
            v.channels = DecodedChannels(t);
            v.values = DecodeTexels(t, ct.bytes);
        }
        return {};
    };
}

Status Draw(Renderer& renderer,
            const ColorPipeline& color,
            const Scene& scene,
            const FrameSettings& settings,
            const CameraSetup& camera,
            const PathPlan& plan,
            LinearImage& out,
            std::vector<TargetValues>* targets) {
    Renderer::State& s = renderer.internal_state();
    SceneResources& resources = s.ResourcesFor(scene, color);
    if (!resources.bounds) {  // a shadowed frame's maps are fitted to them
        resources.bounds = SceneBounds(scene);
    }
    FrameStats stats;
    if (!targets) {
        return DrawPlan(s, resources, scene, settings, camera, plan, out, stats);
    }
    targets->clear();
    const StepObserver keep = KeepTargets(*targets);
    return DrawPlan(s, resources, scene, settings, camera, plan, out, stats, &keep);
}

}  // namespace

Status DrawForwardPlan(Renderer& renderer,
                       const ColorPipeline& color,
                       const Scene& scene,
                       const FrameSettings& settings,
                       const CameraSetup& camera,
                       const ForwardPlan& plan,
                       LinearImage& out,
                       std::vector<TargetValues>* targets) {
    return Draw(renderer, color, scene, settings, camera, *ViewForwardPlan(plan), out, targets);
}

Status DrawDeferredPlan(Renderer& renderer,
                        const ColorPipeline& color,
                        const Scene& scene,
                        const FrameSettings& settings,
                        const CameraSetup& camera,
                        const DeferredPlan& plan,
                        LinearImage& out,
                        std::vector<TargetValues>* targets) {
    return Draw(renderer, color, scene, settings, camera, *ViewDeferredPlan(plan), out, targets);
}

}  // namespace kiln::runtime::tool_access
