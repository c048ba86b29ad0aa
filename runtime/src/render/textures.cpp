#include "render/textures.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "kiln/runtime/image.h"
#include "render/frame_values.h"
#include "render/reflection_probe.h"

namespace kiln::runtime {
namespace {

const char* ShapeName(vk::ImageShape shape) {
    switch (shape) {
        case vk::ImageShape::k2D:
            return "2D";
        case vk::ImageShape::k3D:
            return "3D";
        case vk::ImageShape::kCube:
            return "cube";
        case vk::ImageShape::k2DArray:
            return "2D-array";
        case vk::ImageShape::kCubeArray:
            return "cube-array";
    }
    return "?";
}

// Halves an RGBA8 image (2x2 box filter, odd edges clamped) until both sides fit `limit`, the
// device's maxImageDimension2D. Averages the stored values: for sRGB images this darkens
// high-contrast detail slightly, acceptable for an image the device cannot hold at all.
bool FitToLimit(uint32_t& w, uint32_t& h, std::vector<uint8_t>& rgba, uint32_t limit) {
    bool changed = false;
    while (w > limit || h > limit) {
        const uint32_t nw = std::max(1u, w / 2), nh = std::max(1u, h / 2);
        std::vector<uint8_t> out(size_t(nw) * nh * 4);
        for (uint32_t y = 0; y < nh; ++y) {
            for (uint32_t x = 0; x < nw; ++x) {
                for (uint32_t c = 0; c < 4; ++c) {
                    uint32_t sum = 0;
                    for (uint32_t dy = 0; dy < 2; ++dy) {
                        for (uint32_t dx = 0; dx < 2; ++dx) {
                            const uint32_t sx = std::min(w - 1, x * 2 + dx);
                            const uint32_t sy = std::min(h - 1, y * 2 + dy);
                            sum += rgba[(size_t(sy) * w + sx) * 4 + c];
                        }
                    }
                    out[(size_t(y) * nw + x) * 4 + c] = uint8_t((sum + 2) / 4);
                }
            }
        }
        rgba = std::move(out);
        w = nw;
        h = nh;
        changed = true;
    }
    return changed;
}

}  // namespace

std::optional<vk::ImageShape> ShapeOf(const pack::ResourceRec& resource) {
    const bool arrayed = resource.arrayed != 0;
    switch (pack::ImageDim(resource.dim)) {
        case pack::ImageDim::k2D:
            return arrayed ? vk::ImageShape::k2DArray : vk::ImageShape::k2D;
        case pack::ImageDim::k3D:
            return vk::ImageShape::k3D;
        case pack::ImageDim::kCube:
            return arrayed ? vk::ImageShape::kCubeArray : vk::ImageShape::kCube;
        default:
            return std::nullopt;
    }
}

TextureBinding UnsetTexture(std::string_view name) {
    TextureBinding binding;
    // The one reflection probe is the scene's ambient (render/reflection_probe.h), which is also
    // what the spherical harmonics (unity_SH*) hold, so diffuse and specular ambient agree.
    if (name == "unity_SpecCube0" || name == "unity_SpecCube1") {
        binding.source = TextureBinding::Source::kAmbient;
    }
    return binding;
}

FrameTextures::~FrameTextures() {
    for (auto& [key, uploaded] : images_) {
        vk::DestroyImage(s_.context, uploaded.image);
    }
    for (auto& [shape, image] : ambient_) {
        vk::DestroyImage(s_.context, image);
    }
}

Status FrameTextures::Ambient(vk::ImageShape shape, BoundTexture& out) {
    const AmbientKey key{scene_->ambient_mode, scene_->ambient, scene_->ambient_equator,
                         scene_->ambient_ground, SkyOf(*scene_)};
    if (!(key == ambient_key_)) {  // the scene's ambient changed since the last frame
        for (auto& [old_shape, image] : ambient_) {
            vk::DestroyImage(s_.context, image);
        }
        ambient_.clear();
        ambient_key_ = key;
    }
    auto it = ambient_.find(shape);
    if (it == ambient_.end()) {
        // Linear radiance above 1 needs a float texel; RGBA16F is filterable on every device.
        // A cube is the reflection probe (render/reflection_probe.h), prefiltered per roughness
        // mip; other shapes hold the mean radiance.
        auto half4 = [](const glm::vec3& radiance, std::vector<uint8_t>& bytes_out) {
            std::array<uint16_t, 4> half{};
            for (int i = 0; i < 3; ++i) {
                // guard: beyond binary16's largest value the texel would be infinite
                half[size_t(i)] = glm::packHalf1x16(std::min(radiance[i], 65504.0f));
            }
            half[3] = glm::packHalf1x16(1.0f);
            const auto* bytes = reinterpret_cast<const uint8_t*>(half.data());
            bytes_out.insert(bytes_out.end(), bytes, bytes + 8);
        };
        std::vector<uint8_t> texels;
        vk::Image image;
        if (shape == vk::ImageShape::kCube || shape == vk::ImageShape::kCubeArray) {
            const ReflectionProbe probe = MakeReflectionProbe(*scene_);
            for (const std::vector<glm::vec3>& level : probe.texels) {
                for (const glm::vec3& t : level) {
                    half4(t, texels);
                }
            }
            if (Status e = vk::CreateCubeImage(s_.context, shape, probe.size, probe.mips,
                                               VK_FORMAT_R16G16B16A16_SFLOAT, texels, image);
                !e.ok()) {
                return e;
            }
        } else {
            half4(MeanAmbient(*scene_), texels);
            if (Status e = vk::CreateConstantImage(s_.context, shape, VK_FORMAT_R16G16B16A16_SFLOAT,
                                                   texels, image);
                !e.ok()) {
                return e;
            }
        }
        it = ambient_.emplace(shape, image).first;
    }
    if (Status e =
            s_.Sampler(TextureWrap::kClampToEdge, TextureWrap::kClampToEdge, false, out.sampler);
        !e.ok()) {
        return e;
    }
    out.view = it->second.view;
    out.width = it->second.width;
    out.height = it->second.height;
    out.format = it->second.format;
    out.source = shape == vk::ImageShape::kCube ? "the scene's ambient (reflection probe)"
                                                : "the scene's ambient (mean radiance)";
    return {};
}

namespace {

// `rgba` (w x h) averaged down to at most Thumbnail::kThumbnailSize texels a side.
std::shared_ptr<const Thumbnail> MakeThumbnail(uint32_t w,
                                               uint32_t h,
                                               const std::vector<uint8_t>& rgba) {
    auto t = std::make_shared<Thumbnail>();
    if (w == 0 || h == 0 || rgba.size() < size_t(w) * h * 4) {
        return t;
    }
    const uint32_t step =
        std::max((std::max(w, h) + Thumbnail::kThumbnailSize - 1) / Thumbnail::kThumbnailSize, 1u);
    t->width = (w + step - 1) / step;
    t->height = (h + step - 1) / step;
    t->rgba8.resize(size_t(t->width) * t->height * 4);
    for (uint32_t y = 0; y < t->height; ++y) {
        for (uint32_t x = 0; x < t->width; ++x) {
            uint32_t sum[4] = {0, 0, 0, 0}, n = 0;
            for (uint32_t sy = y * step; sy < std::min(h, (y + 1) * step); ++sy) {
                for (uint32_t sx = x * step; sx < std::min(w, (x + 1) * step); ++sx, ++n) {
                    for (int c = 0; c < 4; ++c) {
                        sum[c] += rgba[(size_t(sy) * w + sx) * 4 + size_t(c)];
                    }
                }
            }
            for (int c = 0; c < 4; ++c) {
                t->rgba8[(size_t(y) * t->width + x) * 4 + size_t(c)] =
                    uint8_t(n ? (sum[c] + n / 2) / n : 0);
            }
        }
    }
    return t;
}

}  // namespace

Status FrameTextures::Default(const TextureBinding& binding,
                              vk::ImageShape shape,
                              std::string warning,
                              BoundTexture& out) {
    const vk::Image* image = nullptr;
    if (Status e = s_.DefaultTexture(binding.default_name, shape, image); !e.ok()) {
        return e;
    }
    if (Status e = s_.Sampler(TextureWrap::kRepeat, TextureWrap::kRepeat, false, out.sampler);
        !e.ok()) {
        return e;
    }
    out.view = image->view;
    out.width = out.height = 1;
    out.format = image->format;
    out.source = "default '" + binding.default_name + "'";
    out.warning = std::move(warning);
    return {};
}

Status FrameTextures::Get(const TextureBinding& binding, vk::ImageShape shape, BoundTexture& out) {
    out = BoundTexture{};
    if (binding.source == TextureBinding::Source::kAmbient) {
        return Ambient(shape, out);
    }
    if (binding.source == TextureBinding::Source::kDefault) {
        return Default(binding, shape, {}, out);
    }
    if (shape != vk::ImageShape::k2D) {
        return Default(binding, shape,
                       std::string("the shader declares a ") + ShapeName(shape) +
                           " texture and images are 2D; using the default " + ShapeName(shape) +
                           " texture",
                       out);
    }
    std::string key;
    if (binding.source == TextureBinding::Source::kSceneImage) {
        if (binding.image < 0 || size_t(binding.image) >= scene_->images.size() ||
            scene_->images[size_t(binding.image)].rgba8.empty()) {
            return Default(binding, shape,
                           "image " + std::to_string(binding.image) +
                               " has no pixels; using the default texture",
                           out);
        }
        key = "#" + std::to_string(binding.image);
    } else {
        key = binding.file;
    }
    if (Status e = s_.Sampler(binding.wrap_u, binding.wrap_v, binding.nearest, out.sampler);
        !e.ok()) {
        return e;
    }
    auto it = images_.find({key, binding.srgb});
    if (it == images_.end()) {
        uint32_t w = 0, h = 0;
        std::vector<uint8_t> rgba;
        std::string name;
        if (binding.source == TextureBinding::Source::kSceneImage) {
            const SceneImage& si = scene_->images[size_t(binding.image)];
            w = si.width;
            h = si.height;
            rgba = si.rgba8;
            name = "image " + std::to_string(binding.image) + " '" + si.name + "'";
        } else {
            Result<Rgba8Image> decoded = ReadImageRgba8(binding.file);
            if (!decoded) {
                return Default(binding, shape,
                               decoded.error().message + "; using the default texture", out);
            }
            w = decoded.value().width;
            h = decoded.value().height;
            rgba = std::move(decoded.value().rgba);
            name = "'" + binding.file + "'";
        }
        const uint32_t limit = s_.context.properties.limits.maxImageDimension2D;
        const uint32_t w0 = w, h0 = h;
        std::string warning;
        if (FitToLimit(w, h, rgba, limit)) {
            warning = name + " is " + std::to_string(w0) + "x" + std::to_string(h0) +
                      ", larger than the device's limit of " + std::to_string(limit) +
                      "; downscaled to " + std::to_string(w) + "x" + std::to_string(h);
        }
        vk::Image image;
        if (Status e = vk::CreateTexture(s_.context, w, h, rgba, binding.srgb, image); !e.ok()) {
            return e;
        }
        it = images_
                 .emplace(
                     std::pair{key, binding.srgb},
                     Uploaded{image, warning,
                              (binding.source == TextureBinding::Source::kSceneImage ? "glTF "
                                                                                     : "file ") +
                                  name,
                              MakeThumbnail(w, h, rgba)})
                 .first;
    }
    out.view = it->second.image.view;
    out.width = it->second.image.width;
    out.height = it->second.image.height;
    out.format = it->second.image.format;
    out.source = it->second.source;
    out.thumbnail = it->second.thumbnail;
    out.warning = it->second.warning;
    return {};
}

}  // namespace kiln::runtime
