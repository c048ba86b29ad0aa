// A frame as the device records it: a list of passes, each drawing into explicit targets (colour
// attachments and a depth buffer, named, with their formats) that later passes may load or sample.
// Everything is decided on the CPU first (draws with their pipelines, uniform bytes and
// descriptors); RecordFrame then creates the targets, records every pass into one command buffer
// and reads the output target back.
#ifndef KILN_RUNTIME_RENDER_FRAME_H_
#define KILN_RUNTIME_RENDER_FRAME_H_

#include <optional>
#include <string>
#include <vector>

#include "render/renderer_state.h"

namespace kiln::runtime {

struct Draw {
    const vk::Pipeline* pipeline = nullptr;
    const vk::Buffer* vertices = nullptr;
    const vk::Buffer* indices = nullptr;
    uint32_t index_count = 0;
    std::vector<uint8_t> push;
    struct Write {
        uint32_t set, binding;
        VkDescriptorType type;
        VkDeviceSize offset = 0, range = 0;  // uniform buffers: into the frame's buffer
        VkDescriptorImageInfo image{};
    };
    std::vector<Write> writes;
};

// An image of the frame: a colour target or the depth-stencil buffer.
struct FrameTarget {
    std::string name;  // "color", "depth", ...: for messages and the frame debugger
    VkFormat format = VK_FORMAT_UNDEFINED;
    bool depth = false;
    VkClearValue clear{};  // what a pass that clears it writes
};

struct FramePass {
    std::string name;               // "forward", ...
    std::vector<uint32_t> colors;   // indices into Frame::targets, in attachment order
    std::optional<uint32_t> depth;  // index into Frame::targets
    bool clear = true;              // clear the targets first; false: keep what they hold
    std::vector<Draw> draws;
};

struct Frame {
    uint32_t width = 0, height = 0;
    std::vector<FrameTarget> targets;
    std::vector<FramePass> passes;  // recorded in order
    uint32_t output = 0;            // the colour target read back
    std::vector<uint8_t> uniforms;  // every draw's uniform blocks, at their offsets
};

// The formats of a pass's targets: what its pipelines are created against.
vk::TargetFormats FormatsOf(const Frame& frame, const FramePass& pass);

Status RecordFrame(Renderer::State& s, const Frame& frame, LinearImage& out);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_FRAME_H_
