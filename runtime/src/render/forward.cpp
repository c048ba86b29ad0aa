// RenderForward: the lecture's forward path. The draw list (render/forward_plan.h: passes,
// lights and keywords per primitive) becomes draws: the variant each asks for, its pipeline,
// uniform bytes and descriptors, decided on the CPU; then one command buffer records them all.
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <deque>
#include <map>

#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "render/draw.h"
#include "render/forward_plan.h"
#include "render/frame_values.h"
#include "render/renderer_state.h"
#include "render/textures.h"

namespace kiln::runtime {
namespace {

using render::MaterialInstance;
using render::Values;

struct DrawBuilder {
    Renderer::State& s;
    const Scene& scene;
    const ColorPipeline& color;
    render::FrameTextures& textures;
    Values frame;
    FrameStats& stats;
    std::vector<uint8_t> uniforms;
    VkDeviceSize alignment = 256;

    // A warning about the scene, each once a frame.
    void Warn(DiagCode code, std::string message) {
        render::WarnOnce(stats.warnings, scene, code, std::move(message));
    }

    // One draw of a request's pass for its primitive (vertex and index buffers uploaded).
    Status Build(const render::DrawRequest& request,
                 const vk::Buffer& vb,
                 const vk::Buffer& ib,
                 std::vector<Draw>& draws) {
        const MaterialInstance& m = *request.material;
        const uint32_t pass = request.pass;
        const bool additive = request.additive;
        const Light* light = request.light;
        const std::vector<const Light*>& vertex = request.vertex;
        const glm::mat4& world = request.instance->world;
        const uint32_t index_count = uint32_t(request.primitive->indices.size());
        LoadedPack& lp = *s.packs[m.pack];
        const pack::Pack& pack = lp.pack;
        const Result<pack::VariantChoice> selected =
            lp.selector->Select(pass, request.keywords, request.reason);
        if (!selected) {
            return Error{DiagCode::kMissingVariant, m.name + ": " + selected.error().message};
        }
        const pack::VariantChoice& choice = selected.value();
        if (!choice.exact) {
            Warn(DiagCode::kVariantFallback, m.name + ": " + choice.warning);
        }
        const std::vector<std::string> chosen =
            pack.KeywordsOf(pass, pack::VariantKey(pack.Variant(choice.variant).value().key));
        if (!additive && std::count(chosen.begin(), chosen.end(), pack::kKeywordVertexLight)) {
            ++stats.vertex_lit;
        }

        std::vector<pack::StateOverride> overrides;
        for (const pack::StateOverride& o : m.overrides) {
            if (!(additive && o.field == "Blend")) {
                overrides.push_back(o);
            }
        }
        if (additive) {
            overrides.insert(overrides.end(), m.add_overrides.begin(), m.add_overrides.end());
        }
        auto number = [&](std::string_view name) -> std::optional<float> {
            auto it = m.values.find(std::string(name));
            if (it == m.values.end() || it->second.empty()) {
                return std::nullopt;
            }
            return it->second[0];
        };
        vk::RenderState state;
        if (Status e = vk::ResolveRenderState(pack, pass, number, overrides, state); !e.ok()) {
            return Error{
                DiagCode::kRenderFailed,
                m.name + ": pass '" + pack::PassLabel(pack, pass) + "': " + e.error().message};
        }
        if (additive) {
            // The frame's alpha is coverage (docs/runtime.md): an additive pass adds light, and
            // its Blend One One would add 1 to the alpha per light.
            for (vk::BlendTarget& t : state.targets)
                t.mask &= ~VkColorComponentFlags(VK_COLOR_COMPONENT_A_BIT);
        }
        Draw d;
        if (Status e =
                s.GetPipeline(m.pack, choice.variant, state, d.pipeline, stats.pipelines_created);
            !e.ok()) {
            return Error{e.error().code,
                         "shader '" + std::string(pack.String(pack.Shader(m.shader).value().name)) +
                             "' pass '" + pack::PassLabel(pack, pass) + "' variant '" +
                             pack::JoinKeywords(chosen) + "': " + e.error().message};
        }
        d.vertices = &vb;
        d.indices = &ib;
        d.index_count = index_count;

        const Values light_values =
            render::LightValues(light, additive ? std::vector<const Light*>{} : vertex);
        const Values object = render::ObjectValues(world);
        Values material_extra;  // <tex>_TexelSize
        const pack::VariantRec v = pack.Variant(choice.variant).value();
        const render::ValueLookup lookup = [&](std::string_view name) -> const std::vector<float>* {
            for (const Values* table : std::initializer_list<const Values*>{
                     &object, &light_values, &frame, &material_extra}) {
                if (auto it = table->find(name); it != table->end()) {
                    return &it->second;
                }
            }
            auto it = m.values.find(std::string(name));
            return it == m.values.end() ? nullptr : &it->second;
        };
        std::vector<std::pair<uint32_t, uint32_t>> seen;  // (set, binding) already written
        for (uint32_t module : {v.vertex_module, v.fragment_module}) {
            const pack::ModuleRec mod = pack.Module(module).value();
            for (uint32_t r = 0; r < mod.resource_count; ++r) {
                const auto res = pack.Get<pack::ResourceRec>(pack::SectionTag::kResources,
                                                             mod.first_resource + r)
                                     .value();
                if (std::count(seen.begin(), seen.end(), std::pair{res.set, res.binding})) {
                    continue;
                }
                seen.emplace_back(res.set, res.binding);
                std::string name(pack.String(res.name));
                const auto kind = pack::ResourceKind(res.kind);
                if (kind == pack::ResourceKind::kSeparateSampler && name.rfind("sampler", 0) == 0) {
                    name = name.substr(7);  // sampler_MainTex -> _MainTex
                }
                if (kind == pack::ResourceKind::kStorageImage ||
                    kind == pack::ResourceKind::kStorageBuffer) {
                    return Error{DiagCode::kRenderFailed,
                                 m.name + ": resource '" + name +
                                     "' is a storage resource, which forward passes cannot bind"};
                }
                vk::ImageShape shape = vk::ImageShape::k2D;  // a lone sampler has none
                if (kind != pack::ResourceKind::kSeparateSampler) {
                    const std::optional<vk::ImageShape> declared = render::ShapeOf(res);
                    if (!declared) {
                        return Error{
                            DiagCode::kRenderFailed,
                            m.name + ": texture '" + name +
                                "' is 1D or a texel buffer, which the runtime cannot bind"};
                    }
                    shape = *declared;
                }
                render::BoundTexture t;
                auto it = m.textures.find(name);
                if (Status e = textures.Get(
                        it == m.textures.end() ? render::UnsetTexture(name) : it->second, shape, t);
                    !e.ok()) {
                    return e;
                }
                if (!t.warning.empty()) {
                    Warn(DiagCode::kTextureFallback, m.name + ": " + t.warning);
                }
                material_extra[name + "_TexelSize"] = {
                    1.0f / float(t.width), 1.0f / float(t.height), float(t.width), float(t.height)};
                Draw::Write w{res.set, res.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
                w.image = {t.sampler, t.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
                if (kind == pack::ResourceKind::kSeparateImage) {
                    w.type = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
                    w.image.sampler = VK_NULL_HANDLE;
                } else if (kind == pack::ResourceKind::kSeparateSampler) {
                    w.type = VK_DESCRIPTOR_TYPE_SAMPLER;
                    w.image.imageView = VK_NULL_HANDLE;
                }
                d.writes.push_back(w);
            }
        }
        for (uint32_t module : {v.vertex_module, v.fragment_module}) {
            const pack::ModuleRec mod = pack.Module(module).value();
            for (uint32_t b = 0; b < mod.block_count; ++b) {
                const auto block =
                    pack.Get<pack::BlockRec>(pack::SectionTag::kBlocks, mod.first_block + b)
                        .value();
                if (pack::BlockKind(block.kind) == pack::BlockKind::kPushConstant) {
                    d.push.assign(d.pipeline->layout.push_constant_size, 0);
                    render::WriteBlock(pack, block, lookup, d.push.data(), d.push.size());
                    continue;
                }
                if (std::count(seen.begin(), seen.end(), std::pair{block.set, block.binding})) {
                    continue;
                }
                seen.emplace_back(block.set, block.binding);
                const VkDeviceSize offset =
                    (uniforms.size() + alignment - 1) / alignment * alignment;
                uniforms.resize(offset + block.size, 0);
                render::WriteBlock(pack, block, lookup, uniforms.data() + offset, block.size);
                Draw::Write w{block.set, block.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
                w.offset = offset;
                w.range = block.size;
                d.writes.push_back(w);
            }
        }
        (additive ? stats.add_passes : stats.base_passes)++;
        draws.push_back(std::move(d));
        return {};
    }
};

}  // namespace

// Frees a frame's buffers on every path out of RenderForward.
struct FrameBuffers {
    const vk::Context& context;
    std::deque<vk::Buffer> buffers;
    ~FrameBuffers() {
        for (vk::Buffer& b : buffers) {
            vk::DestroyBuffer(context, b);
        }
    }
};

Status RenderForward(Renderer::State& s,
                     const Scene& scene,
                     const FrameSettings& settings,
                     const ColorPipeline& color,
                     LinearImage& out,
                     FrameStats& stats) {
    if (settings.width == 0 || settings.height == 0 || settings.width > 16384 ||
        settings.height > 16384) {
        return Error{DiagCode::kBadScene, "image size must be between 1x1 and 16384x16384"};
    }
    if (s.packs.empty()) {
        return Error{DiagCode::kRenderFailed, "no variant pack loaded"};
    }
    if (scene.instances.empty()) {
        return Error{DiagCode::kBadScene,
                     (scene.path.empty() ? std::string("the scene") : scene.path) +
                         ": nothing to draw (no node of the scene has a mesh)"};
    }
    render::CameraSetup camera;
    if (Status e = render::ChooseCamera(scene, settings, camera); !e.ok()) {
        return e;
    }
    stats.camera = camera.name;

    render::ForwardPlan plan;
    if (Status e = render::PlanForward(s.PackList(), scene, settings, camera.position, color, plan,
                                       stats.warnings);
        !e.ok()) {
        return e;
    }
    for (const MaterialInstance& m : plan.materials) {
        s.used_materials.insert(
            {m.name, std::string(s.packs[m.pack]->pack.String(
                         s.packs[m.pack]->pack.Shader(m.shader).value().name))});
    }
    return DrawPlan(s, scene, settings, camera, color, plan, out, stats);
}

Status DrawPlan(Renderer::State& s,
                const Scene& scene,
                const FrameSettings& settings,
                const render::CameraSetup& camera,
                const ColorPipeline& color,
                const render::ForwardPlan& plan,
                LinearImage& out,
                FrameStats& stats) {
    FrameBuffers gpu{s.context, {}};
    render::FrameTextures textures(s, scene);
    DrawBuilder builder{s,     scene, color, textures, render::FrameValues(scene, settings, camera),
                        stats, {},    256};
    builder.alignment =
        std::max<VkDeviceSize>(256, s.context.properties.limits.minUniformBufferOffsetAlignment);
    std::vector<Draw> draws;
    std::map<const Primitive*, std::pair<const vk::Buffer*, const vk::Buffer*>> uploaded;
    for (const render::DrawRequest& r : plan.draws) {
        auto& buffers = uploaded[r.primitive];
        if (!buffers.first) {
            const Primitive& p = *r.primitive;
            vk::Buffer& vb = gpu.buffers.emplace_back();
            if (Status e =
                    vk::CreateBufferWithData(s.context,
                                             {reinterpret_cast<const uint8_t*>(p.vertices.data()),
                                              p.vertices.size() * sizeof(MeshVertex)},
                                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vb);
                !e.ok()) {
                return e;
            }
            vk::Buffer& ib = gpu.buffers.emplace_back();
            if (Status e = vk::CreateBufferWithData(
                    s.context,
                    {reinterpret_cast<const uint8_t*>(p.indices.data()), p.indices.size() * 4},
                    VK_BUFFER_USAGE_INDEX_BUFFER_BIT, ib);
                !e.ok()) {
                return e;
            }
            buffers = {&vb, &ib};
        }
        if (Status e = builder.Build(r, *buffers.first, *buffers.second, draws); !e.ok()) {
            return e;
        }
    }
    stats.objects = plan.objects;
    return RecordFrame(s, settings, draws, builder.uniforms, out);
}

}  // namespace kiln::runtime
