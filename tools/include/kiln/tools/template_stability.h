// kiln stability without --material (docs/accuracy.md): the templates' lighting functions on
// adversarial input grids, evaluated on the device through the library's own HLSL
// (templates/stability/KilnStabilityGrid.shader, one grid point per pixel, fp32 target) and
// compared with the CPU double-precision reference (kiln/reference): non-finite values, the
// largest absolute and relative error and the ULP distance, each case against its documented
// bound; and the white-furnace directional albedo of each BRDF lobe by CPU integration.
#ifndef KILN_TOOLS_TEMPLATE_STABILITY_H_
#define KILN_TOOLS_TEMPLATE_STABILITY_H_

#include <cstdint>
#include <string>
#include <vector>

#include "kiln/pack/format.h"
#include "kiln/result.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"

namespace kiln::tools {

using runtime::ColorPipeline;
using runtime::Renderer;
struct GridCaseReport {
    std::string name;               // "BRDF1_Unity_PBS"
    std::string functions;          // what each channel holds
    std::vector<std::string> axes;  // "n . v {-1, 0, 1e-07, 1}"
    size_t points = 0, values = 0;  // grid points; channel values compared
    size_t non_finite = 0;          // NaN or infinity on the device
    std::string first_non_finite;   // its inputs and channel
    double max_abs = 0;             // largest |device - reference|
    // Largest |device - reference| / max(|reference|, 1e-3): relative where the value is not
    // tiny, absolute below 1e-3 (a colour contribution under 1e-3 is invisible).
    double max_rel = 0;
    uint64_t max_ulp = 0;  // largest distance in fp32 units to the rounded reference
    std::string worst;     // the inputs, channel and both values at max_rel
    double bound = 0;      // max_rel allowed (docs/accuracy.md says why)
    bool ok() const { return non_finite == 0 && max_rel <= bound; }
};

struct EnergyReport {
    std::string brdf;
    double max_albedo = 0;  // over the n . v and roughness grid
    std::string where;      // its inputs
    bool ok() const { return max_albedo <= 1.0 + 1e-3; }
};

struct TemplateStabilityReport {
    std::vector<GridCaseReport> cases;
    std::vector<EnergyReport> energy;
};

struct TemplateStabilityOptions {
    // How the harness pack was compiled: a case evaluated in binary16 there is held to its
    // binary16 bound (docs/accuracy.md, "fp16").
    pack::Precision precision = pack::Precision::kFull;
};

// Needs a pack holding pack::kShaderStabilityGrid among the renderer's packs.
Result<TemplateStabilityReport> TestTemplateStability(Renderer& renderer,
                                                      const ColorPipeline& color,
                                                      const TemplateStabilityOptions& options = {});

// The white-furnace part alone (CPU only).
std::vector<EnergyReport> WhiteFurnaceReport();

}  // namespace kiln::tools

#endif  // KILN_TOOLS_TEMPLATE_STABILITY_H_
