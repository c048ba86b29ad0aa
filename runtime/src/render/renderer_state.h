// The Renderer's private state: device, packs, and the caches that outlive a frame (pipelines,
// render passes, samplers, default textures, and the device resources of the scene it draws).
#ifndef KILN_RUNTIME_RENDER_RENDERER_STATE_H_
#define KILN_RUNTIME_RENDER_RENDERER_STATE_H_

#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "kiln/runtime/renderer.h"
#include "render/draw_list.h"
#include "render/material_binding.h"
#include "vk/context.h"
#include "vk/pipeline.h"
#include "vk/render_pass.h"
#include "vk/resources.h"

namespace kiln::render {
struct CameraSetup;
struct ForwardPlan;
class FrameTextures;
}  // namespace kiln::render

namespace kiln::runtime {

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
    std::unique_ptr<render::FrameTextures> textures;
    render::MaterialCache materials;
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
    // (target formats, clear) -> render pass; pipelines use the clearing one (compatible).
    std::map<std::pair<vk::TargetFormats, bool>, VkRenderPass> render_passes;
    std::deque<PipelineEntry> pipelines;  // deque: entries are handed out by pointer
    std::map<std::pair<bool, bool>, VkSampler> samplers;  // (repeat, nearest)
    std::map<std::pair<std::string, vk::ImageShape>, vk::Image> default_textures;
    DiagnosticList notes;  // pipeline-cache warnings etc., reported with the next frame
    std::set<pack::UsageMaterial> used_materials;       // every frame's, for the usage file
    std::unique_ptr<vk::ModuleChecker> module_checker;  // null when the packs are trusted
    std::unique_ptr<SceneResources> scene_resources;    // of the last scene drawn

    ~State();
    Status GetPipeline(uint32_t pack,
                       uint32_t variant,
                       const vk::RenderState& state,
                       const vk::TargetFormats& targets,
                       const vk::Pipeline*& out,
                       uint32_t& created);
    Status RenderPass(const vk::TargetFormats& targets, bool clear, VkRenderPass& out);
    // The resources of `scene`: the kept ones when the last frame drew the same scene id with
    // the same colour pipeline, else new ones (the old are released).
    SceneResources& ResourcesFor(const Scene& scene, const ColorPipeline& color);
    Status Sampler(bool repeat, bool nearest, VkSampler& out);
    // Unity's named defaults ("white", "black", "gray", "bump", "red"; others are "gray") in
    // the shape the shader declares.
    Status DefaultTexture(const std::string& name, vk::ImageShape shape, const vk::Image*& out);
    std::vector<const pack::Pack*> PackList() const;
};

// Renders a frame with the state's caches (render/forward.cpp): plans it (render/forward_plan.h),
// then draws the plan.
Status RenderForward(Renderer::State& state,
                     const Scene& scene,
                     const FrameSettings& settings,
                     const ColorPipeline& color,
                     LinearImage& out,
                     FrameStats& stats);
// Draws a planned frame: each request's variant, pipeline, uniforms and descriptors, then one
// command buffer (what RenderForward does after planning; kiln test plans its own frames). The
// meshes and textures come from `resources`.
Status DrawPlan(Renderer::State& state,
                SceneResources& resources,
                const Scene& scene,
                const FrameSettings& settings,
                const render::CameraSetup& camera,
                const render::ForwardPlan& plan,
                LinearImage& out,
                FrameStats& stats);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_RENDERER_STATE_H_
