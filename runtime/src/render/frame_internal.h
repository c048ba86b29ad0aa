// What RecordFrame (render/frame.cpp) and the frame debugger's step-by-step recording
// (render/frame_capture.cpp) share: the frame's device objects, the layout tracking of its
// targets, and the recording of a pass's draws.
#ifndef KILN_RUNTIME_RENDER_FRAME_INTERNAL_H_
#define KILN_RUNTIME_RENDER_FRAME_INTERNAL_H_

#include <map>
#include <span>
#include <string>
#include <vector>

#include "render/frame.h"

namespace kiln::runtime {

float HalfToFloat(uint16_t h);
// The nearest IEEE half (ties to even; beyond 65504 infinity, NaN kept).
uint16_t FloatToHalf(float f);
// The texels of a float target (RGBA16F or RGBA32F) as read back, as floats.
std::vector<float> TargetFloats(const FrameTarget& t, std::span<const uint8_t> bytes);
// The texels of any target as read back, decoded to the values a shader reads from it: depth
// as stored (one channel), R8 one channel in [0, 1], UNORM channels in [0, 1], sRGB colour
// channels to linear (alpha as stored), float channels as they are.
std::vector<float> DecodeTexels(const FrameTarget& t, const std::vector<uint8_t>& bytes);
// The channels per texel DecodeTexels gives: 1 (depth, R8) or 4.
uint32_t DecodedChannels(const FrameTarget& t);

// A pass's targets in attachment order: the colours, then the depth buffer.
std::vector<uint32_t> Attachments(const FramePass& pass);
// Every aspect of a target's format: its attachment view and its layout transitions cover them.
VkImageAspectFlags AspectsOf(const FrameTarget& t);
// The layout target `t` is sampled in during `pass`.
VkImageLayout SampledLayout(const Frame& frame, const FramePass& pass, uint32_t t);
// A pass's read-only depth buffer: depth tested and sampled, stencil written.
VkImageLayout ReadOnlyDepthLayout();

// The frame's device objects, freed on every path out of a recording.
struct FrameObjects {
    explicit FrameObjects(const vk::Context& context) : c(context) {}
    ~FrameObjects();
    FrameObjects(const FrameObjects&) = delete;
    FrameObjects& operator=(const FrameObjects&) = delete;

    const vk::Context& c;
    std::vector<vk::Image> targets;
    // What draws sample each target through: its view, or for a depth-stencil target a view of
    // the depth aspect alone (a sampled view has one aspect).
    std::vector<VkImageView> sampled_views;
    std::vector<VkImageView> own_views;       // the depth-only views, destroyed with the frame
    std::vector<VkRenderPass> render_passes;  // per pass, as it clears or loads (the state's)
    std::vector<VkFramebuffer> framebuffers;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    uint32_t pool_sets = 0;                           // what the pool holds
    std::map<VkDescriptorType, uint32_t> pool_sizes;  // ... per descriptor type
    vk::Buffer uniforms;  // at least the frame's uniform bytes (it grows, render/frame_cache.h)
    std::vector<std::vector<std::vector<VkDescriptorSet>>> sets;  // per pass, per draw
    std::string shape;  // ShapeOf the frames the targets were made for
};

// What a frame's targets, views and framebuffers depend on: its size, its targets' formats,
// sizes, samples and kinds, and its passes' attachments, clears and layers. Frames of one path
// at one size have one shape.
std::string ShapeOf(const Frame& frame);
// Creates the targets, their views, the render passes (the state's) and framebuffers;
// `allocations` counts the Vulkan objects made.
Status CreateTargets(Renderer::State& s,
                     const Frame& frame,
                     FrameObjects& f,
                     uint32_t& allocations);
// Writes the frame's uniforms (the buffer grown when too small) and every draw's descriptor sets
// (from the pool, reset, or grown when too small).
Status PrepareDraws(const vk::Context& c,
                    const Frame& frame,
                    FrameObjects& f,
                    uint32_t& allocations);
// Both, into fresh objects (the frame debugger's step-by-step recording).
Status PrepareFrame(Renderer::State& s, const Frame& frame, FrameObjects& f);

// Moves the frame's targets into the layouts each pass uses them in, after whatever wrote them.
struct Layouts {
    const Frame& frame;
    const std::vector<vk::Image>& images;
    std::vector<VkImageLayout> current;

    void To(VkCommandBuffer cmd, uint32_t t, VkImageLayout want);
    // Before `pass`: its sampled targets readable, its attachments in attachment layout (a
    // clearing pass's render pass starts them from undefined itself).
    void Before(VkCommandBuffer cmd, const FramePass& pass);
};

// Begins pass `p` in `render_pass` (clearing or loading), with the frame's viewport and scissor.
void BeginPass(VkCommandBuffer cmd,
               const Frame& frame,
               const FrameObjects& f,
               size_t p,
               VkRenderPass render_pass);

// A copy pass (FramePass::copy_from), after Layouts::Before.
void RecordCopy(VkCommandBuffer cmd,
                const Frame& frame,
                const FrameObjects& f,
                const FramePass& pass);

void RecordDraws(VkCommandBuffer cmd,
                 std::span<const Draw> draws,
                 std::span<const std::vector<VkDescriptorSet>> sets,
                 const VkRect2D& full);

// Records the copy of layer `layer` of target `t` (in `layout`, where it is left) into `dst`, made
// visible to the host: ReadTarget's, and RecordFrame's of its output in the frame's own
// submission.
void RecordTargetCopy(VkCommandBuffer cmd,
                      const Frame& frame,
                      const FrameObjects& f,
                      uint32_t t,
                      uint32_t layer,
                      VkImageLayout layout,
                      VkBuffer dst);

// Copies layer `layer` of target `t` (in `layout`, where it is left) to host memory at the
// target's extent (ExtentOf): colour texels, or the depth aspect of a depth target (4 bytes a
// texel). Single-sample targets only.
Status ReadTarget(const vk::Context& c,
                  const Frame& frame,
                  const FrameObjects& f,
                  uint32_t t,
                  uint32_t layer,
                  VkImageLayout layout,
                  std::vector<uint8_t>& out);

// RecordFrame with an observer: each pass's clear and each draw submitted on its own, the
// targets the pass writes read back after each (render/frame_capture.cpp).
Status RecordFrameSteps(Renderer::State& s,
                        const Frame& frame,
                        LinearImage& out,
                        const StepObserver& observer);

// Bytes per texel of a target's format as ReadTarget returns them.
uint32_t TexelBytes(const FrameTarget& t);

// The output target (in `layout`) as linear floats.
Status ReadOutput(const vk::Context& c,
                  const Frame& frame,
                  const FrameObjects& f,
                  VkImageLayout layout,
                  LinearImage& out);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_FRAME_INTERNAL_H_
