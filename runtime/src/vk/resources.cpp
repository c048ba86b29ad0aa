#include "vk/resources.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

namespace kiln::vk {
namespace {

std::optional<uint32_t> FindMemoryType(const Context& c,
                                       uint32_t type_bits,
                                       VkMemoryPropertyFlags wanted) {
    for (uint32_t i = 0; i < c.memory.memoryTypeCount; ++i) {
        if ((type_bits & (1u << i)) && (c.memory.memoryTypes[i].propertyFlags & wanted) == wanted) {
            return i;
        }
    }
    return std::nullopt;
}

Status Allocate(const Context& c,
                const VkMemoryRequirements& req,
                VkMemoryPropertyFlags wanted,
                VkDeviceMemory& out) {
    auto type = FindMemoryType(c, req.memoryTypeBits, wanted);
    if (!type) {
        type = FindMemoryType(c, req.memoryTypeBits, 0);
    }
    if (!type) {
        return Error{DiagCode::kRenderFailed, "no suitable Vulkan memory type"};
    }
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = req.size;
    info.memoryTypeIndex = *type;
    if (VkResult r = vkAllocateMemory(c.device, &info, nullptr, &out); r != VK_SUCCESS) {
        return VkError("cannot allocate device memory", r);
    }
    return {};
}

// Creates `info`'s image in device-local memory and a view of every mip level and layer.
Status CreateImageAndView(const Context& c,
                          const VkImageCreateInfo& info,
                          VkImageViewType view_type,
                          VkImageAspectFlags aspect,
                          Image& img) {
    if (VkResult r = vkCreateImage(c.device, &info, nullptr, &img.image); r != VK_SUCCESS) {
        return VkError("cannot create an image", r);
    }
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(c.device, img.image, &req);
    if (Status e = Allocate(c, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, img.memory); !e.ok()) {
        DestroyImage(c, img);
        return e;
    }
    vkBindImageMemory(c.device, img.image, img.memory, 0);
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = img.image;
    view.viewType = view_type;
    view.format = info.format;
    view.subresourceRange = {aspect, 0, info.mipLevels, 0, info.arrayLayers};
    if (VkResult r = vkCreateImageView(c.device, &view, nullptr, &img.view); r != VK_SUCCESS) {
        DestroyImage(c, img);
        return VkError("cannot create an image view", r);
    }
    return {};
}

}  // namespace

Status CreateBuffer(const Context& c, VkDeviceSize size, VkBufferUsageFlags usage, Buffer& out) {
    Buffer b;
    b.size = std::max<VkDeviceSize>(size, 4);
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = b.size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    if (VkResult r = vkCreateBuffer(c.device, &info, nullptr, &b.buffer); r != VK_SUCCESS) {
        return VkError("cannot create a buffer", r);
    }
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(c.device, b.buffer, &req);
    const VkMemoryPropertyFlags host =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    if (!FindMemoryType(c, req.memoryTypeBits, host)) {
        DestroyBuffer(c, b);
        return Error{DiagCode::kRenderFailed, "no host-visible coherent memory for a buffer"};
    }
    if (Status e = Allocate(c, req, host, b.memory); !e.ok()) {
        DestroyBuffer(c, b);
        return e;
    }
    vkBindBufferMemory(c.device, b.buffer, b.memory, 0);
    if (VkResult r = vkMapMemory(c.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped);
        r != VK_SUCCESS) {
        DestroyBuffer(c, b);
        return VkError("cannot map a buffer", r);
    }
    out = b;
    return {};
}

Status CreateBufferWithData(const Context& c,
                            std::span<const uint8_t> data,
                            VkBufferUsageFlags usage,
                            Buffer& out) {
    if (Status e = CreateBuffer(c, data.size(), usage, out); !e.ok()) {
        return e;
    }
    if (!data.empty()) {
        std::memcpy(out.mapped, data.data(), data.size());
    }
    return {};
}

void DestroyBuffer(const Context& c, Buffer& b) {
    if (b.buffer) {
        vkDestroyBuffer(c.device, b.buffer, nullptr);
    }
    if (b.memory) {
        vkFreeMemory(c.device, b.memory, nullptr);  // unmaps implicitly
    }
    b = Buffer{};
}

Status CreateImage(const Context& c,
                   uint32_t width,
                   uint32_t height,
                   VkFormat format,
                   VkImageUsageFlags usage,
                   VkImageAspectFlags aspect,
                   Image& out,
                   uint32_t mip_levels,
                   VkSampleCountFlagBits samples) {
    Image img;
    img.format = format;
    img.width = width;
    img.height = height;
    img.mip_levels = mip_levels;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = mip_levels;
    info.arrayLayers = 1;
    info.samples = samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (Status e = CreateImageAndView(c, info, VK_IMAGE_VIEW_TYPE_2D, aspect, img); !e.ok()) {
        return e;
    }
    out = img;
    return {};
}

Status CreateShadowMap(const Context& c, uint32_t size, VkFormat format, bool cube, Image& out) {
    Image img;
    img.format = format;
    img.width = img.height = size;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {size, size, 1};
    info.mipLevels = 1;
    info.arrayLayers = cube ? 6 : 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    // Transfer source: the frame debugger reads each face back.
    info.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                 VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (Status e =
            CreateImageAndView(c, info, cube ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D,
                               VK_IMAGE_ASPECT_DEPTH_BIT, img);
        !e.ok()) {
        return e;
    }
    out = img;
    return {};
}

void DestroyImage(const Context& c, Image& img) {
    if (img.view) {
        vkDestroyImageView(c.device, img.view, nullptr);
    }
    if (img.image) {
        vkDestroyImage(c.device, img.image, nullptr);
    }
    if (img.memory) {
        vkFreeMemory(c.device, img.memory, nullptr);
    }
    img = Image{};
}

void ImageBarrier(VkCommandBuffer cmd,
                  VkImage image,
                  VkImageAspectFlags aspect,
                  VkImageLayout from,
                  VkImageLayout to,
                  VkAccessFlags src_access,
                  VkAccessFlags dst_access,
                  VkPipelineStageFlags src_stage,
                  VkPipelineStageFlags dst_stage,
                  uint32_t base_mip,
                  uint32_t mip_count) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = src_access;
    b.dstAccessMask = dst_access;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, base_mip, mip_count, 0, VK_REMAINING_ARRAY_LAYERS};
    vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

Status CreateTexture(const Context& c,
                     uint32_t width,
                     uint32_t height,
                     std::span<const uint8_t> rgba8,
                     bool srgb,
                     Image& out) {
    if (width == 0 || height == 0 || rgba8.size() != size_t{width} * height * 4) {
        return Error{DiagCode::kRenderFailed, "texture data does not match its size"};
    }
    const VkFormat format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(c.physical, format, &props);
    const bool can_blit =
        (props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_SRC_BIT) &&
        (props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT) &&
        (props.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT);
    const uint32_t mips = can_blit ? uint32_t(std::bit_width(std::max(width, height))) : 1;
    Buffer staging;
    if (Status e = CreateBufferWithData(c, rgba8, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging);
        !e.ok()) {
        return e;
    }
    Image img;
    if (Status e = CreateImage(c, width, height, format,
                               VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                   VK_IMAGE_USAGE_SAMPLED_BIT,
                               VK_IMAGE_ASPECT_COLOR_BIT, img, mips);
        !e.ok()) {
        DestroyBuffer(c, staging);
        return e;
    }
    auto e = SubmitOnce(c, [&](VkCommandBuffer cmd) {
        const auto color = VK_IMAGE_ASPECT_COLOR_BIT;
        ImageBarrier(cmd, img.image, color, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {color, 0, 0, 1};
        copy.imageExtent = {width, height, 1};
        vkCmdCopyBufferToImage(cmd, staging.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               1, &copy);
        int32_t w = int32_t(width), h = int32_t(height);
        for (uint32_t level = 1; level < mips; ++level) {
            ImageBarrier(cmd, img.image, color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, level - 1, 1);
            VkImageBlit blit{};
            blit.srcSubresource = {color, level - 1, 0, 1};
            blit.srcOffsets[1] = {w, h, 1};
            w = std::max(1, w / 2);
            h = std::max(1, h / 2);
            blit.dstSubresource = {color, level, 0, 1};
            blit.dstOffsets[1] = {w, h, 1};
            vkCmdBlitImage(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, img.image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
            ImageBarrier(cmd, img.image, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_READ_BIT,
                         VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, level - 1, 1);
        }
        ImageBarrier(cmd, img.image, color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, mips - 1, 1);
    });
    DestroyBuffer(c, staging);
    if (!e.ok()) {
        DestroyImage(c, img);
        return e;
    }
    out = img;
    return {};
}

namespace {

// Copies `texels` into `img` (in UNDEFINED layout) by `copies` and leaves it in
// SHADER_READ_ONLY_OPTIMAL for `out`; on failure `img` is destroyed.
Status FillSampledImage(const Context& c,
                        Image& img,
                        std::span<const uint8_t> texels,
                        const std::vector<VkBufferImageCopy>& copies,
                        Image& out) {
    Buffer staging;
    if (Status e = CreateBufferWithData(c, texels, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging);
        !e.ok()) {
        DestroyImage(c, img);
        return e;
    }
    auto e = SubmitOnce(c, [&](VkCommandBuffer cmd) {
        const auto color = VK_IMAGE_ASPECT_COLOR_BIT;
        ImageBarrier(cmd, img.image, color, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        vkCmdCopyBufferToImage(cmd, staging.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               uint32_t(copies.size()), copies.data());
        ImageBarrier(cmd, img.image, color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
    });
    DestroyBuffer(c, staging);
    if (!e.ok()) {
        DestroyImage(c, img);
        return e;
    }
    out = img;
    return {};
}

}  // namespace

Status CreateConstantImage(const Context& c,
                           ImageShape shape,
                           VkFormat format,
                           std::span<const uint8_t> texel,
                           Image& out) {
    if (shape == ImageShape::kCubeArray && !c.image_cube_array) {
        return Error{DiagCode::kRenderFailed,
                     "the device cannot sample cube-map arrays (imageCubeArray)"};
    }
    const bool cube = shape == ImageShape::kCube || shape == ImageShape::kCubeArray;
    const uint32_t layers = cube ? 6u : 1u;  // a cube array of one cube is six layers
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
    info.imageType = shape == ImageShape::k3D ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {1, 1, 1};
    info.mipLevels = 1;
    info.arrayLayers = layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    static constexpr VkImageViewType kViewTypes[] = {
        VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_VIEW_TYPE_3D, VK_IMAGE_VIEW_TYPE_CUBE,
        VK_IMAGE_VIEW_TYPE_2D_ARRAY, VK_IMAGE_VIEW_TYPE_CUBE_ARRAY};  // by ImageShape
    Image img;
    img.format = format;
    img.width = img.height = 1;
    if (Status e =
            CreateImageAndView(c, info, kViewTypes[size_t(shape)], VK_IMAGE_ASPECT_COLOR_BIT, img);
        !e.ok()) {
        return e;
    }
    const uint32_t texel_size = format == VK_FORMAT_R32G32B32A32_SFLOAT   ? 16u
                                : format == VK_FORMAT_R16G16B16A16_SFLOAT ? 8u
                                                                          : 4u;
    std::vector<uint8_t> texels;
    if (cube && texel.size() == size_t{6} * texel_size) {  // one per face
        for (uint32_t i = 0; i < layers; ++i) {
            texels.insert(texels.end(), texel.begin() + (i % 6) * texel_size,
                          texel.begin() + (i % 6 + 1) * texel_size);
        }
    } else {
        for (uint32_t i = 0; i < layers; ++i) {
            texels.insert(texels.end(), texel.begin(), texel.begin() + texel_size);
        }
    }
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers};
    copy.imageExtent = {1, 1, 1};
    return FillSampledImage(c, img, texels, {copy}, out);
}

Status CreateCubeImage(const Context& c,
                       ImageShape shape,
                       uint32_t size,
                       uint32_t mips,
                       VkFormat format,
                       std::span<const uint8_t> texels,
                       Image& out) {
    if (shape == ImageShape::kCubeArray && !c.image_cube_array) {
        return Error{DiagCode::kRenderFailed,
                     "the device cannot sample cube-map arrays (imageCubeArray)"};
    }
    const size_t texel_size = format == VK_FORMAT_R32G32B32A32_SFLOAT ? 16u : 8u;
    size_t expected = 0;
    for (uint32_t m = 0; m < mips; ++m) {
        const size_t n = std::max(1u, size >> m);
        expected += 6 * n * n * texel_size;
    }
    if (size == 0 || mips == 0 || texels.size() != expected) {
        return Error{DiagCode::kRenderFailed, "a cube image's texels do not match its size"};
    }
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {size, size, 1};
    info.mipLevels = mips;
    info.arrayLayers = 6;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    Image img;
    img.format = format;
    img.width = img.height = size;
    img.mip_levels = mips;
    const VkImageViewType view =
        shape == ImageShape::kCubeArray ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY : VK_IMAGE_VIEW_TYPE_CUBE;
    if (Status e = CreateImageAndView(c, info, view, VK_IMAGE_ASPECT_COLOR_BIT, img); !e.ok()) {
        return e;
    }
    std::vector<VkBufferImageCopy> copies;
    VkDeviceSize offset = 0;
    for (uint32_t m = 0; m < mips; ++m) {
        const uint32_t n = std::max(1u, size >> m);
        VkBufferImageCopy copy{};
        copy.bufferOffset = offset;
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m, 0, 6};
        copy.imageExtent = {n, n, 1};
        copies.push_back(copy);
        offset += VkDeviceSize(6) * n * n * texel_size;
    }
    return FillSampledImage(c, img, texels, copies, out);
}

}  // namespace kiln::vk
