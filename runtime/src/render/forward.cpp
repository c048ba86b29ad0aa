// RenderForward: the lecture's forward path. For every primitive of every instance: its
// material instance, the shader's ForwardBase (or untagged) pass lit by the main directional
// light with ambient and vertex lights, then one ForwardAdd pass per further pixel light with
// DIRECTIONAL / POINT / SPOT selecting the variant. Opaque objects first, in scene order, then
// transparent ones back to front. Draws are planned on the CPU first (pipelines, uniform bytes,
// descriptors), then one command buffer records them all.
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <deque>
#include <map>

#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "render/draw.h"
#include "render/frame_values.h"
#include "render/renderer_state.h"
#include "render/textures.h"

namespace kiln::runtime {
namespace {

using render::MaterialInstance;
using render::Values;

struct ShaderPasses {
    std::vector<uint32_t> base;  // ForwardBase, Always or untagged, in order
    std::optional<uint32_t> add;
};

ShaderPasses PassesOf(const pack::Pack& pack, uint32_t shader) {
    ShaderPasses out;
    const pack::ShaderRec s = pack.Shader(shader).value();
    for (uint32_t p = s.first_pass; p < s.first_pass + s.pass_count; ++p) {
        const pack::PassRec rec = pack.Pass(p).value();
        if (rec.subshader != 0) {
            continue;  // the first SubShader is the one that runs
        }
        const std::string_view mode = pack::LightModeOf(pack, p);
        if (mode.empty() || mode == pack::kLightModeForwardBase || mode == pack::kLightModeAlways) {
            out.base.push_back(p);
        } else if (mode == pack::kLightModeForwardAdd && !out.add) {
            out.add = p;
        }
    }
    return out;
}

struct Planner {
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
        const auto& all = stats.warnings.all();
        if (std::none_of(all.begin(), all.end(),
                         [&](const Diagnostic& d) { return d.message == message; })) {
            stats.warnings.Warning(code, scene.path, kNoPosition, std::move(message));
        }
    }

    // One draw of `pass` for a primitive, lit by `light` (and `vertex` lights in base passes).
    Status Plan(const MaterialInstance& m,
                uint32_t pass,
                bool additive,
                const Light* light,
                const std::vector<const Light*>& vertex,
                const glm::mat4& world,
                const vk::Buffer& vb,
                const vk::Buffer& ib,
                uint32_t index_count,
                std::vector<Draw>& draws) {
        LoadedPack& lp = *s.packs[m.pack];
        const pack::Pack& pack = lp.pack;
        std::vector<std::string> keywords = m.keywords;
        if (additive) {
            const LightType type = light ? light->type : LightType::kDirectional;
            keywords.emplace_back(type == LightType::kPoint  ? pack::kKeywordPoint
                                  : type == LightType::kSpot ? pack::kKeywordSpot
                                                             : pack::kKeywordDirectional);
        } else {
            keywords.emplace_back(pack::kKeywordDirectional);
            // Objects without lightmaps take ambient light from the light probes (unity_SH*), as in
            // Unity; passes that do not declare the keyword ignore it.
            keywords.emplace_back(pack::kKeywordLightProbeSH);
            if (!vertex.empty()) {
                keywords.emplace_back(pack::kKeywordVertexLight);
            }
        }
        const Result<pack::VariantChoice> selected = lp.selector->Select(pass, keywords);
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

    // Material instances, built on first use: a sidecar .material, else the glTF material on
    // Kiln/StandardMetallic. Index materials.size() is glTF's default material.
    std::vector<std::optional<MaterialInstance>> instances(scene.materials.size() + 1);
    auto instance_for = [&](int index, const MaterialInstance*& m) -> Status {
        const size_t slot = index < 0 ? scene.materials.size() : size_t(index);
        if (instances[slot]) {
            m = &*instances[slot];
            return {};
        }
        SceneMaterial gltf;
        gltf.name = "(default)";
        if (index >= 0) {
            gltf = scene.materials[slot];
        }
        MaterialInstance inst;
        if (auto it = scene.material_files.find(gltf.name);
            index >= 0 && it != scene.material_files.end()) {
            if (Status e = render::InstanceFromMaterialFile(s.PackList(), it->second, color, inst);
                !e.ok()) {
                return e;
            }
        } else {
            bool found = false;
            for (uint32_t p = 0; p < s.packs.size() && !found; ++p) {
                if (auto shader = s.packs[p]->pack.FindShader("Kiln/StandardMetallic")) {
                    render::InstanceFromDefaults(s.packs[p]->pack, p, *shader, color, inst);
                    found = true;
                }
            }
            if (!found) {
                return Error{DiagCode::kRenderFailed,
                             "glTF material '" + gltf.name +
                                 "' needs shader 'Kiln/StandardMetallic', which is in none of the "
                                 "loaded packs (add the shipped materials.kpack)"};
            }
            render::ApplyGltfMaterial(gltf, inst);
        }
        instances[slot] = std::move(inst);
        m = &*instances[slot];
        return {};
    };

    FrameBuffers gpu{s.context, {}};
    render::FrameTextures textures(s, scene);
    Planner planner{s,     scene, color, textures, render::FrameValues(scene, settings, camera),
                    stats, {},    256};
    planner.alignment =
        std::max<VkDeviceSize>(256, s.context.properties.limits.minUniformBufferOffsetAlignment);
    std::vector<Light> scene_lights = scene.lights;
    if (scene_lights.empty() && settings.default_light) {
        Light key;
        key.name = "default light";
        key.type = LightType::kDirectional;
        key.direction = glm::normalize(glm::vec3(-0.35f, -0.8f, -0.5f));
        key.intensity = 3.14159265f;  // pi lux: _LightColor0 = 1, Unity's default light
        scene_lights.push_back(key);
        planner.Warn(DiagCode::kDefaultLight,
                     "the scene has no KHR_lights_punctual lights: lit by a default directional "
                     "light of pi lux (Unity's intensity 1) shining along (-0.35, -0.8, -0.5)");
    }
    const Light* main = render::MainLight(scene_lights);

    struct Item {
        const Instance* instance;
        const Primitive* primitive;
        const MaterialInstance* material;
        glm::vec3 center;
        float radius, depth;
    };
    std::vector<Item> opaque, transparent;
    for (const Instance& inst : scene.instances) {
        for (const Primitive& prim : scene.meshes[inst.mesh].primitives) {
            const MaterialInstance* m = nullptr;
            if (Status e = instance_for(prim.material, m); !e.ok()) {
                return e;
            }
            glm::vec3 lo(std::numeric_limits<float>::max()), hi(-lo);
            for (const MeshVertex& v : prim.vertices) {
                const glm::vec3 w(inst.world * glm::vec4(glm::make_vec3(v.position), 1));
                lo = glm::min(lo, w);
                hi = glm::max(hi, w);
            }
            const glm::vec3 center = (lo + hi) * 0.5f;
            const float depth = glm::length(center - camera.position);
            (m->transparent ? transparent : opaque)
                .push_back({&inst, &prim, m, center, glm::length(hi - lo) * 0.5f, depth});
        }
    }
    std::stable_sort(transparent.begin(), transparent.end(),
                     [](const Item& a, const Item& b) { return a.depth > b.depth; });
    opaque.insert(opaque.end(), transparent.begin(), transparent.end());

    std::vector<Draw> draws;
    std::map<const Primitive*, std::pair<const vk::Buffer*, const vk::Buffer*>> uploaded;
    for (const Item& item : opaque) {
        const MaterialInstance& m = *item.material;
        const ShaderPasses passes = PassesOf(s.packs[m.pack]->pack, m.shader);
        if (passes.base.empty()) {
            planner.Warn(DiagCode::kPassNotDrawn,
                         m.name +
                             ": the shader has no ForwardBase or untagged pass; objects "
                             "using it are not drawn by the forward path");
            continue;
        }
        auto& buffers = uploaded[item.primitive];
        if (!buffers.first) {
            const Primitive& p = *item.primitive;
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
        const render::ObjectLights lights =
            render::LightsFor(scene_lights, main, item.center, item.radius, settings.pixel_lights);
        const uint32_t count = uint32_t(item.primitive->indices.size());
        for (uint32_t pass : passes.base) {
            if (Status e =
                    planner.Plan(m, pass, false, lights.main, lights.vertex, item.instance->world,
                                 *buffers.first, *buffers.second, count, draws);
                !e.ok()) {
                return e;
            }
        }
        if (passes.add) {
            for (const Light* light : lights.pixel) {
                if (Status e = planner.Plan(m, *passes.add, true, light, {}, item.instance->world,
                                            *buffers.first, *buffers.second, count, draws);
                    !e.ok()) {
                    return e;
                }
            }
        }
        ++stats.objects;
    }
    return RecordFrame(s, settings, draws, planner.uniforms, out);
}

}  // namespace kiln::runtime
