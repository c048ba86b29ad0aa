// kiln stability: numerical stability on stiff and extreme inputs (docs/accuracy.md).
//
// TestMaterialStability draws each fragment variant of a material (the variants its keywords
// select, with each light keyword the forward path sets) in a scene made for exact inputs, with
// its values, then each Range() property at its minimum and maximum, under extreme light set-ups:
// the light at the camera (l = v), mirrored behind the surface (l = -v exactly at the centre
// pixel), on the surface (distance 0), 1e-6 and 1e6 away, grazing, with ranges 1e-6 and none,
// spot cones with inner = outer and inner > outer, and intensities 6.6e4, 1e9 and 3.4e38. Every
// pixel of every render must be finite; a finding names the variant, the values, the set-up and
// the first non-finite pixel with the inputs there (n . l, n . v, l . v, distance).
//
// TestTemplateStability (kiln/tools/template_stability.h) evaluates the templates' lighting
// functions on adversarial grids against the CPU reference.
#ifndef KILN_TOOLS_STABILITY_H_
#define KILN_TOOLS_STABILITY_H_

#include <string>
#include <vector>

#include "kiln/result.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"

namespace kiln::tools {

using runtime::ColorPipeline;
using runtime::Renderer;
struct StabilityFinding {
    std::string shader, pass;
    std::vector<std::string> keywords;
    std::string properties;      // "(material)" or "_Smoothness = 0 (Range min)"
    std::string light;           // the set-up
    size_t bad = 0, values = 0;  // non-finite channel values, of all
    uint32_t x = 0, y = 0;       // the first non-finite pixel
    std::string inputs;          // what the pixel sees: "n . l = -1, n . v = 1, l = -v, ..."
};

struct MaterialStabilityReport {
    std::string material, shader;
    size_t variants = 0, renders = 0;
    std::vector<StabilityFinding> findings;
};

struct MaterialStabilityOptions {
    uint32_t size = 33;  // odd: the centre pixel sees the scene's exact point
};

// `material`: a .material file whose shader is in the renderer's packs. An error only when the
// material cannot be used or nothing can be drawn.
Result<MaterialStabilityReport> TestMaterialStability(Renderer& renderer,
                                                      const ColorPipeline& color,
                                                      const std::string& material,
                                                      const MaterialStabilityOptions& options = {});

}  // namespace kiln::tools

#endif  // KILN_TOOLS_STABILITY_H_
