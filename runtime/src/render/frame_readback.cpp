// Reading a frame's targets back to the host: the output image, and every target after each step
// for the frame debugger.
#include <cmath>
#include <cstring>

#include "render/frame_internal.h"

namespace kiln::runtime {

std::vector<float> TargetFloats(const FrameTarget& t, std::span<const uint8_t> bytes) {
    const bool f32 = t.format == VK_FORMAT_R32G32B32A32_SFLOAT;
    std::vector<float> out(bytes.size() / (f32 ? 4 : 2));
    for (size_t i = 0; i < out.size(); ++i) {
        if (f32) {
            std::memcpy(&out[i], bytes.data() + i * 4, 4);
        } else {
            uint16_t half;
            std::memcpy(&half, bytes.data() + i * 2, 2);
            out[i] = HalfToFloat(half);
        }
    }
    return out;
}

namespace {

float SrgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

uint16_t FloatToHalf(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    const uint16_t sign = uint16_t((bits >> 16) & 0x8000);
    const uint32_t abs = bits & 0x7FFFFFFFu;
    if (abs > 0x7F800000u) {
        return uint16_t(sign | 0x7E00);  // NaN
    }
    if (abs >= 0x477FF000u) {  // rounds to 65520 or more: infinity
        return uint16_t(sign | 0x7C00);
    }
    if (abs < 0x38800000u) {  // below 2^-14: a subnormal half (or zero)
        if (abs < 0x33000000u) {
            return sign;  // below half the smallest subnormal
        }
        const uint32_t mant = (abs & 0x7FFFFF) | 0x800000;
        const uint32_t shift = 126 - (abs >> 23);  // the half is mant x 2^(exp - 126)
        const uint32_t half = mant >> shift;
        const uint32_t rest = mant & ((1u << shift) - 1), mid = 1u << (shift - 1);
        uint32_t h = half;
        if (rest > mid || (rest == mid && (h & 1))) {
            ++h;
        }
        return uint16_t(sign | h);
    }
    uint32_t h = ((abs >> 23) - 112) << 10 | ((abs >> 13) & 0x3FF);
    const uint32_t rest = abs & 0x1FFF;
    if (rest > 0x1000 || (rest == 0x1000 && (h & 1))) {
        ++h;  // may carry into the exponent: still the nearest
    }
    return uint16_t(sign | h);
}

uint32_t DecodedChannels(const FrameTarget& t) {
    return t.depth || t.format == VK_FORMAT_R8_UNORM ? 1 : 4;
}

std::vector<float> DecodeTexels(const FrameTarget& t, const std::vector<uint8_t>& bytes) {
    if (t.format == VK_FORMAT_R16G16B16A16_SFLOAT || t.format == VK_FORMAT_R32G32B32A32_SFLOAT) {
        return TargetFloats(t, bytes);
    }
    std::vector<float> out;
    if (t.format == VK_FORMAT_R8_UNORM) {
        for (uint8_t v : bytes) {
            out.push_back(float(v) / 255.0f);
        }
        return out;
    }
    const size_t size = t.format == VK_FORMAT_D16_UNORM ? 2 : 4;
    for (size_t i = 0; i + size <= bytes.size(); i += size) {
        uint32_t bits = 0;
        std::memcpy(&bits, bytes.data() + i, size);
        switch (t.format) {
            case VK_FORMAT_D16_UNORM:
                out.push_back(float(bits) / 65535.0f);
                break;
            case VK_FORMAT_D24_UNORM_S8_UINT:
                out.push_back(float(bits & 0xFFFFFFu) / 16777215.0f);
                break;
            case VK_FORMAT_D32_SFLOAT:
            case VK_FORMAT_D32_SFLOAT_S8_UINT: {
                float z;
                std::memcpy(&z, &bits, 4);
                out.push_back(z);
                break;
            }
            case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
                out.insert(out.end(),
                           {float(bits & 0x3FF) / 1023.0f, float((bits >> 10) & 0x3FF) / 1023.0f,
                            float((bits >> 20) & 0x3FF) / 1023.0f, float(bits >> 30) / 3.0f});
                break;
            default: {  // 8-bit RGBA, sRGB or UNORM
                const bool srgb = t.format == VK_FORMAT_R8G8B8A8_SRGB;
                for (int c = 0; c < 4; ++c) {
                    const float v = float((bits >> (8 * c)) & 0xFF) / 255.0f;
                    out.push_back(srgb && c < 3 ? SrgbToLinear(v) : v);
                }
            }
        }
    }
    return out;
}

uint32_t TexelBytes(const FrameTarget& t) {
    switch (t.format) {
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return 16;
        case VK_FORMAT_R16G16B16A16_SFLOAT:
            return 8;
        case VK_FORMAT_R8_UNORM:
            return 1;  // the screen-space shadows
        case VK_FORMAT_D16_UNORM:
            return 2;  // a shadow map where the device lacks D32
        default:
            return 4;  // RGBA8, A2B10G10R10, and a depth aspect (D32 float or D24 in 32 bits)
    }
}

void RecordTargetCopy(VkCommandBuffer cmd,
                      const Frame& frame,
                      const FrameObjects& f,
                      uint32_t t,
                      uint32_t layer,
                      VkImageLayout layout,
                      VkBuffer dst) {
    const FrameTarget& target = frame.targets[t];
    const VkExtent2D extent = ExtentOf(frame, target);
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    b.oldLayout = layout;
    b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = f.targets[t].image;
    b.subresourceRange = {AspectsOf(target), 0, 1, layer, 1};  // the face the pass drew
    const VkPipelineStageFlags before =
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    vkCmdPipelineBarrier(cmd, before, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1,
                         &b);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {target.depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT,
                             0, layer, 1};
    copy.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, f.targets[t].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, 1,
                           &copy);
    // Back where the frame left it, for the steps after this one.
    b.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    b.dstAccessMask = 0;
    b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    b.newLayout = layout;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &b);
    VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &to_host, 0, nullptr, 0, nullptr);
}

Status ReadTarget(const vk::Context& c,
                  const Frame& frame,
                  const FrameObjects& f,
                  uint32_t t,
                  uint32_t layer,
                  VkImageLayout layout,
                  std::vector<uint8_t>& out) {
    const FrameTarget& target = frame.targets[t];
    const VkExtent2D extent = ExtentOf(frame, target);
    const VkDeviceSize size = VkDeviceSize{extent.width} * extent.height * TexelBytes(target);
    vk::Buffer staging;
    if (Status e = vk::CreateBuffer(c, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, staging); !e.ok()) {
        return e;
    }
    auto e = vk::SubmitOnce(c, [&](VkCommandBuffer cmd) {
        RecordTargetCopy(cmd, frame, f, t, layer, layout, staging.buffer);
    });
    if (e.ok()) {
        const auto* p = static_cast<const uint8_t*>(staging.mapped);
        out.assign(p, p + size);
    }
    vk::DestroyBuffer(c, staging);
    return e;
}

Status ReadOutput(const vk::Context& c,
                  const Frame& frame,
                  const FrameObjects& f,
                  VkImageLayout layout,
                  LinearImage& out) {
    std::vector<uint8_t> bytes;
    if (Status e = ReadTarget(c, frame, f, frame.output, 0, layout, bytes); !e.ok()) {
        return e;
    }
    out.width = frame.width;
    out.height = frame.height;
    out.rgba = TargetFloats(frame.targets[frame.output], bytes);
    return {};
}

}  // namespace kiln::runtime
