// RecordFrame: colour and depth targets, one uniform buffer and one descriptor pool for the
// frame, the draws recorded in order into one command buffer, then the read-back of the colour
// target as linear floats.
#include <cstring>
#include <map>

#include "render/draw.h"

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

struct FrameObjects {
    const vk::Context& c;
    vk::Image color, depth;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    vk::Buffer uniforms;
    ~FrameObjects() {
        if (pool) {
            vkDestroyDescriptorPool(c.device, pool, nullptr);
        }
        if (framebuffer) {
            vkDestroyFramebuffer(c.device, framebuffer, nullptr);
        }
        vk::DestroyBuffer(c, uniforms);
        vk::DestroyImage(c, color);
        vk::DestroyImage(c, depth);
    }
};

}  // namespace

Status RecordFrame(Renderer::State& s,
                   const FrameSettings& settings,
                   const std::vector<Draw>& draws,
                   const std::vector<uint8_t>& uniforms,
                   LinearImage& out) {
    const vk::Context& c = s.context;
    const uint32_t w = settings.width, h = settings.height;
    FrameObjects f{c, {}, {}, VK_NULL_HANDLE, VK_NULL_HANDLE, {}};
    if (Status e =
            vk::CreateImage(c, w, h, s.color_format,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT, f.color);
        !e.ok()) {
        return e;
    }
    if (Status e =
            vk::CreateImage(c, w, h, s.depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                            VK_IMAGE_ASPECT_DEPTH_BIT, f.depth);
        !e.ok()) {
        return e;
    }
    const VkImageView views[2] = {f.color.view, f.depth.view};
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = s.render_pass;
    fb.attachmentCount = 2;
    fb.pAttachments = views;
    fb.width = w;
    fb.height = h;
    fb.layers = 1;
    if (VkResult r = vkCreateFramebuffer(c.device, &fb, nullptr, &f.framebuffer); r != VK_SUCCESS) {
        return vk::VkError("cannot create the framebuffer", r);
    }
    if (Status e =
            vk::CreateBufferWithData(c, uniforms, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, f.uniforms);
        !e.ok()) {
        return e;
    }

    // One pool sized for every set of every draw.
    std::map<VkDescriptorType, uint32_t> counts;
    uint32_t set_count = 0;
    for (const Draw& d : draws) {
        set_count += uint32_t(d.pipeline->layout.sets.size());
        for (const auto& bindings : d.pipeline->layout.bindings) {
            for (const auto& b : bindings) {
                counts[b.descriptorType] += b.descriptorCount;
            }
        }
    }
    std::vector<VkDescriptorPoolSize> sizes;
    for (const auto& [type, n] : counts) {
        sizes.push_back({type, n});
    }
    if (sizes.empty()) {  // sets without bindings still need a non-empty pool description
        sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1});
    }
    if (set_count > 0) {
        VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        pool.maxSets = set_count;
        pool.poolSizeCount = uint32_t(sizes.size());
        pool.pPoolSizes = sizes.data();
        if (VkResult r = vkCreateDescriptorPool(c.device, &pool, nullptr, &f.pool);
            r != VK_SUCCESS) {
            return vk::VkError("cannot create the frame's descriptor pool", r);
        }
    }

    // Descriptor sets per draw, written before recording.
    std::vector<std::vector<VkDescriptorSet>> sets(draws.size());
    for (size_t i = 0; i < draws.size(); ++i) {
        const vk::VariantLayout& layout = draws[i].pipeline->layout;
        if (layout.sets.empty()) {
            continue;
        }
        sets[i].resize(layout.sets.size());
        VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        alloc.descriptorPool = f.pool;
        alloc.descriptorSetCount = uint32_t(layout.sets.size());
        alloc.pSetLayouts = layout.sets.data();
        if (VkResult r = vkAllocateDescriptorSets(c.device, &alloc, sets[i].data());
            r != VK_SUCCESS) {
            return vk::VkError("cannot allocate descriptor sets", r);
        }
        std::vector<VkDescriptorBufferInfo> buffer_infos(draws[i].writes.size());
        std::vector<VkWriteDescriptorSet> writes;
        for (size_t k = 0; k < draws[i].writes.size(); ++k) {
            const Draw::Write& dw = draws[i].writes[k];
            if (dw.set >= sets[i].size()) {
                continue;
            }
            VkWriteDescriptorSet wr{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            wr.dstSet = sets[i][dw.set];
            wr.dstBinding = dw.binding;
            wr.descriptorCount = 1;
            wr.descriptorType = dw.type;
            if (dw.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
                buffer_infos[k] = {f.uniforms.buffer, dw.offset, dw.range};
                wr.pBufferInfo = &buffer_infos[k];
            } else {
                wr.pImageInfo = &dw.image;
            }
            writes.push_back(wr);
        }
        vkUpdateDescriptorSets(c.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
    }

    VkCommandBuffer cmd = vk::BeginOneShot(c);
    if (cmd == VK_NULL_HANDLE) {
        return Error{DiagCode::kRenderFailed, "cannot allocate a command buffer"};
    }
    VkClearValue clear[2]{};
    clear[0].color = {{settings.background.r, settings.background.g, settings.background.b,
                       0}};  // alpha 0: not covered
    clear[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = s.render_pass;
    begin.framebuffer = f.framebuffer;
    begin.renderArea = {{0, 0}, {w, h}};
    begin.clearValueCount = 2;
    begin.pClearValues = clear;
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    // Negative height: clip-space +y points up the image, as in GL and glTF.
    const VkViewport viewport{0, float(h), float(w), -float(h), 0, 1};
    const VkRect2D scissor{{0, 0}, {w, h}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
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
    vkCmdEndRenderPass(cmd);
    if (Status e = vk::SubmitAndWait(c, cmd); !e.ok()) {
        return e;
    }

    const bool f32 = s.color_format == VK_FORMAT_R32G32B32A32_SFLOAT;
    std::vector<uint8_t> bytes;
    if (Status e = vk::ReadBack(c, f.color, f32 ? 16 : 8, bytes); !e.ok()) {
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
