// Render passes for a frame's passes (render/frame.h): one subpass over the pass's colour targets
// and depth buffer, cleared or loaded. Targets stay in their attachment layouts between passes;
// the dependencies order each pass after the previous one's writes and before the next reads
// (attachments, sampling or the read-back copy).
#ifndef KILN_RUNTIME_VK_RENDER_PASS_H_
#define KILN_RUNTIME_VK_RENDER_PASS_H_

#include <compare>
#include <vector>

#include "vk/context.h"

namespace kiln::vk {

// The formats of a pass's targets: pipelines are created against them (a pipeline works in any
// render pass with the same formats, whatever its load operations).
struct TargetFormats {
    std::vector<VkFormat> colors;
    VkFormat depth = VK_FORMAT_UNDEFINED;  // none
    // Samples per pixel of every attachment (MSAA); with `resolve`, each colour attachment is
    // resolved into a single-sample one of its format at the end of the pass.
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool resolve = false;

    auto operator<=>(const TargetFormats&) const = default;
};

// `clear`: the targets start undefined and are cleared; else they are loaded in their attachment
// layouts (a previous pass of the frame wrote them). `depth_read_only`: the depth buffer is loaded
// and stays in DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL, so the pass may sample its depth while
// it depth-tests against it; its stencil is cleared and writable (the deferred light pass's
// masks). Resolve attachments follow the depth attachment (or the colours), one per colour,
// undefined at the start and left in COLOR_ATTACHMENT_OPTIMAL.
Status CreateRenderPass(const Context& c,
                        const TargetFormats& formats,
                        bool clear,
                        bool depth_read_only,
                        VkRenderPass& out);

}  // namespace kiln::vk

#endif  // KILN_RUNTIME_VK_RENDER_PASS_H_
