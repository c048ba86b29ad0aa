#include "render/frame.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>

#include "render/frame_cache.h"
#include "render/frame_internal.h"
#include "vk/timestamps.h"

namespace kiln::runtime {
namespace {

bool HasStencil(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT_S8_UINT || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_D16_UNORM_S8_UINT || f == VK_FORMAT_S8_UINT;
}

}  // namespace

float HalfToFloat(uint16_t h) {
    const uint32_t sign = uint32_t(h & 0x8000) << 16;
    const uint32_t exp = (h >> 10) & 0x1F;
    const uint32_t mant = h & 0x3FF;
    uint32_t bits;
    if (exp == 0) {
        if (mant == 0) {
            bits = sign;
        } else {  // subnormal: normalize
            uint32_t m = mant;
            int e = -1;
            do {
                ++e;
                m <<= 1;
            } while ((m & 0x400) == 0);
            bits = sign | uint32_t(127 - 15 - e) << 23 | (m & 0x3FF) << 13;
        }
    } else if (exp == 31) {
        bits = sign | 0x7F800000u | mant << 13;
    } else {
        bits = sign | (exp + 127 - 15) << 23 | mant << 13;
    }
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
}

// The layout a target is sampled in.
VkImageLayout ReadOnlyDepthLayout() {
    return VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL;
}

VkImageLayout SampledLayout(const Frame& frame, const FramePass& pass, uint32_t t) {
    if (pass.depth_read_only && pass.depth == t) {
        return ReadOnlyDepthLayout();  // sampled while it is the pass's read-only depth buffer
    }
    return frame.targets[t].depth ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                                  : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

// Every aspect of a target's format: its attachment view and its layout transitions cover them.
VkImageAspectFlags AspectsOf(const FrameTarget& t) {
    if (!t.depth) {
        return VK_IMAGE_ASPECT_COLOR_BIT;
    }
    return VK_IMAGE_ASPECT_DEPTH_BIT | (HasStencil(t.format) ? VK_IMAGE_ASPECT_STENCIL_BIT : 0);
}

std::vector<uint32_t> Attachments(const FramePass& pass) {
    std::vector<uint32_t> out = pass.colors;
    if (pass.depth) {
        out.push_back(*pass.depth);
    }
    return out;
}

vk::TargetFormats FormatsOf(const Frame& frame, const FramePass& pass) {
    vk::TargetFormats out;
    for (uint32_t t : pass.colors) {
        out.colors.push_back(frame.targets[t].format);
    }
    if (pass.depth) {
        out.depth = frame.targets[*pass.depth].format;
    }
    const std::vector<uint32_t> attachments = Attachments(pass);
    if (!attachments.empty()) {
        out.samples = frame.targets[attachments.front()].samples;
    }
    out.resolve = !pass.resolves.empty();
    return out;
}

VkExtent2D ExtentOf(const Frame& frame, const FrameTarget& target) {
    return target.size > 0 ? VkExtent2D{target.size, target.size}
                           : VkExtent2D{frame.width, frame.height};
}

VkExtent2D ExtentOf(const Frame& frame, const FramePass& pass) {
    const std::vector<uint32_t> attachments = Attachments(pass);
    return attachments.empty() ? VkExtent2D{frame.width, frame.height}
                               : ExtentOf(frame, frame.targets[attachments.front()]);
}

FrameObjects::~FrameObjects() {
    if (pool) {
        vkDestroyDescriptorPool(c.device, pool, nullptr);
    }
    for (VkFramebuffer fb : framebuffers) {
        vkDestroyFramebuffer(c.device, fb, nullptr);
    }
    vk::DestroyBuffer(c, uniforms);
    for (VkImageView v : own_views) {
        vkDestroyImageView(c.device, v, nullptr);
    }
    for (vk::Image& image : targets) {
        vk::DestroyImage(c, image);
    }
}

void Layouts::To(VkCommandBuffer cmd, uint32_t t, VkImageLayout want) {
    if (current[t] == want) {
        return;
    }
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                      VK_ACCESS_TRANSFER_WRITE_BIT;
    b.oldLayout = current[t];
    b.newLayout = want;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = images[t].image;
    b.subresourceRange = {AspectsOf(frame.targets[t]), 0, 1, 0, frame.targets[t].cube ? 6u : 1u};
    const VkPipelineStageFlags stages =
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
        VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
        VK_PIPELINE_STAGE_TRANSFER_BIT;
    vkCmdPipelineBarrier(cmd, stages, stages, 0, 0, nullptr, 0, nullptr, 1, &b);
    current[t] = want;
}

void Layouts::Before(VkCommandBuffer cmd, const FramePass& pass) {
    if (pass.copy_from) {
        To(cmd, *pass.copy_from, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        To(cmd, pass.colors[0], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        return;
    }
    for (uint32_t t : pass.sampled) {
        if (!(pass.depth_read_only && pass.depth == t)) {  // else the attachment's layout below
            To(cmd, t, SampledLayout(frame, pass, t));
        }
    }
    for (uint32_t t : pass.colors) {
        if (pass.clear) {
            current[t] = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        } else {
            To(cmd, t, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
        }
    }
    for (uint32_t t : pass.resolves) {  // the render pass takes them from undefined
        current[t] = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    if (pass.depth) {
        const VkImageLayout want = pass.depth_read_only
                                       ? ReadOnlyDepthLayout()
                                       : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        if (pass.clear && !pass.depth_read_only) {
            current[*pass.depth] = want;
        } else {
            To(cmd, *pass.depth, want);
        }
    }
}

void BeginPass(VkCommandBuffer cmd,
               const Frame& frame,
               const FrameObjects& f,
               size_t p,
               VkRenderPass render_pass) {
    const FramePass& pass = frame.passes[p];
    std::vector<VkClearValue> clear;
    for (uint32_t t : Attachments(pass)) {
        clear.push_back(frame.targets[t].clear);
    }
    const VkExtent2D extent = ExtentOf(frame, pass);
    const uint32_t w = extent.width, h = extent.height;
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = render_pass;
    begin.framebuffer = f.framebuffers[p];
    begin.renderArea = {{0, 0}, {w, h}};
    begin.clearValueCount = uint32_t(clear.size());  // ignored by a loading render pass
    begin.pClearValues = clear.data();
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    // Negative height: clip-space +y points up the image, as in GL and glTF.
    const VkViewport viewport{0, float(h), float(w), -float(h), 0, 1};
    const VkRect2D scissor{{0, 0}, {w, h}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void RecordCopy(VkCommandBuffer cmd,
                const Frame& frame,
                const FrameObjects& f,
                const FramePass& pass) {
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    const VkExtent2D extent = ExtentOf(frame, frame.targets[*pass.copy_from]);
    region.extent = {extent.width, extent.height, 1};
    vkCmdCopyImage(cmd, f.targets[*pass.copy_from].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                   f.targets[pass.colors[0]].image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                   &region);
}

void RecordDraws(VkCommandBuffer cmd,
                 std::span<const Draw> draws,
                 std::span<const std::vector<VkDescriptorSet>> sets,
                 const VkRect2D& full) {
    const vk::Pipeline* bound = nullptr;
    VkRect2D scissor = full;
    std::optional<float> depth;  // the viewport BeginPass set: depth range 0..1
    for (size_t i = 0; i < draws.size(); ++i) {
        const Draw& d = draws[i];
        const VkRect2D want = d.scissor.value_or(full);
        if (std::memcmp(&want, &scissor, sizeof want) != 0) {
            vkCmdSetScissor(cmd, 0, 1, &want);
            scissor = want;
        }
        if (d.depth != depth) {
            const float w = float(full.extent.width), h = float(full.extent.height);
            const VkViewport viewport{0, h, w, -h, d.depth.value_or(0.0f), d.depth.value_or(1.0f)};
            vkCmdSetViewport(cmd, 0, 1, &viewport);
            depth = d.depth;
        }
        if (d.pipeline != bound) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline->pipeline);
            bound = d.pipeline;
        }
        if (!sets[i].empty()) {
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline->layout.layout,
                                    0, uint32_t(sets[i].size()), sets[i].data(), 0, nullptr);
        }
        const vk::VariantLayout& layout = d.pipeline->layout;
        if (layout.push_constant_size > 0 && d.push.size() == layout.push_constant_size) {
            vkCmdPushConstants(cmd, layout.layout, layout.push_constant_stages, 0,
                               layout.push_constant_size, d.push.data());
        }
        const VkDeviceSize zero = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &d.vertices->buffer, &zero);
        vkCmdBindIndexBuffer(cmd, d.indices->buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, d.index_count, 1, 0, 0, 0);
    }
}

Status RecordFrame(Renderer::State& s,
                   const Frame& frame,
                   LinearImage& out,
                   FrameStats& stats,
                   const StepObserver* observer,
                   std::chrono::steady_clock::time_point started) {
    if (observer) {
        return RecordFrameSteps(s, frame, out, *observer);
    }
    FrameCache& cache = s.Frames();
    FrameObjects* f = nullptr;
    if (Status e = cache.Prepare(s, frame, f, stats.allocations); !e.ok()) {
        return e;
    }
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    if (Status e = cache.Begin(cmd, stats.allocations); !e.ok()) {
        return e;
    }
    Layouts layouts{frame, f->targets,
                    std::vector<VkImageLayout>(frame.targets.size(), VK_IMAGE_LAYOUT_UNDEFINED)};
    // A mark before each pass and one after the last: the intervals are the passes' times.
    const uint32_t passes = uint32_t(frame.passes.size());
    vk::Timestamps& timer = cache.Timer(cmd, passes + 1, stats.allocations);
    for (uint32_t p = 0; p < passes; ++p) {
        layouts.Before(cmd, frame.passes[p]);
        timer.Mark(cmd, p, p > 0);
        if (frame.passes[p].copy_from) {
            RecordCopy(cmd, frame, *f, frame.passes[p]);
            continue;
        }
        BeginPass(cmd, frame, *f, p, f->render_passes[p]);
        RecordDraws(cmd, frame.passes[p].draws, f->sets[p],
                    {{0, 0}, ExtentOf(frame, frame.passes[p])});
        vkCmdEndRenderPass(cmd);
    }
    timer.Mark(cmd, passes, true);
    // The output's read-back in the same submission.
    const FrameTarget& output = frame.targets[frame.output];
    const VkDeviceSize bytes =
        VkDeviceSize{frame.width} * frame.height * VkDeviceSize{TexelBytes(output)};
    vk::Buffer* staging = nullptr;
    if (Status e = cache.Staging(bytes, staging, stats.allocations); !e.ok()) {
        return e;
    }
    RecordTargetCopy(cmd, frame, *f, frame.output, 0, layouts.current[frame.output],
                     staging->buffer);
    const auto submitted = std::chrono::steady_clock::now();
    stats.cpu_ms = std::chrono::duration<double, std::milli>(submitted - started).count();
    if (Status e = cache.SubmitAndWait(cmd, stats.allocations); !e.ok()) {
        return e;
    }
    const std::vector<double> ms = timer.Intervals();
    stats.pass_times.clear();
    stats.gpu_ms = ms.empty() ? -1.0 : 0.0;
    for (size_t p = 0; p < ms.size(); ++p) {
        stats.pass_times.push_back({frame.passes[p].name, ms[p]});
        stats.gpu_ms += ms[p];
    }
    const auto* p = static_cast<const uint8_t*>(staging->mapped);
    out.width = frame.width;
    out.height = frame.height;
    out.rgba = TargetFloats(output, {p, size_t(bytes)});  // from the mapped buffer, no copy
    stats.readback_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - submitted)
            .count();
    return {};
}

}  // namespace kiln::runtime
