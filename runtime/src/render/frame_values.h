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

namespace kiln::render {

using Values = std::map<std::string, std::vector<float>, std::less<>>;

struct CameraSetup {
    std::string name;
    glm::mat4 view{1.0f}, projection{1.0f};
    glm::vec3 position{0.0f};
    float znear = 0.05f, zfar = 0;  // 0: infinite
};

Status ChooseCamera(const runtime::Scene& scene,
                    const runtime::FrameSettings& settings,
                    CameraSetup& out);

// UnityPerCamera, UnityPerFrame and UnityProbes (the scene's ambient as constant radiance).
Values FrameValues(const runtime::Scene& scene,
                   const runtime::FrameSettings& settings,
                   const CameraSetup& camera);

// UnityLighting for one pixel light (nullptr: none, colour 0) and up to four vertex lights.
Values LightValues(const runtime::Light* light, const std::vector<const runtime::Light*>& vertex);

// UnityPerDraw.
Values ObjectValues(const glm::mat4& world);

// The lights of one object: the main directional light (brightest directional) for the base
// pass, then the rest by importance (directional lights, then point and spot lights by
// intensity / distance^2 to the object; lights whose range ends before the object are dropped).
struct ObjectLights {
    const runtime::Light* main = nullptr;
    std::vector<const runtime::Light*> pixel;   // additive passes, at most pixel_lights
    std::vector<const runtime::Light*> vertex;  // point lights beyond those, at most 4
};
const runtime::Light* MainLight(const std::vector<runtime::Light>& lights);
ObjectLights LightsFor(const std::vector<runtime::Light>& lights,
                       const runtime::Light* main,
                       const glm::vec3& center,
                       float radius,
                       uint32_t pixel_lights);

float Luminance(const glm::vec3& c);

}  // namespace kiln::render

#endif  // KILN_RUNTIME_RENDER_FRAME_VALUES_H_
