#include "kiln/runtime/renderer.h"

#include "render/renderer_state.h"
#include "vk/pipeline_cache.h"

namespace kiln::runtime {
namespace {

std::optional<Error> CreateRenderPass(Renderer::State& s) {
    VkAttachmentDescription attachments[2]{};
    attachments[0].format = s.color_format;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    attachments[1] = attachments[0];
    attachments[1].format = s.depth_format;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &color;
    subpass.pDepthStencilAttachment = &depth;
    VkSubpassDependency done{};  // the copy to the read-back buffer waits for the colour writes
    done.srcSubpass = 0;
    done.dstSubpass = VK_SUBPASS_EXTERNAL;
    done.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    done.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    done.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    done.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 2;
    info.pAttachments = attachments;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &done;
    if (VkResult r = vkCreateRenderPass(s.context.device, &info, nullptr, &s.render_pass);
        r != VK_SUCCESS) {
        return vk::VkError("cannot create the render pass", r);
    }
    return std::nullopt;
}

}  // namespace

Renderer::State::~State() {
    if (!context.device) {
        return;
    }
    vkDeviceWaitIdle(context.device);
    if (pipeline_cache) {
        if (!options.pipeline_cache.empty()) {
            vk::SavePipelineCache(context, pipeline_cache, options.pipeline_cache);
        }
        vkDestroyPipelineCache(context.device, pipeline_cache, nullptr);
    }
    for (PipelineEntry& p : pipelines) {
        vk::DestroyPipeline(context, p.pipeline);
    }
    for (auto& [key, sampler] : samplers) {
        vkDestroySampler(context.device, sampler, nullptr);
    }
    for (auto& [name, image] : default_textures) {
        vk::DestroyImage(context, image);
    }
    if (render_pass) {
        vkDestroyRenderPass(context.device, render_pass, nullptr);
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

std::optional<Error> Renderer::State::GetPipeline(uint32_t pack,
                                                  uint32_t variant,
                                                  const vk::RenderState& state,
                                                  const vk::Pipeline*& out,
                                                  uint32_t& created) {
    for (const PipelineEntry& p : pipelines) {
        if (p.pack == pack && p.variant == variant && p.state == state) {
            out = &p.pipeline;
            return std::nullopt;
        }
    }
    PipelineEntry entry{pack, variant, state, {}};
    vk::PipelineTargets targets{render_pass, 1};
    if (auto e = vk::CreatePipeline(context, packs[pack]->pack, variant, state, targets,
                                    pipeline_cache, module_checker.get(), entry.pipeline)) {
        return e;
    }
    ++created;
    pipelines.push_back(std::move(entry));
    out = &pipelines.back().pipeline;
    return std::nullopt;
}

std::optional<Error> Renderer::State::Sampler(bool repeat, bool nearest, VkSampler& out) {
    auto it = samplers.find({repeat, nearest});
    if (it != samplers.end()) {
        out = it->second;
        return std::nullopt;
    }
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    info.minFilter = nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    const VkSamplerAddressMode mode =
        repeat ? VK_SAMPLER_ADDRESS_MODE_REPEAT : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeU = info.addressModeV = info.addressModeW = mode;
    info.maxLod = VK_LOD_CLAMP_NONE;
    VkSampler sampler = VK_NULL_HANDLE;
    if (VkResult r = vkCreateSampler(context.device, &info, nullptr, &sampler); r != VK_SUCCESS) {
        return vk::VkError("cannot create a sampler", r);
    }
    samplers[{repeat, nearest}] = sampler;
    out = sampler;
    return std::nullopt;
}

std::optional<Error> Renderer::State::DefaultTexture(const std::string& requested,
                                                     vk::ImageShape shape,
                                                     const vk::Image*& out) {
    // Unity's built-in defaults; an unknown or empty name is "gray".
    static const std::map<std::string, std::array<uint8_t, 4>> kDefaults = {
        {"white", {255, 255, 255, 255}}, {"black", {0, 0, 0, 0}},
        {"gray", {128, 128, 128, 128}},  {"grey", {128, 128, 128, 128}},
        {"bump", {128, 128, 255, 128}},  {"red", {255, 0, 0, 255}},
    };
    const std::string name = kDefaults.count(requested) ? requested : "gray";
    if (auto it = default_textures.find({name, shape}); it != default_textures.end()) {
        out = &it->second;
        return std::nullopt;
    }
    const std::array<uint8_t, 4> texel = kDefaults.at(name);
    vk::Image image;
    if (auto e = vk::CreateConstantImage(context, shape, VK_FORMAT_R8G8B8A8_UNORM, texel, image)) {
        return e;
    }
    out = &(default_textures[{name, shape}] = image);
    return std::nullopt;
}

Renderer::Renderer() = default;
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

std::optional<Error> Renderer::Create(const RendererOptions& options, Renderer& out) {
    auto s = std::make_unique<State>();
    s->options = options;
    vk::ContextOptions co;
    co.validation = options.validation;
    co.device_filter = options.device_filter;
    if (auto e = vk::CreateContext(co, s->context)) {
        return e;
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
        return Error{
            "the device has no depth-stencil format (D32_SFLOAT_S8_UINT or "
            "D24_UNORM_S8_UINT)"};
    }
    if (auto e = CreateRenderPass(*s)) {
        return e;
    }
    std::string note;
    if (auto e =
            vk::CreatePipelineCache(s->context, options.pipeline_cache, s->pipeline_cache, note)) {
        return e;
    }
    if (!note.empty()) {
        s->notes.push_back(note);
    }
    if (!options.trust_packs) {
        s->module_checker = std::make_unique<vk::ModuleChecker>(s->context.properties.limits);
    }
    out.state_ = std::move(s);
    return std::nullopt;
}

std::optional<Error> Renderer::AddPack(const std::string& path) {
    auto loaded = std::make_unique<LoadedPack>();
    loaded->path = path;
    if (auto e = pack::MappedFile::Map(path, loaded->file)) {
        return Error{path + ": " + e->message, ErrorKind::kPack};
    }
    if (auto e = pack::Pack::Open(loaded->file.bytes(), loaded->pack)) {
        return Error{
            path + ": " + std::string(pack::PackErrorCodeName(e->code)) + ": " + e->message,
            ErrorKind::kPack};
    }
    loaded->selector =
        std::make_unique<pack::VariantSelector>(loaded->pack, state_->options.missing_variant);
    state_->packs.push_back(std::move(loaded));
    return std::nullopt;
}

std::optional<Error> Renderer::Render(const Scene& scene,
                                      const FrameSettings& settings,
                                      const ColorPipeline& color,
                                      LinearImage& out,
                                      FrameStats& stats) {
    stats = FrameStats{};
    stats.warnings = std::move(state_->notes);
    state_->notes.clear();
    return RenderForward(*state_, scene, settings, color, out, stats);
}

std::string Renderer::DeviceName() const {
    return state_->context.properties.deviceName;
}

std::vector<std::string> Renderer::ValidationMessages() const {
    return vk::ValidationMessages(state_->context);
}

std::optional<Error> Renderer::WriteUsage(const std::string& path) const {
    std::vector<const pack::VariantSelector*> selectors;
    for (const auto& p : state_->packs) {
        selectors.push_back(p->selector.get());
    }
    if (const Result<bool> written = pack::WriteUsageFile(path, pack::UsageOf(selectors));
        !written) {
        return Error{written.error().message};
    }
    return std::nullopt;
}

size_t Renderer::pack_count() const {
    return state_->packs.size();
}

const pack::Pack& Renderer::pack(size_t index) const {
    return state_->packs.at(index)->pack;
}

}  // namespace kiln::runtime
