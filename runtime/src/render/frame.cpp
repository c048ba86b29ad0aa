#include "render/frame.h"

#include <cstring>
#include <map>

#include "render/frame_internal.h"
#include "vk/timestamps.h"

namespace kiln::runtime {
namespace {

bool HasStencil(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT_S8_UINT || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_D16_UNORM_S8_UINT || f == VK_FORMAT_S8_UINT;
}

// One descriptor pool sized for every set of every draw of the frame; null when no draw has a set.
Status CreatePool(const vk::Context& c, const Frame& frame, VkDescriptorPool& out) {
    std::map<VkDescriptorType, uint32_t> counts;
    uint32_t set_count = 0;
    for (const FramePass& pass : frame.passes) {
        for (const Draw& d : pass.draws) {
            set_count += uint32_t(d.pipeline->layout.sets.size());
            for (const auto& bindings : d.pipeline->layout.bindings) {
                for (const auto& b : bindings) {
                    counts[b.descriptorType] += b.descriptorCount;
                }
            }
        }
    }
    if (set_count == 0) {
        return {};
    }
    std::vector<VkDescriptorPoolSize> sizes;
    for (const auto& [type, n] : counts) {
        sizes.push_back({type, n});
    }
    if (sizes.empty()) {  // sets without bindings still need a non-empty pool description
        sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1});
    }
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.maxSets = set_count;
    pool.poolSizeCount = uint32_t(sizes.size());
    pool.pPoolSizes = sizes.data();
    if (VkResult r = vkCreateDescriptorPool(c.device, &pool, nullptr, &out); r != VK_SUCCESS) {
        return vk::VkError("cannot create the frame's descriptor pool", r);
    }
    return {};
}

// A draw's descriptor sets, allocated from `pool` and written.
Status WriteSets(const vk::Context& c,
                 VkDescriptorPool pool,
                 const vk::Buffer& uniforms,
                 const Frame& frame,
                 const FramePass& pass,
                 const std::vector<VkImageView>& sampled_views,
                 const Draw& draw,
                 std::vector<VkDescriptorSet>& out) {
    const vk::VariantLayout& layout = draw.pipeline->layout;
    if (layout.sets.empty()) {
        return {};
    }
    out.resize(layout.sets.size());
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool;
    alloc.descriptorSetCount = uint32_t(layout.sets.size());
    alloc.pSetLayouts = layout.sets.data();
    if (VkResult r = vkAllocateDescriptorSets(c.device, &alloc, out.data()); r != VK_SUCCESS) {
        return vk::VkError("cannot allocate descriptor sets", r);
    }
    std::vector<VkDescriptorBufferInfo> buffer_infos(draw.writes.size());
    std::vector<VkDescriptorImageInfo> image_infos(draw.writes.size());
    std::vector<VkWriteDescriptorSet> writes;
    for (size_t k = 0; k < draw.writes.size(); ++k) {
        const Draw::Write& dw = draw.writes[k];
        if (dw.set >= out.size()) {
            continue;
        }
        VkWriteDescriptorSet wr{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        wr.dstSet = out[dw.set];
        wr.dstBinding = dw.binding;
        wr.descriptorCount = 1;
        wr.descriptorType = dw.type;
        if (dw.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
            buffer_infos[k] = {uniforms.buffer, dw.offset, dw.range};
            wr.pBufferInfo = &buffer_infos[k];
        } else if (dw.target >= 0 && size_t(dw.target) < sampled_views.size()) {
            image_infos[k] = dw.image;
            image_infos[k].imageView = sampled_views[size_t(dw.target)];
            image_infos[k].imageLayout = SampledLayout(frame, pass, uint32_t(dw.target));
            wr.pImageInfo = &image_infos[k];
        } else {
            wr.pImageInfo = &dw.image;
        }
        writes.push_back(wr);
    }
    vkUpdateDescriptorSets(c.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
    return {};
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

Status PrepareFrame(Renderer::State& s, const Frame& frame, FrameObjects& f) {
    const vk::Context& c = s.context;
    for (const FrameTarget& t : frame.targets) {
        vk::Image& image = f.targets.emplace_back();
        if (t.shadow_map) {  // depth only, sampled with comparisons
            if (Status e = vk::CreateShadowMap(c, t.size, t.format, t.cube, image); !e.ok()) {
                return e;
            }
            f.sampled_views.push_back(image.view);
            continue;
        }
        // Every single-sample target may be sampled by a later pass and read back (the frame
        // debugger); a multisampled one is only an attachment, resolved by its pass.
        const bool multisampled = t.samples != VK_SAMPLE_COUNT_1_BIT;
        const VkImageUsageFlags usage =
            (t.depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT
                     : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) |
            (multisampled ? 0
                          : VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                (t.depth ? 0 : VK_IMAGE_USAGE_TRANSFER_DST_BIT));
        const VkExtent2D extent = ExtentOf(frame, t);
        if (Status e = vk::CreateImage(c, extent.width, extent.height, t.format, usage,
                                       AspectsOf(t), image, 1, t.samples);
            !e.ok()) {
            return e;
        }
        f.sampled_views.push_back(image.view);
        if (AspectsOf(t) != (t.depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT)) {
            VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
            view.image = image.image;
            view.viewType = VK_IMAGE_VIEW_TYPE_2D;
            view.format = t.format;
            view.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
            VkImageView depth_only = VK_NULL_HANDLE;
            if (VkResult r = vkCreateImageView(c.device, &view, nullptr, &depth_only);
                r != VK_SUCCESS) {
                return vk::VkError("cannot create a depth view", r);
            }
            f.own_views.push_back(depth_only);
            f.sampled_views.back() = depth_only;
        }
    }
    for (const FramePass& pass : frame.passes) {
        if (pass.copy_from) {  // no render pass
            f.render_passes.push_back(VK_NULL_HANDLE);
            f.framebuffers.push_back(VK_NULL_HANDLE);
            continue;
        }
        VkRenderPass rp = VK_NULL_HANDLE;
        if (Status e = s.RenderPass(FormatsOf(frame, pass), pass.clear, pass.depth_read_only, rp);
            !e.ok()) {
            return e;
        }
        f.render_passes.push_back(rp);
        std::vector<VkImageView> views;
        for (uint32_t t : Attachments(pass)) {
            views.push_back(f.targets[t].view);
            if (frame.targets[t].cube) {  // the face the pass draws, as a 2D view
                VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
                view.image = f.targets[t].image;
                view.viewType = VK_IMAGE_VIEW_TYPE_2D;
                view.format = frame.targets[t].format;
                view.subresourceRange = {AspectsOf(frame.targets[t]), 0, 1, pass.layer, 1};
                VkImageView face = VK_NULL_HANDLE;
                if (VkResult r = vkCreateImageView(c.device, &view, nullptr, &face);
                    r != VK_SUCCESS) {
                    return vk::VkError("cannot create a cube face view", r);
                }
                f.own_views.push_back(face);
                views.back() = face;
            }
        }
        for (uint32_t t : pass.resolves) {  // after the depth, as the render pass has them
            views.push_back(f.targets[t].view);
        }
        VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fb.renderPass = rp;
        fb.attachmentCount = uint32_t(views.size());
        fb.pAttachments = views.data();
        const VkExtent2D extent = ExtentOf(frame, pass);
        fb.width = extent.width;
        fb.height = extent.height;
        fb.layers = 1;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        if (VkResult r = vkCreateFramebuffer(c.device, &fb, nullptr, &framebuffer);
            r != VK_SUCCESS) {
            return vk::VkError("cannot create a framebuffer", r);
        }
        f.framebuffers.push_back(framebuffer);
    }
    if (Status e = vk::CreateBufferWithData(c, frame.uniforms, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                            f.uniforms);
        !e.ok()) {
        return e;
    }
    if (Status e = CreatePool(c, frame, f.pool); !e.ok()) {
        return e;
    }
    // Descriptor sets per draw, written before recording.
    f.sets.resize(frame.passes.size());
    for (size_t p = 0; p < frame.passes.size(); ++p) {
        f.sets[p].resize(frame.passes[p].draws.size());
        for (size_t i = 0; i < frame.passes[p].draws.size(); ++i) {
            if (Status e = WriteSets(c, f.pool, f.uniforms, frame, frame.passes[p], f.sampled_views,
                                     frame.passes[p].draws[i], f.sets[p][i]);
                !e.ok()) {
                return e;
            }
        }
    }
    return {};
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
                   const StepObserver* observer) {
    if (observer) {
        return RecordFrameSteps(s, frame, out, *observer);
    }
    const vk::Context& c = s.context;
    FrameObjects f(c);
    if (Status e = PrepareFrame(s, frame, f); !e.ok()) {
        return e;
    }
    VkCommandBuffer cmd = vk::BeginOneShot(c);
    if (cmd == VK_NULL_HANDLE) {
        return Error{DiagCode::kRenderFailed, "cannot allocate a command buffer"};
    }
    Layouts layouts{frame, f.targets,
                    std::vector<VkImageLayout>(frame.targets.size(), VK_IMAGE_LAYOUT_UNDEFINED)};
    // A mark before each pass and one after the last: the intervals are the passes' times.
    const uint32_t passes = uint32_t(frame.passes.size());
    vk::Timestamps timer(c, passes + 1);
    timer.Reset(cmd);
    for (uint32_t p = 0; p < passes; ++p) {
        layouts.Before(cmd, frame.passes[p]);
        timer.Mark(cmd, p, p > 0);
        if (frame.passes[p].copy_from) {
            RecordCopy(cmd, frame, f, frame.passes[p]);
            continue;
        }
        BeginPass(cmd, frame, f, p, f.render_passes[p]);
        RecordDraws(cmd, frame.passes[p].draws, f.sets[p],
                    {{0, 0}, ExtentOf(frame, frame.passes[p])});
        vkCmdEndRenderPass(cmd);
    }
    timer.Mark(cmd, passes, true);
    if (Status e = vk::SubmitAndWait(c, cmd); !e.ok()) {
        return e;
    }
    const std::vector<double> ms = timer.Intervals();
    stats.pass_times.clear();
    stats.gpu_ms = ms.empty() ? -1.0 : 0.0;
    for (size_t p = 0; p < ms.size(); ++p) {
        stats.pass_times.push_back({frame.passes[p].name, ms[p]});
        stats.gpu_ms += ms[p];
    }
    return ReadOutput(c, frame, f, layouts.current[frame.output], out);
}

}  // namespace kiln::runtime
