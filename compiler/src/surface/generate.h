// The programs of a surface shader's passes (issue 39), as Unity's surface-shader compiler writes
// them ("Show generated code"): for each planned pass (surface/pass_plan.h) a header (its pragmas,
// the alpha-mode defines, the include files, INTERNAL_DATA and its helper macros) that goes before
// the shader's own code, and a tail after it (the v2f_surf struct with only the interpolators the
// Input struct reads and the pass needs, vert_surf, frag_surf calling the surface function, the
// lighting model's functions and the final-colour functions).
#ifndef KILN_SURFACE_GENERATE_H_
#define KILN_SURFACE_GENERATE_H_

#include <string>
#include <vector>

#include "surface/analysis.h"
#include "surface/pass_plan.h"

namespace kiln::surface {

enum class PassKind { kForwardBase, kForwardAdd, kDeferred, kShadowCaster, kMeta };

PassKind KindOf(const PlannedPass& pass);

struct GeneratedPass {
    PlannedPass plan;
    std::string header;  // HLSL before the shader's code
    std::string tail;    // HLSL after it
};

std::vector<GeneratedPass> GenerateSurfacePasses(const SurfaceShader& shader);

}  // namespace kiln::surface

#endif  // KILN_SURFACE_GENERATE_H_
