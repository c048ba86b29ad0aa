// RenderForward: the lecture's forward path. The draw list (render/forward_plan.h: passes,
// lights and keywords per primitive) becomes draws: the variant each asks for, its pipeline,
// uniform bytes and descriptors, decided on the CPU; then one command buffer records them all.
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>

#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "render/forward_plan.h"
#include "render/frame.h"
#include "render/frame_values.h"
#include "render/renderer_state.h"
#include "render/textures.h"

namespace kiln::runtime {
namespace {

using render::MaterialInstance;
using render::Values;

// What draws of one material's pass with one variant share: the pipeline for the frame's
// targets, the texture descriptors and the <tex>_TexelSize values they imply. Resolved once a
// frame per (material, pass, variant, additive), not per draw.
struct Binding {
    const vk::Pipeline* pipeline = nullptr;
    std::vector<Draw::Write> textures;
    Values texel_sizes;
};

bool Written(const std::vector<Draw::Write>& writes, uint32_t set, uint32_t binding) {
    return std::any_of(writes.begin(), writes.end(),
                       [&](const Draw::Write& w) { return w.set == set && w.binding == binding; });
}

struct DrawBuilder {
    Renderer::State& s;
    SceneResources& resources;
    const Scene& scene;
    vk::TargetFormats targets;
    Values frame;
    FrameStats& stats;
    std::vector<uint8_t> uniforms;
    VkDeviceSize alignment = 256;
    std::map<std::tuple<const MaterialInstance*, uint32_t, uint32_t, bool>, Binding> bindings;

    // A warning about the scene, each once a frame.
    void Warn(DiagCode code, std::string message) {
        render::WarnOnce(stats.warnings, scene, code, std::move(message));
    }

    // The pipeline of `m`'s pass `pass` with variant `variant` (`chosen`: its keywords).
    Status Pipeline(const MaterialInstance& m,
                    uint32_t pass,
                    uint32_t variant,
                    bool additive,
                    const std::vector<std::string>& chosen,
                    const vk::Pipeline*& out) {
        const pack::Pack& pack = s.packs[m.pack]->pack;
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
        if (Status e = s.GetPipeline(m.pack, variant, state, targets, out, stats.pipelines_created);
            !e.ok()) {
            return Error{e.error().code,
                         "shader '" + std::string(pack.String(pack.Shader(m.shader).value().name)) +
                             "' pass '" + pack::PassLabel(pack, pass) + "' variant '" +
                             pack::JoinKeywords(chosen) + "': " + e.error().message};
        }
        return {};
    }

    // The texture descriptors of `m` for the variant's modules.
    Status Textures(const MaterialInstance& m, const pack::VariantRec& v, Binding& out) {
        const pack::Pack& pack = s.packs[m.pack]->pack;
        for (uint32_t module : {v.vertex_module, v.fragment_module}) {
            const pack::ModuleRec mod = pack.Module(module).value();
            for (uint32_t r = 0; r < mod.resource_count; ++r) {
                const auto res = pack.Get<pack::ResourceRec>(pack::SectionTag::kResources,
                                                             mod.first_resource + r)
                                     .value();
                if (Written(out.textures, res.set, res.binding)) {
                    continue;
                }
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
                if (Status e = resources.textures->Get(
                        it == m.textures.end() ? render::UnsetTexture(name) : it->second, shape, t);
                    !e.ok()) {
                    return e;
                }
                if (!t.warning.empty()) {
                    Warn(DiagCode::kTextureFallback, m.name + ": " + t.warning);
                }
                out.texel_sizes[name + "_TexelSize"] = {
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
                out.textures.push_back(w);
            }
        }
        return {};
    }

    // One draw of a request's pass for its primitive.
    Status Build(const render::DrawRequest& request, std::vector<Draw>& draws) {
        const MaterialInstance& m = *request.material;
        const uint32_t pass = request.pass;
        const bool additive = request.additive;
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
        const pack::VariantRec v = pack.Variant(choice.variant).value();
        const std::vector<std::string> chosen = pack.KeywordsOf(pass, pack::VariantKey(v.key));
        if (!additive && std::count(chosen.begin(), chosen.end(), pack::kKeywordVertexLight)) {
            ++stats.vertex_lit;
        }
        auto [it, fresh] = bindings.try_emplace({&m, pass, choice.variant, additive});
        Binding& binding = it->second;
        if (fresh) {
            if (Status e = Pipeline(m, pass, choice.variant, additive, chosen, binding.pipeline);
                !e.ok()) {
                bindings.erase(it);
                return e;
            }
            if (Status e = Textures(m, v, binding); !e.ok()) {
                bindings.erase(it);
                return e;
            }
        }
        Draw d;
        d.pipeline = binding.pipeline;
        d.writes = binding.textures;
        const uint32_t mesh = request.instance->mesh;
        const uint32_t primitive =
            uint32_t(request.primitive - scene.meshes[mesh].primitives.data());
        if (Status e = resources.Buffers(scene, mesh, primitive, d.vertices, d.indices); !e.ok()) {
            return e;
        }
        d.index_count = uint32_t(request.primitive->indices.size());

        Values light_values = render::LightValues(
            request.light, additive ? std::vector<const Light*>{} : request.vertex);
        if (!additive && !request.sh.empty()) {
            // Read before the frame's probe: this object's ambient plus its SH lights.
            light_values.merge(render::ProbeValues(scene, request.sh, request.center));
            ++stats.sh_lit;
        }
        const Values object = render::ObjectValues(request.instance->world);
        const render::ValueLookup lookup = [&](std::string_view name) -> const std::vector<float>* {
            for (const Values* table : std::initializer_list<const Values*>{
                     &object, &light_values, &frame, &binding.texel_sizes}) {
                if (auto found = table->find(name); found != table->end()) {
                    return &found->second;
                }
            }
            auto found = m.values.find(std::string(name));
            return found == m.values.end() ? nullptr : &found->second;
        };
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
                if (Written(d.writes, block.set, block.binding)) {
                    continue;  // the textures' or an earlier module's
                }
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
    SceneResources& resources = s.ResourcesFor(scene, color);
    const bool automatic = scene.cameras.empty() || settings.camera == FrameSettings::kCameraAuto;
    if (!resources.bounds && automatic) {  // the automatic camera frames them
        resources.bounds = SceneBounds(scene);
    }
    render::CameraSetup camera;
    if (Status e = render::ChooseCamera(scene, settings, camera,
                                        resources.bounds ? &*resources.bounds : nullptr);
        !e.ok()) {
        return e;
    }
    stats.camera = camera.name;

    const uint32_t uploads = resources.uploads;
    const size_t materials = resources.materials.size();
    render::ForwardPlan plan;
    if (Status e = render::PlanForward(s.PackList(), scene, settings, camera.position, color,
                                       resources.materials, plan, stats.warnings);
        !e.ok()) {
        return e;
    }
    for (const MaterialInstance* m : plan.list.materials) {
        const pack::Pack& pack = s.packs[m->pack]->pack;
        s.used_materials.insert(
            {m->name, std::string(pack.String(pack.Shader(m->shader).value().name))});
    }
    stats.materials_resolved = uint32_t(resources.materials.size() - materials);
    const Status drawn = DrawPlan(s, resources, scene, settings, camera, plan, out, stats);
    stats.buffers_uploaded = resources.uploads - uploads;
    return drawn;
}

Status DrawPlan(Renderer::State& s,
                SceneResources& resources,
                const Scene& scene,
                const FrameSettings& settings,
                const render::CameraSetup& camera,
                const render::ForwardPlan& plan,
                LinearImage& out,
                FrameStats& stats) {
    // The forward path's frame: one pass into the colour target and the depth buffer.
    Frame frame;
    frame.width = settings.width;
    frame.height = settings.height;
    FrameTarget color_target{"color", s.color_format, false, {}};
    // Alpha 0: not covered (the frame's alpha is coverage).
    color_target.clear.color = {
        {settings.background.r, settings.background.g, settings.background.b, 0}};
    FrameTarget depth_target{"depth", s.depth_format, true, {}};
    depth_target.clear.depthStencil = {1.0f, 0};
    frame.targets = {color_target, depth_target};
    frame.output = 0;
    FramePass& forward = frame.passes.emplace_back();
    forward.name = "forward";
    forward.colors = {0};
    forward.depth = 1;

    DrawBuilder builder{s,
                        resources,
                        scene,
                        FormatsOf(frame, forward),
                        render::FrameValues(scene, settings, camera),
                        stats,
                        {},
                        256,
                        {}};
    builder.alignment =
        std::max<VkDeviceSize>(256, s.context.properties.limits.minUniformBufferOffsetAlignment);
    for (const render::DrawRequest& r : plan.draws) {
        if (Status e = builder.Build(r, forward.draws); !e.ok()) {
            return e;
        }
    }
    stats.objects = plan.objects;
    frame.uniforms = std::move(builder.uniforms);
    return RecordFrame(s, frame, out);
}

}  // namespace kiln::runtime
