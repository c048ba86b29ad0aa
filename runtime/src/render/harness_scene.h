// The scene kiln test draws every variant in (kiln/runtime/variant_test.h): a unit sphere over a
// plane, one perspective camera, and lights placed at the camera so the sphere's centre faces
// them (the image centre is lit head-on, where a specular highlight is brightest).
#ifndef KILN_RUNTIME_RENDER_HARNESS_SCENE_H_
#define KILN_RUNTIME_RENDER_HARNESS_SCENE_H_

#include "kiln/runtime/scene.h"

namespace kiln::render {

// Sphere (centre (0, 0.5, 0), radius 0.5) first, then the plane y = 0; camera 0 looks at the
// sphere's centre from +Z.
runtime::Scene HarnessScene();

// A light of `type` at the harness camera, shining along its view; `intensity` in lux (directional)
// or candela (point, spot).
runtime::Light HarnessLight(runtime::LightType type, float intensity);

}  // namespace kiln::render

#endif  // KILN_RUNTIME_RENDER_HARNESS_SCENE_H_
