// The Renderer's private state: device, packs, and the caches that outlive a frame (pipelines,
// render passes, samplers, default textures, and the device resources of the scene it draws).
#ifndef KILN_RUNTIME_RENDER_RENDERER_STATE_H_
#define KILN_RUNTIME_RENDER_RENDERER_STATE_H_

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "kiln/runtime/renderer.h"
#include "render/draw_list.h"
#include "render/material_binding.h"
#include "vk/context.h"
#include "vk/pipeline.h"
#include "vk/render_pass.h"
#include "vk/resources.h"

namespace kiln::runtime {
struct CameraSetup;
class FrameCache;
class FrameTextures;
}  // namespace kiln::runtime

namespace kiln::runtime {

struct Frame;
struct CapturedTarget;
// Called after each step of a frame recorded step by step (render/frame.h, RecordFrame).
using StepObserver = std::function<Status(const Frame& frame,
                                          size_t pass,
                                          int draw,
                                          std::vector<CapturedTarget> targets,
                                          double gpu_ms)>;

struct LoadedPack {
    std::string path;
    pack::MappedFile file;
    pack::Pack pack;
    std::unique_ptr<pack::VariantSelector> selector;
};

struct PipelineEntry {
    uint32_t pack = 0, variant = 0;
    vk::RenderState state;
    vk::TargetFormats targets;
    vk::Pipeline pipeline;
};

// The device resources of the scene the renderer draws (Scene::id): vertex and index buffers per
// (mesh, primitive), uploaded images, and material instances. Kept while frames draw the scene
// with the same id and colour pipeline; a scene without an id gets fresh ones each frame.
struct SceneResources {
    SceneResources(Renderer::State& s, const Scene& scene, const ColorPipeline& color);
    ~SceneResources();
    SceneResources(const SceneResources&) = delete;
    SceneResources& operator=(const SceneResources&) = delete;

    // The buffers of primitive `primitive` of mesh `mesh`, uploaded on first use.
    Status Buffers(const Scene& scene,
                   uint32_t mesh,
                   uint32_t primitive,
                   const vk::Buffer*& vertices,
                   const vk::Buffer*& indices);

    Renderer::State& s;
    uint64_t id = 0;
    const ColorPipeline* color = nullptr;
    std::map<std::pair<uint32_t, uint32_t>, std::pair<vk::Buffer, vk::Buffer>> meshes;
    std::unique_ptr<FrameTextures> textures;
    MaterialCache materials;
    std::optional<std::pair<glm::vec3, glm::vec3>> bounds;  // SceneBounds, for the camera
    uint32_t uploads = 0;                                   // buffers uploaded, for the stats
};

struct Renderer::State {
    RendererOptions options;
    vk::Context context;
    std::vector<std::unique_ptr<LoadedPack>> packs;
    VkPipelineCache pipeline_cache = VK_NULL_HANDLE;
    VkFormat color_format = VK_FORMAT_R16G16B16A16_SFLOAT;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    // (target formats, clear, read-only depth) -> render pass; pipelines use the clearing one
    // (render passes that differ only in load operations and layouts are compatible).
    std::map<std::tuple<vk::TargetFormats, bool, bool>, VkRenderPass> render_passes;
    std::deque<PipelineEntry> pipelines;  // deque: entries are handed out by pointer
    // (wrap u, wrap v, nearest, nearest mips)
    std::map<std::tuple<TextureWrap, TextureWrap, bool, bool>, VkSampler> samplers;
    std::map<std::pair<std::string, vk::ImageShape>, vk::Image> default_textures;
    VkSampler shadow_sampler = VK_NULL_HANDLE;      // ShadowSampler's, made on first use
    VkFormat shadow_format = VK_FORMAT_UNDEFINED;   // ShadowMapFormat's, found on first use
    bool shadow_filtered = false;                   // ... and whether it filters linearly
    std::map<bool, vk::Image> default_shadow_maps;  // (cube) -> DefaultShadowMap's
    DiagnosticList notes;  // pipeline-cache warnings etc., reported with the next frame
    std::set<pack::UsageMaterial> used_materials;       // every frame's, for the usage file
    std::unique_ptr<vk::ModuleChecker> module_checker;  // null when the packs are trusted
    std::unique_ptr<SceneResources> scene_resources;    // of the last scene drawn
    vk::Buffer screen_vertices, screen_indices;         // ScreenTriangle's, made on first use
    std::unique_ptr<FrameCache> frame_cache;            // Frames()'s, made on first use

    ~State();
    Status GetPipeline(uint32_t pack,
                       uint32_t variant,
                       const vk::RenderState& state,
                       const vk::TargetFormats& targets,
                       const vk::Pipeline*& out,
                       uint32_t& created);
    Status RenderPass(const vk::TargetFormats& targets,
                      bool clear,
                      bool depth_read_only,
                      VkRenderPass& out);
    // The resources of `scene`: the kept ones when the last frame drew the same scene id with
    // the same colour pipeline, else new ones (the old are released).
    SceneResources& ResourcesFor(const Scene& scene, const ColorPipeline& color);
    // `nearest_mips`: no filtering between mip levels either (what a depth target, which has no
    // linear filtering, must be sampled with).
    Status Sampler(TextureWrap u,
                   TextureWrap v,
                   bool nearest,
                   VkSampler& out,
                   bool nearest_mips = false);
    // The shadow maps' sampler: a depth comparison (reference <= stored: lit) with bilinear
    // filtering of its results (2x2 percentage-closer filtering) where the format filters
    // (ShadowMapFormat), 1 (lit) outside the map.
    Status ShadowSampler(VkSampler& out);
    // The shadow maps' depth format: one the device draws into and samples (D32, else D16),
    // preferring one it filters linearly.
    Status ShadowMapFormat(VkFormat& out);
    // A 1x1 shadow map (a cube: six faces) at depth 1, in DEPTH_STENCIL_READ_ONLY_OPTIMAL: what a
    // receiver variant drawn without its light's map (kiln test, shadows off) samples: lit.
    Status DefaultShadowMap(bool cube, const vk::Image*& out);
    // Unity's named defaults ("white", "black", "gray", "bump", "red"; others are "gray") in
    // the shape the shader declares.
    Status DefaultTexture(const std::string& name, vk::ImageShape shape, const vk::Image*& out);
    std::vector<const pack::Pack*> PackList() const;
    // The device objects frames reuse (render/frame_cache.h).
    FrameCache& Frames();
    // Records a frame's materials (with their shaders) for the usage file.
    void NoteMaterials(const std::vector<const MaterialInstance*>& materials);
    // A triangle covering the whole frame in clip space (x, y in -1..3), in the mesh vertex
    // layout: what the deferred light pass draws.
    Status ScreenTriangle(const vk::Buffer*& vertices, const vk::Buffer*& indices);
};

// Renders a frame with the state's caches (render/render_frame.cpp): plans it along the settings'
// path (render/render_path.h), then builds and records the plan's frame.
Status RenderFrame(Renderer::State& state,
                   const Scene& scene,
                   const FrameSettings& settings,
                   const ColorPipeline& color,
                   LinearImage& out,
                   FrameStats& stats,
                   FrameCapture* capture = nullptr);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_RENDERER_STATE_H_
