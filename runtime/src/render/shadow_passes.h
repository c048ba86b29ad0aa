// The shadow passes of a frame (render/shadow_plan.h decides them): per shadowed light its
// map drawn by the objects' ShadowCaster passes (a point light's six cube faces, one pass each);
// with a directional light, the camera's depth drawn by the same passes and one collector pass
// per directional light into a screen-space shadow texture. They come before the passes that
// sample what each receiver's light left: the forward pass, the deferred light pass.
#ifndef KILN_RUNTIME_RENDER_SHADOW_PASSES_H_
#define KILN_RUNTIME_RENDER_SHADOW_PASSES_H_

#include <deque>
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "render/draw_builder.h"
#include "render/frame.h"
#include "render/shadow_plan.h"

namespace kiln::runtime {

// What the receivers of each shadowed light bind: the frame target sampled as
// _ShadowMapTexture and the values their shadow macros read.
struct ShadowFrame {
    struct Receiver {
        uint32_t target = 0;
        const Values* values = nullptr;
    };
    std::map<const Light*, Receiver> receivers;
    std::vector<uint32_t> sampled;               // the targets the receivers' passes sample
    std::deque<LightShadow> shadows;             // the values point into them
    std::deque<DrawRequest> requests;            // the passes' draws, as built
    Values camera_depth;                         // the camera depth pass's values (no bias)
    uint32_t draws = 0;                          // ShadowCaster and collector draws
    std::map<uint32_t, uint32_t> unused_colors;  // size -> target (UnusedColor)
};

// Appends the shadow passes of `plan` (none when no light casts) to `frame`; `bounds`: the
// scene's world bounds, which a shadowed frame needs.
Status AddShadowPasses(Renderer::State& s,
                       DrawBuilder& builder,
                       const FrameSettings& settings,
                       const ShadowPlan& plan,
                       const std::optional<std::pair<glm::vec3, glm::vec3>>& bounds,
                       Frame& frame,
                       ShadowFrame& out);

// `requests` with each receiver of a shadowed light bound to its light's shadow (the target it
// samples as _ShadowMapTexture and the values its shadow macros read).
std::vector<DrawRequest> WithShadows(std::span<const DrawRequest> requests,
                                     const ShadowFrame& shadows);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_SHADOW_PASSES_H_
