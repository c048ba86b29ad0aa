#include "render/frame.h"

#include <cstring>
#include <deque>
#include <map>

namespace kiln::runtime {
namespace {

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

// The frame's device objects, freed on every path out of RecordFrame.
struct FrameObjects {
    const vk::Context& c;
    std::vector<vk::Image> targets;
    std::vector<VkFramebuffer> framebuffers;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    vk::Buffer uniforms;
    ~FrameObjects() {
        if (pool) {
            vkDestroyDescriptorPool(c.device, pool, nullptr);
        }
        for (VkFramebuffer f : framebuffers) {
            vkDestroyFramebuffer(c.device, f, nullptr);
        }
        vk::DestroyBuffer(c, uniforms);
        for (vk::Image& image : targets) {
            vk::DestroyImage(c, image);
        }
    }
};

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
        } else {
            wr.pImageInfo = &dw.image;
        }
        writes.push_back(wr);
    }
    vkUpdateDescriptorSets(c.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
    return {};
}

void RecordDraws(VkCommandBuffer cmd,
                 const std::vector<Draw>& draws,
                 const std::vector<std::vector<VkDescriptorSet>>& sets) {
    const vk::Pipeline* bound = nullptr;
    for (size_t i = 0; i < draws.size(); ++i) {
        const Draw& d = draws[i];
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

}  // namespace

// A pass's targets in attachment order: the colours, then the depth buffer.
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
    return out;
}

Status RecordFrame(Renderer::State& s, const Frame& frame, LinearImage& out) {
    const vk::Context& c = s.context;
    const uint32_t w = frame.width, h = frame.height;
    FrameObjects f{c, {}, {}, VK_NULL_HANDLE, {}};
    for (const FrameTarget& t : frame.targets) {
        vk::Image& image = f.targets.emplace_back();
        const VkImageUsageFlags usage =
            t.depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT
                    : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        if (Status e = vk::CreateImage(
                c, w, h, t.format, usage,
                t.depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT, image);
            !e.ok()) {
            return e;
        }
    }
    std::vector<VkRenderPass> render_passes;
    for (const FramePass& pass : frame.passes) {
        VkRenderPass rp = VK_NULL_HANDLE;
        if (Status e = s.RenderPass(FormatsOf(frame, pass), pass.clear, rp); !e.ok()) {
            return e;
        }
        render_passes.push_back(rp);
        std::vector<VkImageView> views;
        for (uint32_t t : Attachments(pass)) {
            views.push_back(f.targets[t].view);
        }
        VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fb.renderPass = rp;
        fb.attachmentCount = uint32_t(views.size());
        fb.pAttachments = views.data();
        fb.width = w;
        fb.height = h;
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
    std::vector<std::vector<std::vector<VkDescriptorSet>>> sets(frame.passes.size());
    for (size_t p = 0; p < frame.passes.size(); ++p) {
        sets[p].resize(frame.passes[p].draws.size());
        for (size_t i = 0; i < frame.passes[p].draws.size(); ++i) {
            if (Status e = WriteSets(c, f.pool, f.uniforms, frame.passes[p].draws[i], sets[p][i]);
                !e.ok()) {
                return e;
            }
        }
    }

    VkCommandBuffer cmd = vk::BeginOneShot(c);
    if (cmd == VK_NULL_HANDLE) {
        return Error{DiagCode::kRenderFailed, "cannot allocate a command buffer"};
    }
    // Negative height: clip-space +y points up the image, as in GL and glTF.
    const VkViewport viewport{0, float(h), float(w), -float(h), 0, 1};
    const VkRect2D scissor{{0, 0}, {w, h}};
    for (size_t p = 0; p < frame.passes.size(); ++p) {
        const FramePass& pass = frame.passes[p];
        std::vector<VkClearValue> clear;
        for (uint32_t t : Attachments(pass)) {
            clear.push_back(frame.targets[t].clear);
        }
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = render_passes[p];
        begin.framebuffer = f.framebuffers[p];
        begin.renderArea = {{0, 0}, {w, h}};
        begin.clearValueCount = pass.clear ? uint32_t(clear.size()) : 0;
        begin.pClearValues = pass.clear ? clear.data() : nullptr;
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        RecordDraws(cmd, pass.draws, sets[p]);
        vkCmdEndRenderPass(cmd);
    }
    // The output leaves its attachment layout for the read-back copy (the render pass's
    // dependency made its writes available to transfers).
    VkImageMemoryBarrier to_copy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    to_copy.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    to_copy.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    to_copy.oldLayout =
        frame.passes.empty() ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    to_copy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    to_copy.srcQueueFamilyIndex = to_copy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_copy.image = f.targets[frame.output].image;
    to_copy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &to_copy);
    if (Status e = vk::SubmitAndWait(c, cmd); !e.ok()) {
        return e;
    }

    const bool f32 = frame.targets[frame.output].format == VK_FORMAT_R32G32B32A32_SFLOAT;
    std::vector<uint8_t> bytes;
    if (Status e = vk::ReadBack(c, f.targets[frame.output], f32 ? 16 : 8, bytes); !e.ok()) {
        return e;
    }
    out.width = w;
    out.height = h;
    out.rgba.resize(size_t{w} * h * 4);
    if (f32) {
        std::memcpy(out.rgba.data(), bytes.data(), out.rgba.size() * 4);
    } else {
        for (size_t i = 0; i < out.rgba.size(); ++i) {
            uint16_t half;
            std::memcpy(&half, bytes.data() + i * 2, 2);
            out.rgba[i] = HalfToFloat(half);
        }
    }
    return {};
}

}  // namespace kiln::runtime
