// Preparing a frame's device objects (render/frame_internal.h): its targets, views and
// framebuffers (CreateTargets, once per frame shape: render/frame_cache.h), its uniforms and its
// draws' descriptor sets (PrepareDraws, every frame).
#include <algorithm>
#include <cstring>
#include <map>

#include "render/frame_internal.h"

namespace kiln::runtime {
namespace {

// The frame's descriptor pool, holding every set of every draw: the pool of earlier frames, reset,
// when it is large enough; else a new one with room for twice what the frame needs.
Status EnsurePool(const vk::Context& c,
                  const Frame& frame,
                  FrameObjects& f,
                  uint32_t& allocations) {
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
    bool fits = f.pool != VK_NULL_HANDLE && set_count <= f.pool_sets;
    for (const auto& [type, n] : counts) {
        fits = fits && f.pool_sizes.count(type) && n <= f.pool_sizes.at(type);
    }
    if (fits) {
        if (VkResult r = vkResetDescriptorPool(c.device, f.pool, 0); r != VK_SUCCESS) {
            return vk::VkError("cannot reset the frame's descriptor pool", r);
        }
        return {};
    }
    if (set_count == 0) {
        return {};  // no draw has a set: the pool is not needed
    }
    if (f.pool) {
        vkDestroyDescriptorPool(c.device, f.pool, nullptr);
        f.pool = VK_NULL_HANDLE;
    }
    f.pool_sets = 2 * std::max(set_count, f.pool_sets);
    for (const auto& [type, n] : counts) {
        f.pool_sizes[type] = 2 * std::max(n, f.pool_sizes[type]);
    }
    std::vector<VkDescriptorPoolSize> sizes;
    for (const auto& [type, n] : f.pool_sizes) {
        sizes.push_back({type, n});
    }
    if (sizes.empty()) {  // sets without bindings still need a non-empty pool description
        sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1});
    }
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.maxSets = f.pool_sets;
    pool.poolSizeCount = uint32_t(sizes.size());
    pool.pPoolSizes = sizes.data();
    if (VkResult r = vkCreateDescriptorPool(c.device, &pool, nullptr, &f.pool); r != VK_SUCCESS) {
        f.pool = VK_NULL_HANDLE;
        f.pool_sets = 0;
        f.pool_sizes.clear();
        return vk::VkError("cannot create the frame's descriptor pool", r);
    }
    ++allocations;
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

Status CreateTargets(Renderer::State& s,
                     const Frame& frame,
                     FrameObjects& f,
                     uint32_t& allocations) {
    const vk::Context& c = s.context;
    for (const FrameTarget& t : frame.targets) {
        vk::Image& image = f.targets.emplace_back();
        if (t.shadow_map) {  // depth only, sampled with comparisons
            if (Status e = vk::CreateShadowMap(c, t.size, t.format, t.cube, image); !e.ok()) {
                return e;
            }
            ++allocations;
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
        ++allocations;
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
            ++allocations;
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
                ++allocations;
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
        ++allocations;
    }
    return {};
}

Status PrepareDraws(const vk::Context& c,
                    const Frame& frame,
                    FrameObjects& f,
                    uint32_t& allocations) {
    // The uniform buffer: grown (to twice the frame's bytes) only when too small.
    const VkDeviceSize bytes = std::max<VkDeviceSize>(frame.uniforms.size(), 256);
    if (f.uniforms.size < bytes) {
        vk::DestroyBuffer(c, f.uniforms);
        if (Status e =
                vk::CreateBuffer(c, 2 * bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, f.uniforms);
            !e.ok()) {
            return e;
        }
        ++allocations;
    }
    if (!frame.uniforms.empty()) {
        std::memcpy(f.uniforms.mapped, frame.uniforms.data(), frame.uniforms.size());
    }
    if (Status e = EnsurePool(c, frame, f, allocations); !e.ok()) {
        return e;
    }
    // Descriptor sets per draw, written before recording.
    f.sets.assign(frame.passes.size(), {});
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

Status PrepareFrame(Renderer::State& s, const Frame& frame, FrameObjects& f) {
    uint32_t allocations = 0;
    if (Status e = CreateTargets(s, frame, f, allocations); !e.ok()) {
        return e;
    }
    return PrepareDraws(s.context, frame, f, allocations);
}

std::string ShapeOf(const Frame& frame) {
    std::string out = std::to_string(frame.width) + "x" + std::to_string(frame.height);
    for (const FrameTarget& t : frame.targets) {
        out += "|t" + std::to_string(int(t.format)) + "," + std::to_string(t.depth) + "," +
               std::to_string(int(t.samples)) + "," + std::to_string(t.size) + "," +
               std::to_string(t.cube) + "," + std::to_string(t.shadow_map);
    }
    auto list = [](const std::vector<uint32_t>& v) {
        std::string l;
        for (uint32_t x : v) {
            l += std::to_string(x) + ";";
        }
        return l;
    };
    for (const FramePass& p : frame.passes) {
        out += "|p" + list(p.colors) + "," + (p.depth ? std::to_string(*p.depth) : "-") + "," +
               list(p.resolves) + "," + std::to_string(p.layer) + "," + std::to_string(p.clear) +
               "," + std::to_string(p.depth_read_only) + "," +
               (p.copy_from ? std::to_string(*p.copy_from) : "-");
    }
    return out;
}

}  // namespace kiln::runtime
