// Textures for one frame: scene images and .material files uploaded on first use (in the colour
// space the property asks for), the renderer's default textures otherwise.
#ifndef KILN_RUNTIME_RENDER_TEXTURES_H_
#define KILN_RUNTIME_RENDER_TEXTURES_H_

#include <map>
#include <string>
#include <tuple>

#include "render/material_binding.h"
#include "render/renderer_state.h"

namespace kiln::render {

struct BoundTexture {
    VkImageView view = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    uint32_t width = 1, height = 1;
    std::string warning;  // why a default texture stands in
};

class FrameTextures {
  public:
    FrameTextures(runtime::Renderer::State& s, const runtime::Scene& scene)
        : s_(s), scene_(scene) {}
    ~FrameTextures();
    FrameTextures(const FrameTextures&) = delete;
    FrameTextures& operator=(const FrameTextures&) = delete;

    std::optional<runtime::Error> Get(const TextureBinding& binding, BoundTexture& out);

  private:
    std::optional<runtime::Error> Default(const TextureBinding& binding,
                                          std::string warning,
                                          BoundTexture& out);
    runtime::Renderer::State& s_;
    const runtime::Scene& scene_;
    // (source key, srgb) -> uploaded image; the key is "#<image>" or the file path.
    std::map<std::pair<std::string, bool>, vk::Image> images_;
};

}  // namespace kiln::render

#endif  // KILN_RUNTIME_RENDER_TEXTURES_H_
