// A planned draw: everything the command buffer needs, decided before recording. RecordFrame
// renders a list of them into the colour target and reads the result back.
#ifndef KILN_RUNTIME_RENDER_DRAW_H_
#define KILN_RUNTIME_RENDER_DRAW_H_

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

Status RecordFrame(Renderer::State& s,
                   const FrameSettings& settings,
                   const std::vector<Draw>& draws,
                   const std::vector<uint8_t>& uniforms,
                   LinearImage& out);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_DRAW_H_
