// The Renderer's private state: device, packs, and the caches that outlive a frame (pipelines,
// samplers, default textures, the render pass).
#ifndef KILN_RUNTIME_RENDER_RENDERER_STATE_H_
#define KILN_RUNTIME_RENDER_RENDERER_STATE_H_

#include <deque>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "kiln/runtime/renderer.h"
#include "render/material_binding.h"
#include "vk/context.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace kiln::render {
struct CameraSetup;
struct ForwardPlan;
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
    vk::Pipeline pipeline;
};

struct Renderer::State {
    RendererOptions options;
    vk::Context context;
    std::vector<std::unique_ptr<LoadedPack>> packs;
    VkPipelineCache pipeline_cache = VK_NULL_HANDLE;
    VkFormat color_format = VK_FORMAT_R16G16B16A16_SFLOAT;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    VkRenderPass render_pass = VK_NULL_HANDLE;
    std::deque<PipelineEntry> pipelines;  // deque: entries are handed out by pointer
    std::map<std::pair<bool, bool>, VkSampler> samplers;  // (repeat, nearest)
    std::map<std::pair<std::string, vk::ImageShape>, vk::Image> default_textures;
    DiagnosticList notes;  // pipeline-cache warnings etc., reported with the next frame
    std::set<pack::UsageMaterial> used_materials;       // every frame's, for the usage file
    std::unique_ptr<vk::ModuleChecker> module_checker;  // null when the packs are trusted

    ~State();
    Status GetPipeline(uint32_t pack,
                       uint32_t variant,
                       const vk::RenderState& state,
                       const vk::Pipeline*& out,
                       uint32_t& created);
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
// command buffer (what RenderForward does after planning; kiln test plans its own frames).
Status DrawPlan(Renderer::State& state,
                const Scene& scene,
                const FrameSettings& settings,
                const render::CameraSetup& camera,
                const ColorPipeline& color,
                const render::ForwardPlan& plan,
                LinearImage& out,
                FrameStats& stats);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_RENDERER_STATE_H_
