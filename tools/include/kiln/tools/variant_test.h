// kiln test: every variant of every pass of the loaded packs (or a seeded sample) drawn by the
// Vulkan runtime in one standard harness, with checks a broken variant fails (docs/variants.md,
// "Test"). The harness is a sphere over a plane seen by one camera. A forward pass is lit by a
// light of the type its keywords name (ForwardAdd: DIRECTIONAL, POINT or SPOT; base passes: the
// main directional light, plus a point light as a vertex light for VERTEXLIGHT_ON), placed at the
// camera so the sphere's centre faces it, and drawn with its shader's Properties at their
// defaults, then each Range() property at its minimum and at its maximum. The other passes are
// drawn in the frames the runtime's paths draw them in (harness/pass_test.h): ShadowCaster into
// a spot light's map or a point light's cube, Deferred into the G-buffer and lit, the internal
// light pass and shadow collector in frames of a reference shader. The checks:
//   pipeline   the variant's pipeline is created and drawn (SPIR-V, layout, render state)
//   validation the Vulkan validation layer reports nothing while it is drawn
//   finite     every output pixel and every value of every target of the frame is finite
//   lit        a lit variant is not black where its light faces the surface
//   additive   an additive pass (ForwardAdd) only adds to what was drawn before it: over a grey
//              background no channel of any pixel falls below the background
//   no-light   with its light at intensity 0 a variant draws exactly what it draws with no light
//              (within 1e-5 in linear fp32: both renders run the same SPIR-V, and the light's
//              contribution is multiplied by zero)
//   coverage   a shadow map covers exactly what the light sees of the scene (harness/
//   depth      shadow_map_check.h), and its depths unproject onto the surfaces
//   normal     the G-buffer's normals decode to unit vectors facing the camera
//   shadow     a shadowed light pass only darkens, and darkens where the sphere's shadow falls;
//              screen-space shadows hold that shadow
//   drawn      the frame drew the pass
#ifndef KILN_TOOLS_VARIANT_TEST_H_
#define KILN_TOOLS_VARIANT_TEST_H_

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kiln/result.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"

namespace kiln::tools {

using runtime::ColorPipeline;
using runtime::LinearImage;
using runtime::Renderer;
struct VariantTestOptions {
    uint32_t size = 64;              // the square image's side in pixels
    std::optional<uint32_t> sample;  // test this many variants, chosen with `seed`; all if unset
    uint64_t seed = 1;
    std::vector<std::string> shaders;  // only these shaders (by name); all if empty
};

struct VariantTestFailure {
    std::string pack, shader, pass;
    std::vector<std::string> keywords;
    // The property values of the failing render: "(defaults)", or "_Exponent = 0 (Range min)".
    std::string properties;
    std::string check;    // "pipeline", "validation", "finite", "lit", ... (above)
    std::string message;  // what was seen
    LinearImage image;    // the failing render (empty when nothing was drawn)
};

struct VariantTestReport {
    size_t variants = 0, renders = 0;  // variants tested, renders drawn
    std::vector<VariantTestFailure> failures;
    // Variants not tested, one line per pass and reason with its variant count (a LightMode no
    // path draws, a light pass's keyword combination no frame asks for, a Deferred pass with no
    // light pass loaded); `skipped_variants` in all, so that variants + skipped_variants is every
    // variant of the packs (of --shader's shaders).
    std::vector<std::string> skipped;
    size_t skipped_variants = 0;
};

// Runs the harness over every pack `renderer` holds. An error only when the harness itself
// cannot run (no pack, no device); a failing variant is a failure in the report.
Result<VariantTestReport> TestVariants(Renderer& renderer,
                                       const ColorPipeline& color,
                                       const VariantTestOptions& options);

}  // namespace kiln::tools

#endif  // KILN_TOOLS_VARIANT_TEST_H_
