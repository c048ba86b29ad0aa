// The scene kiln test draws every variant in (kiln/tools/variant_test.h): a unit sphere over a
// plane, one perspective camera, and lights placed at the camera so the sphere's centre faces
// them (the image centre is lit head-on, where a specular highlight is brightest).
#ifndef KILN_TOOLS_HARNESS_SCENE_H_
#define KILN_TOOLS_HARNESS_SCENE_H_

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "kiln/runtime/scene.h"
#include "render/tool_access.h"

namespace kiln::tools {

using runtime::CameraSetup;
using runtime::MaterialInstance;
// Sphere (centre (0, 0.5, 0), radius 0.5) first, then the plane y = 0 (|x|, |z| <= 2); camera 0
// looks at the sphere's centre from kHarnessEye.
inline constexpr glm::vec3 kHarnessSphereCentre{0.0f, 0.5f, 0.0f};
inline constexpr float kHarnessSphereRadius = 0.5f;
inline constexpr float kHarnessPlaneHalf = 2.0f;
inline constexpr glm::vec3 kHarnessEye{0.0f, 0.6f, 2.4f};
runtime::Scene HarnessScene();

// A UV sphere of `segments` x `rings` quads around `centre`, with normals, tangents and UVs.
runtime::Primitive SpherePrimitive(uint32_t segments,
                                   uint32_t rings,
                                   glm::vec3 centre,
                                   float radius);
// A square of side 2 * `half` in the plane y = 0, facing +y.
runtime::Primitive FloorPrimitive(float half);

// A light of `type` at the harness camera, shining along its view; `intensity` in lux (directional)
// or candela (point, spot).
runtime::Light HarnessLight(runtime::LightType type, float intensity);

// kiln stability's scene (kiln/tools/stability.h): a plane in z = 0 facing +z, made of
// triangles around a vertex at the origin, and a sphere beside it; camera 0 at (0, 0,
// kStabilityEyeZ) looks down -z at the origin, so in an odd-sized image the centre pixel sees
// exactly the origin with normal +z (a vertex: its interpolated values are exact). A light
// mirrored through the origin is then exactly opposite the view there (l = -v).
inline constexpr float kStabilityEyeZ = 2.0f;
inline constexpr float kStabilityYFov = 0.9f;
inline constexpr glm::vec3 kStabilitySphereCentre{0.55f, 0.45f, 0.25f};
inline constexpr float kStabilitySphereRadius = 0.25f;
runtime::Scene StabilityScene();

// A harness draw: one pass of `material` with the variant of `keywords` on every object of the
// scene, lit per pixel by lights[0] (unless `pixel_light` is false) and per vertex by lights[1]
// (when `vertex_light`), drawn as one forward frame.
struct HarnessPass {
    const MaterialInstance* material = nullptr;
    uint32_t pass = 0;
    bool additive = false;
    std::vector<std::string> keywords;
    std::vector<runtime::Light> lights;
    bool pixel_light = true, vertex_light = false;
    bool mirrored = false;  // the view mirrors the winding (a cube map face's)
};
// `targets`: every target of the frame read back too.
Status DrawHarnessPass(runtime::Renderer& renderer,
                       const runtime::ColorPipeline& color,
                       const runtime::Scene& scene,
                       const runtime::FrameSettings& settings,
                       const CameraSetup& camera,
                       const HarnessPass& draw,
                       runtime::LinearImage& out,
                       std::vector<runtime::tool_access::TargetValues>* targets = nullptr);

}  // namespace kiln::tools

#endif  // KILN_TOOLS_HARNESS_SCENE_H_
