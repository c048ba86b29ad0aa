#include "vk/render_pass.h"

namespace kiln::vk {

namespace {

// One attachment of `format`, cleared (from undefined) or loaded (in `layout`), left in `layout`.
// Depth-stencil attachments keep their stencil too.
VkAttachmentDescription Attachment(VkFormat format,
                                   bool clear,
                                   VkImageLayout layout,
                                   bool depth,
                                   VkSampleCountFlagBits samples) {
    const VkAttachmentLoadOp load =
        clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    VkAttachmentDescription a{};
    a.format = format;
    a.samples = samples;
    a.loadOp = load;
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    a.stencilLoadOp = depth ? load : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    a.stencilStoreOp = depth ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a.initialLayout = clear ? VK_IMAGE_LAYOUT_UNDEFINED : layout;
    a.finalLayout = layout;
    return a;
}

}  // namespace

Status CreateRenderPass(const Context& c,
                        const TargetFormats& formats,
                        bool clear,
                        bool depth_read_only,
                        VkRenderPass& out) {
    const VkImageLayout depth_layout =
        depth_read_only ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL
                        : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    std::vector<VkAttachmentDescription> attachments;
    std::vector<VkAttachmentReference> colors;
    for (VkFormat f : formats.colors) {
        colors.push_back({uint32_t(attachments.size()), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
        attachments.push_back(
            Attachment(f, clear, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, false, formats.samples));
    }
    VkAttachmentReference depth{uint32_t(attachments.size()), depth_layout};
    if (formats.depth != VK_FORMAT_UNDEFINED) {
        VkAttachmentDescription a = Attachment(formats.depth, clear && !depth_read_only,
                                               depth_layout, true, formats.samples);
        if (depth_read_only) {
            // The depth is kept; the stencil starts cleared, for the pass's own masks.
            a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
            a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        }
        attachments.push_back(a);
    }
    std::vector<VkAttachmentReference> resolves;
    if (formats.resolve) {
        for (VkFormat f : formats.colors) {
            resolves.push_back(
                {uint32_t(attachments.size()), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
            // Written whole by the resolve: nothing to load or clear.
            VkAttachmentDescription a = Attachment(
                f, true, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, false, VK_SAMPLE_COUNT_1_BIT);
            a.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
            attachments.push_back(a);
        }
    }
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = uint32_t(colors.size());
    subpass.pColorAttachments = colors.data();
    subpass.pResolveAttachments = resolves.empty() ? nullptr : resolves.data();
    subpass.pDepthStencilAttachment = formats.depth != VK_FORMAT_UNDEFINED ? &depth : nullptr;

    const VkPipelineStageFlags attachment_stages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    const VkAccessFlags attachment_writes =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    const VkAccessFlags attachment_access = attachment_writes |
                                            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    VkSubpassDependency deps[2]{};
    // The previous pass's writes before this pass's attachment reads and writes.
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask = attachment_stages;
    deps[0].dstStageMask = attachment_stages;
    deps[0].srcAccessMask = attachment_writes;
    deps[0].dstAccessMask = attachment_access;
    // This pass's writes before what follows: another pass, sampling, or the read-back copy.
    deps[1].srcSubpass = 0;
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask = attachment_stages;
    deps[1].dstStageMask =
        attachment_stages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    deps[1].srcAccessMask = attachment_writes;
    deps[1].dstAccessMask =
        attachment_access | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = uint32_t(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 2;
    info.pDependencies = deps;
    if (VkResult r = vkCreateRenderPass(c.device, &info, nullptr, &out); r != VK_SUCCESS) {
        return VkError("cannot create a render pass", r);
    }
    return {};
}

}  // namespace kiln::vk
