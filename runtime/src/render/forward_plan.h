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
#include "render/material_binding.h"

namespace kiln::render {

// The passes of a shader the paths draw: of its first SubShader, every ForwardBase, Always or
// untagged pass in order, the first ForwardAdd pass, and the first Deferred pass.
struct ShaderPasses {
    std::vector<uint32_t> base;
    std::optional<uint32_t> add;
    std::optional<uint32_t> deferred;
};
ShaderPasses PassesOf(const pack::Pack& pack, uint32_t shader);

struct DrawRequest {
    const runtime::Instance* instance = nullptr;
    const runtime::Primitive* primitive = nullptr;
    const MaterialInstance* material = nullptr;
    uint32_t pass = 0;
    bool additive = false;
    const runtime::Light* light = nullptr;      // the pass's pixel light (base: the main one)
    std::vector<const runtime::Light*> vertex;  // base passes: up to four vertex lights
    std::vector<const runtime::Light*> sh;      // base passes: lights in the object's SH
    std::vector<std::string> keywords;          // what the draw asks the selector for
    std::string reason;                         // "material on node 'n': point light 'l'"
    glm::vec3 center{0.0f};                     // the object's, where SH lights are projected
};

struct ForwardPlan {
    DrawList list;                   // the requests point into it
    std::vector<DrawRequest> draws;  // in drawing order
    uint32_t objects = 0;            // primitives drawn
};

// The forward requests of one item of `list`, appended to `out`: its base passes, then one
// additive pass per pixel light. False (and a warning, once) when its shader has no pass the
// forward path draws.
bool AddForwardRequests(const std::vector<const pack::Pack*>& packs,
                        const runtime::Scene& scene,
                        const runtime::FrameSettings& settings,
                        const DrawList& list,
                        const DrawItem& item,
                        std::vector<DrawRequest>& out,
                        DiagnosticList& warnings);

// "material on node 'n'" (or on mesh 'm', or on an unnamed node): who a draw is for.
std::string ObjectLabel(const runtime::Scene& scene,
                        const runtime::Instance& instance,
                        const MaterialInstance& material);
// ObjectLabel + ": ", what a request's reason starts with.
std::string Requester(const runtime::Scene& scene, const DrawItem& item);

// "point light 'l'", or "no light".
std::string LightName(const runtime::Light* light);

// Plans a frame: the draw list (materials from `materials`), then its requests. Warnings (the
// default light, a shader the path cannot draw) go to `warnings` once each, against the scene's
// file.
Status PlanForward(const std::vector<const pack::Pack*>& packs,
                   const runtime::Scene& scene,
                   const runtime::FrameSettings& settings,
                   const glm::vec3& camera_position,
                   const runtime::ColorPipeline& color,
                   MaterialCache& materials,
                   ForwardPlan& out,
                   DiagnosticList& warnings);

}  // namespace kiln::render

#endif  // KILN_RUNTIME_RENDER_FORWARD_PLAN_H_
