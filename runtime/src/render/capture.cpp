#include "render/capture.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "render/frame_internal.h"

namespace kiln::runtime {
namespace {

uint8_t Byte(double v) {
    return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

// Depth as distance from the camera, shown near white to far dark grey; nothing drawn is black.
// A shadow map (drawn from a light, not the camera) shows its stored depth the same way.
// `stored`: the target's depths as DecodeTexels gives them.
std::vector<uint8_t> DepthImage(const FrameTarget& t,
                                const std::vector<float>& stored,
                                const glm::mat4& inverse_projection) {
    const size_t n = stored.size();
    std::vector<double> distance(n, -1.0);
    double lo = 1e300, hi = -1e300;
    for (size_t i = 0; i < n; ++i) {
        const float z = stored[i];
        if (!(z < 1.0f)) {
            continue;  // the clear value: nothing drawn
        }
        double d = double(z);
        if (!t.shadow_map) {
            const glm::vec4 v = inverse_projection * glm::vec4(0, 0, z, 1);
            d = std::abs(double(v.w)) > 0 ? -double(v.z) / double(v.w) : 0.0;
        }
        distance[i] = d;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    std::vector<uint8_t> out(n * 4, 0);
    for (size_t i = 0; i < n; ++i) {
        const double k = distance[i] < 0 ? 0.0
                         : hi > lo       ? 1.0 - 0.8 * (distance[i] - lo) / (hi - lo)
                                         : 1.0;
        out[i * 4] = out[i * 4 + 1] = out[i * 4 + 2] = Byte(k);
        out[i * 4 + 3] = 255;
    }
    return out;
}

// A colour target as stored: UNORM and sRGB bytes as they are, 10-bit and float channels scaled
// to bytes; alpha opaque.
std::vector<uint8_t> StoredImage(const FrameTarget& t, const std::vector<uint8_t>& bytes) {
    std::vector<uint8_t> out;
    if (t.format == VK_FORMAT_A2B10G10R10_UNORM_PACK32) {
        for (size_t i = 0; i + 4 <= bytes.size(); i += 4) {
            uint32_t v;
            std::memcpy(&v, bytes.data() + i, 4);
            out.insert(out.end(), {Byte((v & 0x3FF) / 1023.0), Byte(((v >> 10) & 0x3FF) / 1023.0),
                                   Byte(((v >> 20) & 0x3FF) / 1023.0), 255});
        }
    } else if (t.format == VK_FORMAT_R16G16B16A16_SFLOAT ||
               t.format == VK_FORMAT_R32G32B32A32_SFLOAT) {
        const std::vector<float> f = TargetFloats(t, bytes);
        for (size_t i = 0; i + 4 <= f.size(); i += 4) {
            out.insert(out.end(), {Byte(f[i]), Byte(f[i + 1]), Byte(f[i + 2]), 255});
        }
    } else if (t.format == VK_FORMAT_R8_UNORM) {  // one channel, shown grey
        for (uint8_t v : bytes) {
            out.insert(out.end(), {v, v, v, 255});
        }
    } else {  // 8-bit RGBA, sRGB or UNORM
        out = bytes;
        for (size_t i = 3; i < out.size(); i += 4) {
            out[i] = 255;
        }
    }
    return out;
}

// The target's values for the readout: four channels as halves, one as floats.
void StoreValues(const FrameTarget& t, const std::vector<uint8_t>& bytes, DebugImage& out) {
    if (DecodedChannels(t) == 1) {
        out.single = DecodeTexels(t, bytes);
        return;
    }
    if (t.format == VK_FORMAT_R16G16B16A16_SFLOAT) {  // already halves: as stored
        out.half.resize(bytes.size() / 2);
        std::memcpy(out.half.data(), bytes.data(), out.half.size() * 2);
        return;
    }
    const std::vector<float> values = DecodeTexels(t, bytes);
    out.half.reserve(values.size());
    for (float v : values) {
        out.half.push_back(FloatToHalf(v));
    }
}

// The format's name without VK_FORMAT_, for the frame debugger.
std::string FormatName(VkFormat f) {
    switch (f) {
        case VK_FORMAT_R8G8B8A8_SRGB:
            return "R8G8B8A8_SRGB";
        case VK_FORMAT_R8G8B8A8_UNORM:
            return "R8G8B8A8_UNORM";
        case VK_FORMAT_R8_UNORM:
            return "R8_UNORM";
        case VK_FORMAT_R16G16B16A16_SFLOAT:
            return "R16G16B16A16_SFLOAT";
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return "R32G32B32A32_SFLOAT";
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
            return "A2B10G10R10_UNORM_PACK32";
        case VK_FORMAT_D32_SFLOAT:
            return "D32_SFLOAT";
        case VK_FORMAT_D16_UNORM:
            return "D16_UNORM";
        case VK_FORMAT_D32_SFLOAT_S8_UINT:
            return "D32_SFLOAT_S8_UINT";
        case VK_FORMAT_D24_UNORM_S8_UINT:
            return "D24_UNORM_S8_UINT";
        case VK_FORMAT_UNDEFINED:
            return "";
        default:
            return "VkFormat " + std::to_string(int(f));
    }
}

}  // namespace

StepObserver CaptureObserver(const glm::mat4& projection,
                             const ColorPipeline& color,
                             FrameCapture& out) {
    const glm::mat4 inverse = glm::inverse(projection);
    return [inverse, &color, &out](const Frame& frame, size_t p, int draw,
                                   std::vector<CapturedTarget> targets, double gpu_ms) -> Status {
        out.width = frame.width;
        out.height = frame.height;
        const FramePass& pass = frame.passes[p];
        DebugStep& step = out.steps.emplace_back();
        step.pass = pass.name;
        step.draw = draw;
        step.gpu_ms = gpu_ms;
        if (pass.copy_from) {
            step.copy =
                frame.targets[*pass.copy_from].name + " -> " + frame.targets[pass.colors[0]].name;
        }
        if (draw >= 0) {
            const Draw::Info& info = pass.draws[size_t(draw)].info;
            step.shader = info.shader;
            step.shader_pass = info.pass;
            step.light_mode = info.light_mode;
            step.keywords = info.keywords;
            step.state = info.state;
            step.light = info.light;
            step.object = info.object;
            step.mesh = info.mesh;
            step.vertex_count = info.vertex_count;
            step.index_count = info.index_count;
            step.values = info.values;
            for (const Draw::Info::Texture& t : info.textures) {
                DebugTexture& dt = step.textures.emplace_back();
                dt.name = t.name;
                dt.source = t.source;
                dt.width = t.width;
                dt.height = t.height;
                dt.format = FormatName(t.format);
                if (t.thumbnail && !t.thumbnail->rgba8.empty()) {
                    dt.thumbnail = {t.name, t.thumbnail->width, t.thumbnail->height,
                                    t.thumbnail->rgba8};
                }
            }
        }
        for (const CapturedTarget& ct : targets) {
            const FrameTarget& t = frame.targets[ct.target];
            DebugImage& image = step.images.emplace_back();
            image.target = t.cube ? t.name + " (face " + std::to_string(ct.layer) + ")" : t.name;
            image.width = ct.width;
            image.height = ct.height;
            StoreValues(t, ct.bytes, image);
            image.depth = t.depth;
            if (t.depth) {
                image.rgba8 = DepthImage(t, image.single, inverse);  // decoded once
            } else if (t.display && (t.format == VK_FORMAT_R16G16B16A16_SFLOAT ||
                                     t.format == VK_FORMAT_R32G32B32A32_SFLOAT)) {
                std::vector<float> linear = TargetFloats(t, ct.bytes);
                color.ApplyDisplay(linear);
                image.rgba8 = ColorPipeline::Quantize(linear);
                for (size_t i = 3; i < image.rgba8.size(); i += 4) {
                    image.rgba8[i] = 255;
                }
            } else {
                image.rgba8 = StoredImage(t, ct.bytes);
            }
        }
        return {};
    };
}

}  // namespace kiln::runtime
