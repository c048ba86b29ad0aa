// The shadow passes of a forward frame (render/shadow_plan.h decides them): per shadowed light its
// map drawn by the objects' ShadowCaster passes (a point light's six cube faces, one pass each);
// with a directional light, the camera's depth drawn by the same passes and one collector pass
// per directional light into a screen-space shadow texture. They come before the forward pass,
// which samples what each receiver's light left.
#ifndef KILN_RUNTIME_RENDER_SHADOW_PASSES_H_
#define KILN_RUNTIME_RENDER_SHADOW_PASSES_H_

#include <deque>
#include <map>

#include "render/draw_builder.h"
#include "render/frame.h"
#include "render/shadow_plan.h"

namespace kiln::runtime {

// What the forward pass's receivers of each shadowed light bind: the frame target sampled as
// _ShadowMapTexture and the values their shadow macros read.
struct ShadowFrame {
    struct Receiver {
        uint32_t target = 0;
        const render::Values* values = nullptr;
    };
    std::map<const Light*, Receiver> receivers;
    std::vector<uint32_t> sampled;               // the targets the forward pass samples
    std::deque<render::LightShadow> shadows;     // the values point into them
    std::deque<render::DrawRequest> requests;    // the passes' draws, as built
    render::Values camera_depth;                 // the camera depth pass's values (no bias)
    uint32_t draws = 0;                          // ShadowCaster and collector draws
    std::map<uint32_t, uint32_t> unused_colors;  // size -> target (UnusedColor)
};

// Appends the shadow passes of `plan` to `frame`; `bounds`: the scene's world bounds.
Status AddShadowPasses(Renderer::State& s,
                       DrawBuilder& builder,
                       const FrameSettings& settings,
                       const render::ShadowPlan& plan,
                       const std::pair<glm::vec3, glm::vec3>& bounds,
                       Frame& frame,
                       ShadowFrame& out);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_SHADOW_PASSES_H_
