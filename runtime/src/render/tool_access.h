// What Kiln's own tools may use of the runtime's internals, in one header (kiln_tools: the
// `kiln test` harness and `kiln stability`, which draw one material on every object of their own
// scenes): material instances they can change, the camera, the paths' planners run on their own
// draw lists, and the frames of plans they built and changed, with every target read back. Nothing
// else of runtime/src is theirs to include (tests/source/ layering_test.py checks), and an engine
// has no use for any of it: never installed.
#ifndef KILN_RUNTIME_RENDER_TOOL_ACCESS_H_
#define KILN_RUNTIME_RENDER_TOOL_ACCESS_H_

#include <string>
#include <vector>

#include "kiln/runtime/color.h"
#include "kiln/runtime/image.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "render/deferred_plan.h"     // DeferredPlan, PlanDeferredRequests
#include "render/forward_plan.h"      // ForwardPlan, DrawRequest, PlanForwardRequests
#include "render/frame_values.h"      // CameraSetup, ChooseCamera
#include "render/material_binding.h"  // MaterialInstance, InstanceFromDefaults / MaterialFile
#include "render/shadow_plan.h"       // ShadowOf, ShadowMapSize

namespace kiln::runtime::tool_access {

// The renderer's packs in the order shaders are looked up in, and the file each was mapped from.
std::vector<const pack::Pack*> Packs(const Renderer& renderer);
const std::string& PackPath(const Renderer& renderer, size_t index);

// A draw list of `material` on the first primitive of every instance of `scene`, lit by
// `lights` (the main light: the brightest directional one, MainLight), for a path's planner
// (PlanForwardRequests, PlanDeferredRequests) to plan from.
void HarnessDrawList(const Scene& scene,
                     const MaterialInstance& material,
                     std::vector<Light> lights,
                     DrawList& out);

// A target of a drawn frame as the frame's last step left it (a cube's faces one each), decoded
// to what a shader reads (render/frame_internal.h, DecodeTexels): `channels` floats per texel,
// rows top first.
struct TargetValues {
    std::string name;  // the frame's name for it: "shadow map: spot light 'l'", "gbuffer2 (normal)"
    uint32_t layer = 0;
    uint32_t width = 0, height = 0, channels = 0;
    bool depth = false;
    std::vector<float> values;
};

// Draws `plan`'s requests as its path draws its frame (its materials' resources uploaded with
// the scene's), into `out`; with `targets`, every target the frame wrote is read back into it
// too (the frame recorded step by step, as the frame debugger records it).
Status DrawForwardPlan(Renderer& renderer,
                       const ColorPipeline& color,
                       const Scene& scene,
                       const FrameSettings& settings,
                       const CameraSetup& camera,
                       const ForwardPlan& plan,
                       LinearImage& out,
                       std::vector<TargetValues>* targets = nullptr);
Status DrawDeferredPlan(Renderer& renderer,
                        const ColorPipeline& color,
                        const Scene& scene,
                        const FrameSettings& settings,
                        const CameraSetup& camera,
                        const DeferredPlan& plan,
                        LinearImage& out,
                        std::vector<TargetValues>* targets = nullptr);

}  // namespace kiln::runtime::tool_access

#endif  // KILN_RUNTIME_RENDER_TOOL_ACCESS_H_
