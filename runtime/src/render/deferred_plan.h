// The deferred path's requests, decided on the CPU without a device, from the same draw list as
// the forward path (render/draw_list.h): each opaque object whose shader has a Deferred pass
// writes the G-buffer; each light of the frame gets one light pass of the internal
// Hidden/Internal-DeferredShading shader (materials/internal/DeferredShading.shader, looked up
// in the loaded packs in order, so a user's pack can replace it); every other object (no Deferred
// pass, or transparent) is drawn afterwards with the forward path's requests. With shadows on,
// the light passes and those forward requests receive them (render/shadow_plan.h), as in Unity's
// deferred path. PlanScene makes the same plan's lookups for stripping (kiln compile --scene
// --path deferred).
#ifndef KILN_RUNTIME_RENDER_DEFERRED_PLAN_H_
#define KILN_RUNTIME_RENDER_DEFERRED_PLAN_H_

#include <optional>
#include <vector>

#include "render/forward_plan.h"

namespace kiln::runtime {

// A draw of the light pass: the whole frame's pixels with geometry (lights without a range), or
// for a ranged light its stencil mask and then the light bounded by it (render/deferred.cpp).
struct LightDraw {
    enum class Role { kWhole, kMask, kBounded };
    DrawRequest request;  // no instance: the full-screen triangle
    Role role = Role::kWhole;
};

struct DeferredPlan {
    DeferredPlan() = default;
    DeferredPlan(const DeferredPlan&) = delete;  // requests point into it
    DeferredPlan& operator=(const DeferredPlan&) = delete;

    DrawList list;
    std::optional<MaterialInstance> light_material;  // the light pass's; when gbuffer is not empty
    std::vector<DrawRequest> gbuffer;  // Deferred passes, opaque objects in scene order
    std::vector<LightDraw> lights;     // per light, one draw or a mask and a bounded draw
    std::vector<DrawRequest> forward;  // the rest, as the forward path draws them
    uint32_t objects = 0;              // primitives drawn by either
    ShadowPlan shadows;                // with settings.shadows on
};

Status PlanDeferred(const std::vector<const pack::Pack*>& packs,
                    const Scene& scene,
                    const FrameSettings& settings,
                    const glm::vec3& camera_position,
                    const ColorPipeline& color,
                    MaterialCache& materials,
                    DeferredPlan& out,
                    DiagnosticList& warnings);
// PlanDeferred after its draw list: the requests of `out.list`, built by the caller.
Status PlanDeferredRequests(const std::vector<const pack::Pack*>& packs,
                            const Scene& scene,
                            const FrameSettings& settings,
                            const ColorPipeline& color,
                            DeferredPlan& out,
                            DiagnosticList& warnings);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_DEFERRED_PLAN_H_
