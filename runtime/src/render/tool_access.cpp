#include "render/tool_access.h"

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

Status DrawForwardPlan(Renderer& renderer,
                       const ColorPipeline& color,
                       const Scene& scene,
                       const FrameSettings& settings,
                       const CameraSetup& camera,
                       const ForwardPlan& plan,
                       LinearImage& out) {
    Renderer::State& s = renderer.internal_state();
    FrameStats stats;
    return DrawPlan(s, s.ResourcesFor(scene, color), scene, settings, camera, plan, out, stats);
}

}  // namespace kiln::runtime::tool_access
