// Planning a frame without a GPU: every variant lookup a render of a scene makes along the
// settings' path, who makes it (material, node, light) and the materials it resolves. It walks the
// same plan as Renderer::Render (the path's requests), so what it records is what a render looks
// up: `kiln render --dry-run` writes
// it as a usage file, `kiln compile --scene` strips a pack by it and `--verify-scene` replays it
// against the stripped pack.
#ifndef KILN_RUNTIME_PLAN_H_
#define KILN_RUNTIME_PLAN_H_

#include <cstdint>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/reader.h"
#include "kiln/pack/variant_selector.h"
#include "kiln/result.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"

namespace kiln::runtime {

struct ScenePlan {
    pack::UsageLog usage;  // every lookup with who asked, and the materials resolved
    // K0012 for each lookup the packs have no variant for (once each, naming who asked).
    DiagnosticList missing;
    uint32_t objects = 0, draws = 0;
};

// Plans one frame of `scene` with `packs` (searched in order, as Renderer::AddPack orders them).
// Errors are those a render would stop at before drawing (a material file that does not
// validate, no pack with Kiln/StandardMetallic for a glTF material, a bad camera); warnings (the
// default light, a shader the path cannot draw) go to `warnings`.
Result<ScenePlan> PlanScene(const std::vector<const pack::Pack*>& packs,
                            const Scene& scene,
                            const FrameSettings& settings,
                            const ColorPipeline& color,
                            DiagnosticList& warnings);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_PLAN_H_
