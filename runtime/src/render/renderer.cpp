#include "kiln/runtime/renderer.h"

#include <array>
#include <string>
#include <utility>

#include "kiln/pack/engine_names.h"
#include "render/frame_cache.h"
#include "render/renderer_state.h"
#include "render/textures.h"
#include "vk/pipeline_cache.h"

namespace kiln::runtime {
FrameCache& Renderer::State::Frames() {
    if (!frame_cache) {
        frame_cache = std::make_unique<FrameCache>(context);
    }
    return *frame_cache;
}

Renderer::State::~State() {
    if (!context.device) {
        return;
    }
    vkDeviceWaitIdle(context.device);
    frame_cache.reset();
    scene_resources.reset();
    if (pipeline_cache) {
        if (!options.pipeline_cache.empty()) {
            // A destructor has no one to tell: a cache that cannot be saved is rebuilt next run.
            (void)vk::SavePipelineCache(context, pipeline_cache, options.pipeline_cache);
        }
        vkDestroyPipelineCache(context.device, pipeline_cache, nullptr);
    }
    for (PipelineEntry& p : pipelines) {
        vk::DestroyPipeline(context, p.pipeline);
    }
    for (auto& [key, sampler] : samplers) {
        vkDestroySampler(context.device, sampler, nullptr);
    }
    if (shadow_sampler) {
        vkDestroySampler(context.device, shadow_sampler, nullptr);
    }
    for (auto& [cube, image] : default_shadow_maps) {
        vk::DestroyImage(context, image);
    }
    for (auto& [name, image] : default_textures) {
        vk::DestroyImage(context, image);
    }
    vk::DestroyBuffer(context, screen_vertices);
    vk::DestroyBuffer(context, screen_indices);
    for (auto& [key, pass] : render_passes) {
        vkDestroyRenderPass(context.device, pass, nullptr);
    }
    vk::DestroyContext(context);
}

std::vector<const pack::Pack*> Renderer::State::PackList() const {
    std::vector<const pack::Pack*> out;
    for (const auto& p : packs) {
        out.push_back(&p->pack);
    }
    return out;
}

void Renderer::State::NoteMaterials(const std::vector<const MaterialInstance*>& materials) {
    for (const MaterialInstance* m : materials) {
        const pack::Pack& pack = packs[m->pack]->pack;
        used_materials.insert(
            {m->name, std::string(pack.String(pack.Shader(m->shader).value().name))});
    }
}

Status Renderer::State::ScreenTriangle(const vk::Buffer*& vertices, const vk::Buffer*& indices) {
    if (!screen_vertices.buffer) {
        MeshVertex corners[3]{};
        const float xy[3][2] = {{-1, -1}, {3, -1}, {-1, 3}};
        for (int i = 0; i < 3; ++i) {
            corners[i].position[0] = xy[i][0];
            corners[i].position[1] = xy[i][1];
            corners[i].normal[2] = 1;
            corners[i].tangent[0] = corners[i].tangent[3] = 1;
            for (float& c : corners[i].color) {
                c = 1;
            }
        }
        const uint32_t order[3] = {0, 1, 2};
        if (Status e = vk::CreateBufferWithData(
                context, {reinterpret_cast<const uint8_t*>(corners), sizeof corners},
                VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, screen_vertices);
            !e.ok()) {
            return e;
        }
        if (Status e = vk::CreateBufferWithData(
                context, {reinterpret_cast<const uint8_t*>(order), sizeof order},
                VK_BUFFER_USAGE_INDEX_BUFFER_BIT, screen_indices);
            !e.ok()) {
            vk::DestroyBuffer(context, screen_vertices);
            return e;
        }
    }
    vertices = &screen_vertices;
    indices = &screen_indices;
    return {};
}

Status Renderer::State::RenderPass(const vk::TargetFormats& targets,
                                   bool clear,
                                   bool depth_read_only,
                                   VkRenderPass& out) {
    const auto key = std::tuple{targets, clear, depth_read_only};
    auto it = render_passes.find(key);
    if (it == render_passes.end()) {
        VkRenderPass pass = VK_NULL_HANDLE;
        if (Status e = vk::CreateRenderPass(context, targets, clear, depth_read_only, pass);
            !e.ok()) {
            return e;
        }
        it = render_passes.emplace(key, pass).first;
    }
    out = it->second;
    return {};
}

Status Renderer::State::GetPipeline(uint32_t pack,
                                    uint32_t variant,
                                    const vk::RenderState& state,
                                    const vk::TargetFormats& targets,
                                    const vk::Pipeline*& out,
                                    uint32_t& created) {
    for (const PipelineEntry& p : pipelines) {
        if (p.pack == pack && p.variant == variant && p.state == state && p.targets == targets) {
            out = &p.pipeline;
            return {};
        }
    }
    PipelineEntry entry{pack, variant, state, targets, {}};
    VkRenderPass compatible = VK_NULL_HANDLE;
    if (Status e = RenderPass(targets, true, false, compatible); !e.ok()) {
        return e;
    }
    const vk::PipelineTargets pipeline_targets{compatible, uint32_t(targets.colors.size()),
                                               targets.samples};
    if (Status e = vk::CreatePipeline(context, packs[pack]->pack, variant, state, pipeline_targets,
                                      pipeline_cache, module_checker.get(), entry.pipeline);
        !e.ok()) {
        return e;
    }
    ++created;
    pipelines.push_back(std::move(entry));
    out = &pipelines.back().pipeline;
    return {};
}

namespace {

VkSamplerAddressMode AddressMode(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::kClampToEdge:
            return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case TextureWrap::kMirroredRepeat:
            return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        case TextureWrap::kRepeat:
            break;
    }
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

}  // namespace

Status Renderer::State::Sampler(TextureWrap u,
                                TextureWrap v,
                                bool nearest,
                                VkSampler& out,
                                bool nearest_mips) {
    const auto key = std::tuple{u, v, nearest, nearest_mips};
    auto it = samplers.find(key);
    if (it != samplers.end()) {
        out = it->second;
        return {};
    }
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    info.minFilter = nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    info.mipmapMode = nearest_mips ? VK_SAMPLER_MIPMAP_MODE_NEAREST : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = AddressMode(u);
    info.addressModeV = info.addressModeW = AddressMode(v);
    info.maxLod = VK_LOD_CLAMP_NONE;
    VkSampler sampler = VK_NULL_HANDLE;
    if (VkResult r = vkCreateSampler(context.device, &info, nullptr, &sampler); r != VK_SUCCESS) {
        return vk::VkError("cannot create a sampler", r);
    }
    samplers[key] = sampler;
    out = sampler;
    return {};
}

Status Renderer::State::ShadowSampler(VkSampler& out) {
    if (!shadow_sampler) {
        VkFormat format = VK_FORMAT_UNDEFINED;
        if (Status e = ShadowMapFormat(format); !e.ok()) {
            return e;
        }
        VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        info.magFilter = info.minFilter = shadow_filtered ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
        info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        info.addressModeU = info.addressModeV = info.addressModeW =
            VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
        info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;  // depth 1: nothing casts there
        info.compareEnable = VK_TRUE;
        info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
        if (VkResult r = vkCreateSampler(context.device, &info, nullptr, &shadow_sampler);
            r != VK_SUCCESS) {
            return vk::VkError("cannot create the shadow-map sampler", r);
        }
    }
    out = shadow_sampler;
    return {};
}

Status Renderer::State::ShadowMapFormat(VkFormat& out) {
    if (shadow_format == VK_FORMAT_UNDEFINED) {
        // D32, else D16; filtered where the device can (lavapipe cannot: nearest comparisons).
        const VkFormatFeatureFlags need =
            VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
        const VkFormatFeatureFlags linear = VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
        for (VkFormatFeatureFlags want : {need | linear, need}) {
            for (VkFormat f : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM}) {
                VkFormatProperties props;
                vkGetPhysicalDeviceFormatProperties(context.physical, f, &props);
                if (shadow_format == VK_FORMAT_UNDEFINED &&
                    (props.optimalTilingFeatures & want) == want) {
                    shadow_format = f;
                    shadow_filtered = (want & linear) != 0;
                }
            }
        }
        if (shadow_format == VK_FORMAT_UNDEFINED) {
            return Error{DiagCode::kRenderFailed,
                         "the device has no depth format it can render shadow maps into and "
                         "sample (render without shadows)"};
        }
    }
    out = shadow_format;
    return {};
}

Status Renderer::State::DefaultShadowMap(bool cube, const vk::Image*& out) {
    if (auto it = default_shadow_maps.find(cube); it != default_shadow_maps.end()) {
        out = &it->second;
        return {};
    }
    VkFormat format = VK_FORMAT_UNDEFINED;
    if (Status e = ShadowMapFormat(format); !e.ok()) {
        return e;
    }
    vk::Image image;
    if (Status e = vk::CreateShadowMap(context, 1, format, cube, image); !e.ok()) {
        return e;
    }
    const Status cleared = vk::SubmitOnce(context, [&](VkCommandBuffer cmd) {
        vk::ImageBarrier(cmd, image.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                         VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        const VkClearDepthStencilValue far{1.0f, 0};
        const VkImageSubresourceRange all{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0,
                                          VK_REMAINING_ARRAY_LAYERS};
        vkCmdClearDepthStencilImage(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &far, 1,
                                    &all);
        vk::ImageBarrier(cmd, image.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                         VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
    });
    if (!cleared.ok()) {
        vk::DestroyImage(context, image);
        return cleared;
    }
    out = &(default_shadow_maps[cube] = image);
    return {};
}

Status Renderer::State::DefaultTexture(const std::string& requested,
                                       vk::ImageShape shape,
                                       const vk::Image*& out) {
    // Unity's built-in defaults (kiln/pack/engine_names.h); an unknown or empty name is "gray".
    const pack::DefaultTexture* known = pack::FindDefaultTexture(requested);
    const pack::DefaultTexture& texture =
        known ? *known : *pack::FindDefaultTexture(pack::kDefaultTextureFallback);
    const std::string name = texture.name;
    if (auto it = default_textures.find({name, shape}); it != default_textures.end()) {
        out = &it->second;
        return {};
    }
    const std::array<uint8_t, 4> texel = {texture.rgba[0], texture.rgba[1], texture.rgba[2],
                                          texture.rgba[3]};
    vk::Image image;
    if (Status e = vk::CreateConstantImage(context, shape, VK_FORMAT_R8G8B8A8_UNORM, texel, image);
        !e.ok()) {
        return e;
    }
    out = &(default_textures[{name, shape}] = image);
    return {};
}

SceneResources::SceneResources(Renderer::State& state,
                               const Scene& scene,
                               const ColorPipeline& color_pipeline)
    : s(state),
      id(scene.id),
      color(&color_pipeline),
      textures(std::make_unique<FrameTextures>(state, scene)) {}

SceneResources::~SceneResources() {
    for (auto& [key, buffers] : meshes) {
        vk::DestroyBuffer(s.context, buffers.first);
        vk::DestroyBuffer(s.context, buffers.second);
    }
}

Status SceneResources::Buffers(const Scene& scene,
                               uint32_t mesh,
                               uint32_t primitive,
                               const vk::Buffer*& vertices,
                               const vk::Buffer*& indices) {
    auto it = meshes.find({mesh, primitive});
    if (it == meshes.end()) {
        const Primitive& p = scene.meshes[mesh].primitives[primitive];
        std::pair<vk::Buffer, vk::Buffer> buffers;
        if (Status e =
                vk::CreateBufferWithData(s.context,
                                         {reinterpret_cast<const uint8_t*>(p.vertices.data()),
                                          p.vertices.size() * sizeof(MeshVertex)},
                                         VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, buffers.first);
            !e.ok()) {
            return e;
        }
        if (Status e = vk::CreateBufferWithData(
                s.context,
                {reinterpret_cast<const uint8_t*>(p.indices.data()), p.indices.size() * 4},
                VK_BUFFER_USAGE_INDEX_BUFFER_BIT, buffers.second);
            !e.ok()) {
            vk::DestroyBuffer(s.context, buffers.first);
            return e;
        }
        uploads += 2;
        it = meshes.emplace(std::pair{mesh, primitive}, buffers).first;
    }
    vertices = &it->second.first;
    indices = &it->second.second;
    return {};
}

SceneResources& Renderer::State::ResourcesFor(const Scene& scene, const ColorPipeline& color) {
    if (!scene_resources || scene.id == 0 || scene_resources->id != scene.id ||
        scene_resources->color != &color) {
        scene_resources.reset();  // frames wait for the device: nothing still uses them
        scene_resources = std::make_unique<SceneResources>(*this, scene, color);
    }
    scene_resources->textures->SetScene(scene);
    return *scene_resources;
}

Renderer::Renderer() = default;
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Result<Renderer> Renderer::Create(const RendererOptions& options) {
    auto s = std::make_unique<State>();
    s->options = options;
    vk::ContextOptions co;
    co.validation = options.validation;
    co.device_filter = options.device_filter;
    if (Status e = vk::CreateContext(co, s->context); !e.ok()) {
        return e.error();
    }
    s->color_format =
        options.float32_target ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R16G16B16A16_SFLOAT;
    for (VkFormat f : {VK_FORMAT_D32_SFLOAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT}) {
        VkFormatProperties props;
        vkGetPhysicalDeviceFormatProperties(s->context.physical, f, &props);
        if (props.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) {
            s->depth_format = f;
            break;
        }
    }
    if (s->depth_format == VK_FORMAT_UNDEFINED) {
        return Error{DiagCode::kRenderFailed,
                     "the device has no depth-stencil format (D32_SFLOAT_S8_UINT or "
                     "D24_UNORM_S8_UINT)"};
    }
    std::string note;
    if (Status e =
            vk::CreatePipelineCache(s->context, options.pipeline_cache, s->pipeline_cache, note);
        !e.ok()) {
        return e.error();
    }
    if (!note.empty()) {
        s->notes.Warning(DiagCode::kPipelineCacheIgnored, options.pipeline_cache, kNoPosition,
                         note);
    }
    if (std::string why = options.pipeline_cache.empty()
                              ? ""
                              : vk::PipelineCacheUnsavable(options.pipeline_cache);
        !why.empty()) {
        s->notes.Warning(DiagCode::kPipelineCacheIgnored, options.pipeline_cache, kNoPosition,
                         "the pipeline cache cannot be saved: " + why);
    }
    if (!options.trust_packs) {
        s->module_checker = std::make_unique<vk::ModuleChecker>(s->context.properties.limits);
    }
    Renderer out;
    out.state_ = std::move(s);
    return out;
}

Status Renderer::AddPack(const std::string& path) {
    auto loaded = std::make_unique<LoadedPack>();
    loaded->path = path;
    Result<pack::MappedFile> mapped = pack::MappedFile::Map(path);
    if (!mapped) {
        return mapped.error();
    }
    loaded->file = std::move(mapped).value();
    // The variant data (the bulk of a large pack) is checked when the first variant is chosen,
    // a module's SPIR-V when its pipeline is built: loading time does not grow with the pack.
    Result<pack::Pack> opened =
        pack::Pack::Open(loaded->file.bytes(), pack::OpenChecks::kOnFirstUse);
    if (!opened) {
        return Error{opened.error().code, path + ": " + opened.error().message};
    }
    loaded->pack = std::move(opened).value();
    loaded->selector =
        std::make_unique<pack::VariantSelector>(loaded->pack, state_->options.missing_variant);
    state_->packs.push_back(std::move(loaded));
    return {};
}

Status Renderer::Render(const Scene& scene,
                        const FrameSettings& settings,
                        const ColorPipeline& color,
                        LinearImage& out,
                        FrameStats& stats,
                        FrameCapture* capture) {
    stats = FrameStats{};
    stats.warnings = std::exchange(state_->notes, DiagnosticList());
    return RenderFrame(*state_, scene, settings, color, out, stats, capture);
}

Renderer::State& Renderer::internal_state() {
    return *state_;
}

const Renderer::State& Renderer::internal_state() const {
    return *state_;
}

std::string Renderer::DeviceName() const {
    return state_->context.properties.deviceName;
}

bool Renderer::HasFloat16() const {
    return state_->context.shader_float16;
}

std::vector<std::string> Renderer::ValidationMessages() const {
    return vk::ValidationMessages(state_->context);
}

Status Renderer::WriteUsage(const std::string& path) const {
    std::vector<const pack::VariantSelector*> selectors;
    for (const auto& p : state_->packs) {
        selectors.push_back(p->selector.get());
    }
    return pack::WriteUsageFile(
        path,
        {pack::UsageOf(selectors), {state_->used_materials.begin(), state_->used_materials.end()}});
}

size_t Renderer::pack_count() const {
    return state_->packs.size();
}

const pack::Pack& Renderer::pack(size_t index) const {
    return state_->packs.at(index)->pack;
}

}  // namespace kiln::runtime
