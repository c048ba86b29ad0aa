// Which passes a surface shader's directive gives, as Unity's surface-shader compiler generates
// them (Unity manual, "Surface Shaders and rendering paths" and the optional directives): each
// pass's Name, LightMode, render state and variant pragmas, before its program is generated
// (issue 39). Kiln differs from Unity in two places, on purpose:
// - the additive pass is named FORWARD_DELTA (Unity names both forward passes FORWARD; Kiln's
//   pass identity, the usage file and --scene stripping need one name per pass, and Unity's own
//   Standard.shader uses these names);
// - no legacy-deferred (PrepassBase/PrepassFinal) passes: Kiln's runtime has no light pre-pass
//   path, and Unity 2019 and later dropped the built-in models' _PrePass forms.
#ifndef KILN_SURFACE_PASS_PLAN_H_
#define KILN_SURFACE_PASS_PLAN_H_

#include <string>
#include <vector>

#include "surface/directive.h"
#include "surface/lighting_model.h"

namespace kiln::surface {

struct PlannedPass {
    std::string name;                // FORWARD, FORWARD_DELTA, DEFERRED, ShadowCaster, Meta
    std::string light_mode;          // ForwardBase, ForwardAdd, Deferred, ShadowCaster, Meta
    std::string pass_define;         // UNITY_PASS_FORWARDBASE, ...
    std::vector<std::string> state;  // ShaderLab render-state lines: "ZWrite Off", "Blend One One"
    std::vector<std::string> pragmas;  // `#pragma` lines without "#pragma ": "multi_compile_fog"
};

// The alpha mode `alpha` (auto) means for this lighting model: fade for the simple models,
// premultiplied for the physically based ones.
AlphaMode EffectiveAlpha(const SurfaceDirective& d);

// The passes, in Unity's order: forward base, forward add, deferred, shadow caster, meta.
// Whether the surface blends over what is there (an alpha mode or a decal): no depth writes, no
// G-buffer pass (but decal:add's), the fwdbasealpha shortcut, no UNITY_OPAQUE_ALPHA.
bool Blended(const SurfaceDirective& d);

std::vector<PlannedPass> PlanSurfacePasses(const SurfaceDirective& d, const LightingModel& model);

}  // namespace kiln::surface

#endif  // KILN_SURFACE_PASS_PLAN_H_
