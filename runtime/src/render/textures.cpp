#include "render/textures.h"

#include <stb/stb_image.h>

namespace kiln::render {

FrameTextures::~FrameTextures() {
    for (auto& [key, image] : images_) {
        vk::DestroyImage(s_.context, image);
    }
}

std::optional<runtime::Error> FrameTextures::Default(const TextureBinding& binding,
                                                     std::string warning,
                                                     BoundTexture& out) {
    const vk::Image* image = nullptr;
    if (auto e = s_.DefaultTexture(binding.default_name, image)) {
        return e;
    }
    if (auto e = s_.Sampler(true, false, out.sampler)) {
        return e;
    }
    out.view = image->view;
    out.width = out.height = 1;
    out.warning = std::move(warning);
    return std::nullopt;
}

std::optional<runtime::Error> FrameTextures::Get(const TextureBinding& binding, BoundTexture& out) {
    out = BoundTexture{};
    std::string key;
    if (binding.source == TextureBinding::Source::kSceneImage) {
        if (binding.image < 0 || size_t(binding.image) >= scene_.images.size() ||
            scene_.images[size_t(binding.image)].rgba8.empty()) {
            return Default(binding,
                           "image " + std::to_string(binding.image) +
                               " has no pixels; using the default texture",
                           out);
        }
        key = "#" + std::to_string(binding.image);
    } else if (binding.source == TextureBinding::Source::kFile) {
        key = binding.file;
    } else {
        return Default(binding, {}, out);
    }
    if (auto e = s_.Sampler(binding.repeat, binding.nearest, out.sampler)) {
        return e;
    }
    auto it = images_.find({key, binding.srgb});
    if (it == images_.end()) {
        vk::Image image;
        if (binding.source == TextureBinding::Source::kSceneImage) {
            const runtime::SceneImage& si = scene_.images[size_t(binding.image)];
            if (auto e = vk::CreateTexture(s_.context, si.width, si.height, si.rgba8, binding.srgb,
                                           image)) {
                return e;
            }
        } else {
            int w = 0, h = 0, n = 0;
            stbi_uc* pixels = stbi_load(binding.file.c_str(), &w, &h, &n, 4);
            if (!pixels) {
                return Default(binding,
                               "cannot decode '" + binding.file + "': " + stbi_failure_reason() +
                                   "; using the default texture",
                               out);
            }
            auto e = vk::CreateTexture(s_.context, uint32_t(w), uint32_t(h),
                                       std::span<const uint8_t>(pixels, size_t(w) * size_t(h) * 4),
                                       binding.srgb, image);
            stbi_image_free(pixels);
            if (e) {
                return e;
            }
        }
        it = images_.emplace(std::pair{key, binding.srgb}, image).first;
    }
    out.view = it->second.view;
    out.width = it->second.width;
    out.height = it->second.height;
    return std::nullopt;
}

}  // namespace kiln::render
