// A frame as the device records it: a list of passes, each drawing into explicit targets (colour
// attachments and a depth buffer, named, with their formats) that later passes may load or sample.
// Everything is decided on the CPU first (draws with their pipelines, uniform bytes and
// descriptors); RecordFrame then creates the targets, records every pass into one command buffer
// (moving each target into the layout the pass uses it in: attachment, read-only depth, or
// sampled) and reads the output target back.
#ifndef KILN_RUNTIME_RENDER_FRAME_H_
#define KILN_RUNTIME_RENDER_FRAME_H_

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/renderer_state.h"
#include "render/textures.h"

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
        // A target of the frame (index into Frame::targets) sampled by the draw: its view and
        // read-only layout replace image's when the frame is recorded. -1: none.
        int target = -1;
    };
    std::vector<Write> writes;
    std::optional<VkRect2D> scissor;  // none: the whole frame
    // Every fragment at this depth (the viewport's depth range collapsed to it), for depth tests
    // against a fixed depth: the deferred light pass's bounds. None: the vertices' depth.
    std::optional<float> depth;
    // Recorded in the same frame-debugger step as the next draw (a light's stencil mask and the
    // light it bounds).
    bool joins_next = false;
    // What the frame debugger records about the draw.
    struct Info {
        std::string shader, pass, light_mode, keywords, state, light, object;
        std::string mesh;  // "mesh 'sphere', primitive 0", or the full-screen triangle
        uint32_t vertex_count = 0, index_count = 0;
        // Each bound texture by the shader's name for it: where it comes from, its size and
        // format, and a small copy of its image where the runtime has one (files, glTF images).
        struct Texture {
            std::string name, source;
            uint32_t width = 0, height = 0;
            VkFormat format = VK_FORMAT_UNDEFINED;
            std::shared_ptr<const Thumbnail> thumbnail;
        };
        std::vector<Texture> textures;
        // The uniform blocks' members by name, as written ("(not set)" members are absent).
        std::vector<std::pair<std::string, std::vector<float>>> values;
    };
    Info info;
};

// An image of the frame: a colour target or the depth-stencil buffer.
struct FrameTarget {
    std::string name;  // "color", "depth", ...: for messages and the frame debugger
    VkFormat format = VK_FORMAT_UNDEFINED;
    bool depth = false;
    VkClearValue clear{};  // what a pass that clears it writes
    // How the frame debugger shows it: through the display transform (light), or as stored
    // (G-buffer data). Depth targets are linearised.
    bool display = true;
    // Sampled with bilinear filtering (a GrabPass's texture, as in Unity); else nearest texels.
    bool filtered = false;
    // Samples per pixel (MSAA). A multisampled target is only an attachment: a pass resolves it
    // (FramePass::resolves) into a single-sample target that is read back or sampled.
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    // A shadow map (depth only): `size` x `size` texels whatever the frame's size, sampled with a
    // depth-comparison sampler; `cube`: six layers (+X, -X, +Y, -Y, +Z, -Z) sampled as a cube, one
    // pass drawing each (FramePass::layer). The frame debugger reads back the face a pass drew.
    bool shadow_map = false;
    uint32_t size = 0;
    bool cube = false;
    // Read back by the frame debugger after each step that writes it (not: an attachment no
    // draw writes, the shadow passes' masked-off colour).
    bool shown = true;
};

struct FramePass {
    std::string name;               // "forward", ...
    std::vector<uint32_t> colors;   // indices into Frame::targets, in attachment order
    std::optional<uint32_t> depth;  // index into Frame::targets
    bool clear = true;              // clear the targets first; false: keep what they hold
    // The depth buffer is read-only in this pass (depth tests, no writes), so the pass may also
    // sample it; its stencil is cleared at the start and writable (the light pass's masks).
    bool depth_read_only = false;
    std::vector<uint32_t> sampled;  // targets the draws sample (Draw::Write::target)
    // Multisampled passes: the single-sample targets the colour attachments are resolved into
    // at the end of the pass, one per colour, in order.
    std::vector<uint32_t> resolves;
    // The layer of a cube shadow map (FrameTarget::cube) the pass draws into.
    uint32_t layer = 0;
    std::vector<Draw> draws;
    // A copy pass (a GrabPass): no render pass and no draws; the single-sample colour target
    // `copy_from` is copied into colors[0], a target of the same format and size.
    std::optional<uint32_t> copy_from;
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

// The size of a target, and of a pass's render area (its attachments').
VkExtent2D ExtentOf(const Frame& frame, const FrameTarget& target);
VkExtent2D ExtentOf(const Frame& frame, const FramePass& pass);

// A target read back after a step: its index into Frame::targets and its texels (a depth
// target's depth aspect, 4 bytes each).
struct CapturedTarget {
    uint32_t target = 0;
    uint32_t layer = 0;  // a cube target's face the pass drew
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> bytes;
};

// Records and submits the frame and reads the output back. With `observer` (the frame debugger)
// each pass's clear and each draw is submitted on its own, and after each the targets the pass
// writes are read back and handed to the observer with the draw's GPU time (timestamp queries;
// negative where the queue has none) — the image is the same. Without it the frame reuses the
// renderer's frame objects (render/frame_cache.h; stats.allocations counts what it made), the
// passes are timed into stats.gpu_ms and stats.pass_times, the CPU time from `started` to the
// submission into stats.cpu_ms, and the output is read back in the same submission.
Status RecordFrame(
    Renderer::State& s,
    const Frame& frame,
    LinearImage& out,
    FrameStats& stats,
    const StepObserver* observer = nullptr,
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now());

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_FRAME_H_
