// The draw list every render path starts from, decided on the CPU without a device: the frame's
// lights (the scene's, or the default light), and for every primitive of every instance its
// material instance and world bounds; opaque objects first, in scene order, then transparent
// ones back to front. The forward planner (render/forward_plan.h) turns it into passes; the
// deferred path reads the same list.
#ifndef KILN_RUNTIME_RENDER_DRAW_LIST_H_
#define KILN_RUNTIME_RENDER_DRAW_LIST_H_

#include <glm/vec3.hpp>

#include <deque>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/reader.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "render/material_binding.h"

namespace kiln::runtime {

// Material instances of one scene, each resolved once: a sidecar .material, else the glTF
// material on Kiln/StandardMetallic. Kept with the scene's device resources while the renderer
// draws the same scene (runtime::Scene::id), so .material files are read once, not per frame.
class MaterialCache {
  public:
    // The instance for glTF material `index` of `scene` (-1: glTF's default material).
    Status For(const std::vector<const pack::Pack*>& packs,
               const Scene& scene,
               const ColorPipeline& color,
               int index,
               const MaterialInstance*& out);
    size_t size() const { return store_.size(); }  // instances resolved so far

  private:
    std::deque<MaterialInstance> store_;          // handed out by pointer
    std::vector<const MaterialInstance*> slots_;  // per glTF material, then the default
};

struct DrawItem {
    const Instance* instance = nullptr;
    const Primitive* primitive = nullptr;
    const MaterialInstance* material = nullptr;
    glm::vec3 center{0.0f};  // of the world-space box around the transformed local bounds
    float radius = 0;        // half the box's diagonal
    float depth = 0;         // centre's distance from the camera
};

struct DrawList {
    DrawList() = default;
    DrawList(const DrawList&) = delete;  // items and the main light point into it
    DrawList& operator=(const DrawList&) = delete;

    std::vector<Light> lights;                       // the scene's, or the default light
    const Light* main = nullptr;                     // the brightest directional light
    std::vector<DrawItem> items;                     // opaque in scene order, then transparent
    std::vector<const MaterialInstance*> materials;  // distinct, in first-use order
};

// World-space box of `primitive` under `world` (the eight corners of its local bounds; the
// vertices when the bounds are unset): (centre, radius).
std::pair<glm::vec3, float> WorldSphere(const Primitive& primitive, const glm::mat4& world);

// Builds the list: `camera_position` orders transparent objects. The default light's warning
// goes to `warnings` once, against the scene's file.
Status BuildDrawList(const std::vector<const pack::Pack*>& packs,
                     const Scene& scene,
                     const FrameSettings& settings,
                     const glm::vec3& camera_position,
                     const ColorPipeline& color,
                     MaterialCache& materials,
                     DrawList& out,
                     DiagnosticList& warnings);

// Adds a warning against the scene unless the same message is already there.
void WarnOnce(DiagnosticList& warnings, const Scene& scene, DiagCode code, std::string message);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_DRAW_LIST_H_
