// What the forward path computes from the scene before drawing: the camera, the built-in
// shader variables (docs/shader-library.md: UnityPerCamera, UnityPerFrame, UnityLighting,
// UnityProbes, UnityPerDraw) and which lights light an object, in what order.
#ifndef KILN_RUNTIME_RENDER_FRAME_VALUES_H_
#define KILN_RUNTIME_RENDER_FRAME_VALUES_H_

#include <glm/mat4x4.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"

namespace kiln::runtime {

using Values = std::map<std::string, std::vector<float>, std::less<>>;

struct CameraSetup {
    std::string name;
    glm::mat4 view{1.0f}, projection{1.0f};
    glm::vec3 position{0.0f};
    float znear = 0.05f, zfar = 0;  // 0: infinite
};

// `bounds`: the scene's world bounds when the caller keeps them (runtime::SceneBounds otherwise,
// computed only when the automatic camera needs them).
Status ChooseCamera(const Scene& scene,
                    const FrameSettings& settings,
                    CameraSetup& out,
                    const std::pair<glm::vec3, glm::vec3>* bounds = nullptr);

// UnityPerCamera, UnityPerFrame and UnityProbes (the scene's ambient as constant radiance).
Values FrameValues(const Scene& scene, const FrameSettings& settings, const CameraSetup& camera);

// UnityLighting for one pixel light (nullptr: none, colour 0) and up to four vertex lights.
Values LightValues(const Light* light, const std::vector<const Light*>& vertex);

// UnityPerDraw, and Unity 2018's transposed model-view matrix (`view`: the camera's).
Values ObjectValues(const glm::mat4& world, const glm::mat4& view);

// The light probe unity_SH* of an object at `center`: the scene's ambient (flat: a constant sky
// of that radiance, so ShadeSH9 returns it; trilight: the gradient's projection) plus each of
// `lights` projected as a distant light from its direction at the centre, with its illuminance
// there (distance attenuation and spot cone as the pixel path computes them), as Unity projects the
// lights it does not draw per pixel or per vertex.
Values ProbeValues(const Scene& scene,
                   const std::vector<const Light*>& lights,
                   const glm::vec3& center);

// The scene's ambient radiance averaged over the sphere (unity_IndirectSpecColor).
glm::vec3 MeanAmbient(const Scene& scene);

// The scene's sky when its ambient is one (AmbientMode::kSky with a sky set), else null: a kSky
// scene without a sky falls back to the flat `ambient`.
const Sky* SkyOf(const Scene& scene);

// The light's illuminance (lux, times its colour) at `point`, on a surface facing it, and the unit
// direction from `point` towards it.
std::pair<glm::vec3, glm::vec3> IlluminanceAt(const Light& light, const glm::vec3& point);

// The lights of one object: the main directional light (brightest directional) for the base
// pass, then the rest by importance (directional lights, then point and spot lights by
// intensity / distance^2 to the object; lights whose range ends before the object are dropped).
// The first `pixel_lights` are per-pixel, up to four point lights after them per-vertex, and
// all the others go into the object's spherical harmonics, as Unity's forward path does.
struct ObjectLights {
    const Light* main = nullptr;
    std::vector<const Light*> pixel;   // additive passes, at most pixel_lights
    std::vector<const Light*> vertex;  // point lights beyond those, at most 4
    std::vector<const Light*> sh;      // the rest
};
const Light* MainLight(const std::vector<Light>& lights);
ObjectLights LightsFor(const std::vector<Light>& lights,
                       const Light* main,
                       const glm::vec3& center,
                       float radius,
                       uint32_t pixel_lights,
                       LightMode mode = LightMode::kAuto);

float Luminance(const glm::vec3& c);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_FRAME_VALUES_H_
