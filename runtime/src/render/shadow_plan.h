// Shadows of either path (docs/runtime.md, "Shadows"), decided on the CPU: which lights cast,
// the objects' ShadowCaster requests, each light's shadow projection and the values its casters
// and receivers read. Unity's built-in pipeline is the model:
//   directional  an orthographic map around the scene, collected into a screen-space texture
//                (Hidden/Internal-ScreenSpaceShadows) from the camera's depth, which the
//                ShadowCaster passes also draw; receivers ask for SHADOWS_SCREEN;
//   spot         a perspective map along the cone (SHADOWS_DEPTH, unity_WorldToShadow[0]);
//   point        a depth cube, one perspective face each (SHADOWS_CUBE, _LightProjectionParams);
// with SHADOWS_SOFT filtering spot and point shadows (the collector's own SHADOWS_SOFT variant for
// directional ones).
#ifndef KILN_RUNTIME_RENDER_SHADOW_PLAN_H_
#define KILN_RUNTIME_RENDER_SHADOW_PLAN_H_

#include <glm/mat4x4.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/forward_plan.h"
#include "render/frame_values.h"

namespace kiln::runtime {

// One light's shadow: its map's view-projections (one, or six cube faces +X, -X, +Y, -Y, +Z, -Z),
// the values its ShadowCaster draws read per face, and those its receivers read.
struct LightShadow {
    const Light* light = nullptr;
    std::vector<glm::mat4> view_projection;
    std::vector<Values> caster;  // per face: unity_MatrixVP, unity_LightShadowBias
    Values receiver;  // unity_WorldToShadow, _LightShadowData, _LightProjectionParams, texel size
    float depth_bias = 0;  // world units, at the scene (what the normal and depth biases move)
};

// The shadow of `light` over a scene within `bounds` (world min, max) in a `resolution`^2 map:
// directional lights fit the bounds' sphere; spot lights their cone, point lights a cube, both
// as far as the light's range or the bounds' farthest corner.
LightShadow ShadowOf(const Light& light,
                     const std::pair<glm::vec3, glm::vec3>& bounds,
                     uint32_t resolution);

// The side of `light`'s map in texels: settings.shadow_resolution (16 to 8192); a point light's
// cube faces half that (a quarter of the texels each), as Unity sizes them: 1.5 times a 2D map's
// memory instead of 6.
uint32_t ShadowMapSize(const FrameSettings& settings, const Light& light);

// The keyword a receiver of `light`'s shadow asks for.
const char* ReceiverKeyword(const Light& light);

// Plans the shadows of a frame whose requests `receivers` are lit by a pixel light (each with
// its light; the path chooses them: the forward path's base passes lit by the main directional
// light and its additive passes, the deferred path's light passes): adds the shadow keywords to
// each receiver and plans the casters of `list` and the collector. A scene without a
// ShadowCaster pass casts nothing: a warning, once, and no shadow keywords.
Status PlanShadows(const std::vector<const pack::Pack*>& packs,
                   const Scene& scene,
                   const FrameSettings& settings,
                   const ColorPipeline& color,
                   const DrawList& list,
                   const std::vector<DrawRequest*>& receivers,
                   ShadowPlan& out,
                   DiagnosticList& warnings);

// The shadow passes' requests of `plan` (the casters, the collector), appended to `out`.
void ShadowRequests(const ShadowPlan& plan, std::vector<const DrawRequest*>& out);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_SHADOW_PLAN_H_
