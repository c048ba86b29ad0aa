// The forward path's draw list, decided on the CPU without a device. For every primitive of every
// instance: its material instance, the shader's ForwardBase (or untagged / Always) passes lit by
// the main directional light with ambient and vertex lights, then one ForwardAdd draw per further
// pixel light; each with the keywords it asks the variant selector for and who asked. Opaque
// objects first, in scene order, then transparent ones back to front. RenderForward draws this
// list; PlanScene (kiln/runtime/plan.h) makes its lookups without drawing, for stripping: both
// read the same list, so a stripped pack holds what a render asks for.
#ifndef KILN_RUNTIME_RENDER_FORWARD_PLAN_H_
#define KILN_RUNTIME_RENDER_FORWARD_PLAN_H_

#include <glm/vec3.hpp>

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/reader.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "render/material_binding.h"

namespace kiln::render {

// The passes of a shader the forward path draws: of its first SubShader, every ForwardBase,
// Always or untagged pass in order, and the first ForwardAdd pass.
struct ShaderPasses {
    std::vector<uint32_t> base;
    std::optional<uint32_t> add;
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
    std::vector<std::string> keywords;          // what the draw asks the selector for
    std::string reason;                         // "material on node 'n': point light 'l'"
};

struct ForwardPlan {
    ForwardPlan() = default;
    ForwardPlan(const ForwardPlan&) = delete;  // requests point into it
    ForwardPlan& operator=(const ForwardPlan&) = delete;

    std::vector<runtime::Light> lights;      // the scene's, or the default light
    std::deque<MaterialInstance> materials;  // each resolved once
    std::vector<DrawRequest> draws;          // in drawing order
    uint32_t objects = 0;                    // primitives drawn
};

// Plans a frame: `camera_position` orders transparent objects. Warnings (the default light, a
// shader the path cannot draw) go to `warnings` once each, against the scene's file.
Status PlanForward(const std::vector<const pack::Pack*>& packs,
                   const runtime::Scene& scene,
                   const runtime::FrameSettings& settings,
                   const glm::vec3& camera_position,
                   const runtime::ColorPipeline& color,
                   ForwardPlan& out,
                   DiagnosticList& warnings);

// Adds a warning against the scene unless the same message is already there.
void WarnOnce(DiagnosticList& warnings,
              const runtime::Scene& scene,
              DiagCode code,
              std::string message);

}  // namespace kiln::render

#endif  // KILN_RUNTIME_RENDER_FORWARD_PLAN_H_
