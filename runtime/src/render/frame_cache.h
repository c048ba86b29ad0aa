// The device objects frames reuse (docs/runtime.md, "Frame resources"), so that a frame of a
// size and path drawn before creates no Vulkan object:
//   per frame shape (its targets' formats, sizes and samples, and its passes' attachments: the
//   same for every frame of one path at one size), the targets with their views and
//   framebuffers, the uniform buffer and the descriptor pool, which grow to the largest frame of
//   the shape and are reset, not recreated; the last kShapes shapes are kept, the least recently
//   used given back first (kiln report interleaves its configurations);
//   one command buffer and fence, the timestamp queries and the read-back buffer, which grow to
//   the largest frame.
// Frames are drawn one at a time and waited for, so a frame's objects are free when the next
// begins. The frame debugger's step-by-step recording makes its own (render/frame_capture.cpp).
#ifndef KILN_RUNTIME_RENDER_FRAME_CACHE_H_
#define KILN_RUNTIME_RENDER_FRAME_CACHE_H_

#include <list>
#include <memory>

#include "render/frame_internal.h"
#include "vk/timestamps.h"

namespace kiln::runtime {

class FrameCache {
  public:
    static constexpr size_t kShapes = 4;

    explicit FrameCache(const vk::Context& c) : c_(c) {}
    ~FrameCache();
    FrameCache(const FrameCache&) = delete;
    FrameCache& operator=(const FrameCache&) = delete;

    // The objects of `frame`'s shape (made on its first frame), its uniforms written and every
    // draw's descriptor sets written. `allocations` counts the Vulkan objects made.
    Status Prepare(Renderer::State& s,
                   const Frame& frame,
                   FrameObjects*& out,
                   uint32_t& allocations);
    // The command buffer, reset and begun.
    Status Begin(VkCommandBuffer& out, uint32_t& allocations);
    // Ends, submits and waits for the command buffer Begin gave.
    Status SubmitAndWait(VkCommandBuffer cmd, uint32_t& allocations);
    // Timestamp queries for `marks` marks, reset in `cmd`.
    vk::Timestamps& Timer(VkCommandBuffer cmd, uint32_t marks, uint32_t& allocations);
    // A host-visible buffer of at least `size` bytes for the output's read-back.
    Status Staging(VkDeviceSize size, vk::Buffer*& out, uint32_t& allocations);

  private:
    const vk::Context& c_;
    std::list<std::unique_ptr<FrameObjects>> shapes_;  // the most recently used first
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    std::unique_ptr<vk::Timestamps> timer_;
    vk::Buffer staging_;
};

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_FRAME_CACHE_H_
