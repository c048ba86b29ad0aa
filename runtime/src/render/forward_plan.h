// The forward path's requests, decided on the CPU without a device. For every item of the draw
// list (render/draw_list.h): the shader's ForwardBase (or untagged / Always) passes lit by the
// main directional light with ambient, vertex lights and the rest of the lights in its spherical
// harmonics, then one ForwardAdd draw per further pixel light; each with the keywords it asks the
// variant selector for and who asked. RenderFrame draws these requests; PlanScene
// (kiln/runtime/plan.h) makes their lookups without drawing, for stripping: both read the same
// list, so a stripped pack holds what a render asks for.
#ifndef KILN_RUNTIME_RENDER_FORWARD_PLAN_H_
#define KILN_RUNTIME_RENDER_FORWARD_PLAN_H_

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/reader.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "render/draw_list.h"
#include "render/frame_values.h"
#include "render/material_binding.h"

namespace kiln::runtime {

// The passes of a shader the paths draw: of its first SubShader, every ForwardBase, Always or
// untagged pass in order (GrabPasses among them), the first ForwardAdd pass, and the first
// Deferred pass.
struct ShaderPasses {
    std::vector<uint32_t> base;
    std::optional<uint32_t> add;
    std::optional<uint32_t> deferred;
    std::optional<uint32_t> shadow_caster;  // the first ShadowCaster pass
};
ShaderPasses PassesOf(const pack::Pack& pack, uint32_t shader);

struct DrawRequest {
    const Instance* instance = nullptr;
    const Primitive* primitive = nullptr;
    const MaterialInstance* material = nullptr;
    uint32_t pass = 0;
    bool additive = false;
    const Light* light = nullptr;       // the pass's pixel light (base: the main one)
    std::vector<const Light*> vertex;   // base passes: up to four vertex lights
    std::vector<const Light*> sh;       // base passes: lights in the object's SH
    std::vector<std::string> keywords;  // what the draw asks the selector for
    std::string reason;                 // "material on node 'n': point light 'l'"
    glm::vec3 center{0.0f};             // the object's, where SH lights are projected
    // Set when the frame is built: values read before the frame's (a shadow pass's camera, the
    // shadow a receiver samples), the frame target bound as _ShadowMapTexture (-1: none), and
    // whether the pass's view mirrors the winding (a cube face).
    const Values* values = nullptr;
    int shadow_map = -1;
    bool mirrored_view = false;
    bool depth_only = false;  // colour writes masked off (a shadow pass's unused target)
    // A GrabPass of the object (no draw): the texture the colour drawn so far is copied into,
    // "" for `GrabPass { }` (_GrabTexture, before every object that has one).
    std::optional<std::string> grab;
};

// The shadows of a frame (render/shadow_plan.h).
struct ShadowPlan {
    std::vector<const Light*> lights;  // shadowed, in first-use order
    // The ShadowCaster pass of each opaque object that has one, with SHADOWS_DEPTH (directional
    // and spot maps, the camera's depth) and with SHADOWS_CUBE (point maps).
    std::vector<DrawRequest> casters, cube_casters;
    // The collector, when a directional light casts: its material and request (SHADOWS_SOFT with
    // soft shadows).
    std::optional<MaterialInstance> collector;
    std::optional<DrawRequest> collect;
};

// A request of `item`'s pass `pass` with the material's keywords (no light, reason unset).
DrawRequest ObjectRequest(const DrawItem& item, uint32_t pass);

struct ForwardPlan {
    DrawList list;                   // the requests point into it
    std::vector<DrawRequest> draws;  // in drawing order
    uint32_t objects = 0;            // primitives drawn
    ShadowPlan shadows;              // with settings.shadows on
};

// The forward requests of one item of `list`, appended to `out`: its base passes, then one
// additive pass per pixel light. False (and a warning, once) when its shader has no pass the
// forward path draws.
bool AddForwardRequests(const std::vector<const pack::Pack*>& packs,
                        const Scene& scene,
                        const FrameSettings& settings,
                        const DrawList& list,
                        const DrawItem& item,
                        std::vector<DrawRequest>& out,
                        DiagnosticList& warnings);

// The requests among the forward path's `requests` that receive their light's shadow: base
// passes lit by the main directional light, and additive passes.
std::vector<DrawRequest*> ForwardReceivers(std::vector<DrawRequest>& requests);

// "material on node 'n'" (or on mesh 'm', or on an unnamed node): who a draw is for.
std::string ObjectLabel(const Scene& scene,
                        const Instance& instance,
                        const MaterialInstance& material);
// ObjectLabel + ": ", what a request's reason starts with.
std::string Requester(const Scene& scene, const DrawItem& item);

// "point light 'l'", or "no light".
std::string LightName(const Light* light);

// Plans a frame: the draw list (materials from `materials`), then its requests. Warnings (the
// default light, a shader the path cannot draw) go to `warnings` once each, against the scene's
// file.
Status PlanForward(const std::vector<const pack::Pack*>& packs,
                   const Scene& scene,
                   const FrameSettings& settings,
                   const glm::vec3& camera_position,
                   const ColorPipeline& color,
                   MaterialCache& materials,
                   ForwardPlan& out,
                   DiagnosticList& warnings);
// PlanForward after its draw list: the requests of `out.list`, built by the caller (kiln test
// builds its own, one material on every object).
Status PlanForwardRequests(const std::vector<const pack::Pack*>& packs,
                           const Scene& scene,
                           const FrameSettings& settings,
                           const ColorPipeline& color,
                           ForwardPlan& out,
                           DiagnosticList& warnings);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_FORWARD_PLAN_H_
