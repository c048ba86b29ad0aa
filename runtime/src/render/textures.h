// Textures of a scene: scene images and .material files uploaded on first use (in the colour
// space the property asks for), the renderer's default textures otherwise, each in the shape
// (2D, 3D, cube, arrays) the shader declares. Kept with the scene's resources between frames.
#ifndef KILN_RUNTIME_RENDER_TEXTURES_H_
#define KILN_RUNTIME_RENDER_TEXTURES_H_

#include <glm/vec3.hpp>

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "vk/resources.h"

#include "render/material_binding.h"
#include "render/renderer_state.h"

namespace kiln::runtime {

// A texture's image scaled down to at most kThumbnailSize texels a side (RGBA8, as decoded), for
// the frame debugger's record of what a draw bound.
struct Thumbnail {
    static constexpr uint32_t kThumbnailSize = 64;
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;
};

struct BoundTexture {
    VkImageView view = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    uint32_t width = 1, height = 1;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::string source;   // "file 'x.png'", "glTF image 2 'albedo'", "default 'white'", ...
    std::string warning;  // why a default texture stands in
    std::shared_ptr<const Thumbnail> thumbnail;  // image files and scene images
};

// The shape a shader declares for a sampled resource; nullopt for 1D and buffer textures.
std::optional<vk::ImageShape> ShapeOf(const pack::ResourceRec& resource);

// What stands in for a texture the material does not set: the engine's own textures
// (unity_SpecCube0/1: the ambient environment) or the default texture.
TextureBinding UnsetTexture(std::string_view name);

class FrameTextures {
  public:
    FrameTextures(Renderer::State& s, const Scene& scene) : s_(s), scene_(&scene) {}
    ~FrameTextures();
    FrameTextures(const FrameTextures&) = delete;
    FrameTextures& operator=(const FrameTextures&) = delete;

    // Image files and scene images are 2D: a shader that declares another shape gets the
    // binding's default texture in its shape, with a warning.
    Status Get(const TextureBinding& binding, vk::ImageShape shape, BoundTexture& out);
    // The scene object of this frame (a copy of the same scene is drawn with the same images).
    void SetScene(const Scene& scene) { scene_ = &scene; }

  private:
    Status Default(const TextureBinding& binding,
                   vk::ImageShape shape,
                   std::string warning,
                   BoundTexture& out);
    Status Ambient(vk::ImageShape shape, BoundTexture& out);
    Renderer::State& s_;
    const Scene* scene_;
    // (source key, srgb) -> uploaded image, with the warning its upload gave (downscaled); the
    // key is "#<image>" or the file path.
    struct Uploaded {
        vk::Image image;
        std::string warning;
        std::string source;
        std::shared_ptr<const Thumbnail> thumbnail;
    };
    std::map<std::pair<std::string, bool>, Uploaded> images_;
    std::map<vk::ImageShape, vk::Image> ambient_;  // Source::kAmbient, per shape
    struct AmbientKey {                            // the ambient ambient_ holds
        AmbientMode mode = AmbientMode::kFlat;
        glm::vec3 sky{-1.0f}, equator{-1.0f}, ground{-1.0f};
        const Sky* image = nullptr;
        bool operator==(const AmbientKey&) const = default;
    };
    AmbientKey ambient_key_;
};

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_TEXTURES_H_
