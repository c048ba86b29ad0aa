#include "render/draw_builder.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>

#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "kiln/pack/render_state.h"
#include "render/textures.h"

namespace kiln::runtime {
namespace {

bool Written(const std::vector<Draw::Write>& writes, uint32_t set, uint32_t binding) {
    return std::any_of(writes.begin(), writes.end(),
                       [&](const Draw::Write& w) { return w.set == set && w.binding == binding; });
}

// "Cull Back, ZTest LEqual, ZWrite On, Blend One One, ColorMask RGB" (target 0), with the names
// of kiln/pack/render_state.h.
std::string Describe(const pack::PassState& st, bool additive) {
    auto name = [](pack::StateValues set, uint32_t value) {
        const auto names = pack::StateValueNames(set);
        return value < names.size() ? std::string(names[value]) : std::to_string(value);
    };
    std::string out = "Cull " + name(pack::StateValues::kCull, uint32_t(st.cull)) + ", ZTest " +
                      (st.ztest == pack::CompareFunction::kDisabled
                           ? std::string("Off")
                           : name(pack::StateValues::kCompare, uint32_t(st.ztest))) +
                      ", ZWrite " + (st.zwrite ? "On" : "Off");
    const pack::BlendTargetState& t = st.targets[0];
    out += t.enable ? ", Blend " + name(pack::StateValues::kBlendFactor, uint32_t(t.src)) + " " +
                          name(pack::StateValues::kBlendFactor, uint32_t(t.dst))
                    : std::string(", Blend Off");
    // Additive passes never write the frame's alpha (coverage).
    const uint32_t mask = additive ? t.color_mask & ~uint32_t(pack::kColorWriteA) : t.color_mask;
    out += ", ColorMask " + pack::ColorMaskName(mask);
    if (st.stencil) {
        out += ", Stencil";
    }
    return out;
}

}  // namespace

DrawBuilder::DrawBuilder(Renderer::State& s,
                         SceneResources& resources,
                         const Scene& scene,
                         Values frame,
                         FrameStats& stats,
                         bool record_info)
    : s_(s),
      resources_(resources),
      scene_(scene),
      frame_values_(std::move(frame)),
      stats_(stats),
      record_info_(record_info) {
    alignment_ =
        std::max<VkDeviceSize>(256, s.context.properties.limits.minUniformBufferOffsetAlignment);
}

void DrawBuilder::BeginPass(const Frame& frame,
                            const FramePass& pass,
                            std::map<std::string, uint32_t, std::less<>> target_textures) {
    frame_ = &frame;
    targets_ = FormatsOf(frame, pass);
    target_textures_ = std::move(target_textures);
    bindings_.clear();  // pipelines and sampled targets differ between passes
}

void DrawBuilder::Warn(DiagCode code, std::string message) {
    WarnOnce(stats_.warnings, scene_, code, std::move(message));
}

Status DrawBuilder::Pipeline(const MaterialInstance& m,
                             uint32_t pass,
                             uint32_t variant,
                             bool additive,
                             bool mirrored,
                             bool depth_only,
                             const std::vector<std::string>& chosen,
                             Binding& out) {
    const pack::Pack& pack = s_.packs[m.pack]->pack;
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
        return Error{DiagCode::kRenderFailed,
                     m.name + ": pass '" + pack::PassLabel(pack, pass) + "': " + e.error().message};
    }
    state.front_clockwise = mirrored;
    if (depth_only) {
        for (vk::BlendTarget& t : state.targets) {
            t.mask = 0;
        }
    }
    if (additive) {
        // The frame's alpha is coverage (docs/runtime.md): an additive pass adds light, and
        // its Blend One One would add 1 to the alpha per light.
        for (vk::BlendTarget& t : state.targets)
            t.mask &= ~VkColorComponentFlags(VK_COLOR_COMPONENT_A_BIT);
    }
    if (record_info_) {
        if (Result<pack::PassState> resolved =
                pack::ResolvePassState(pack, pass, number, overrides)) {
            out.state = Describe(resolved.value(), additive);
        }
    }
    if (Status e = s_.GetPipeline(m.pack, variant, state, targets_, out.pipeline,
                                  stats_.pipelines_created);
        !e.ok()) {
        return Error{e.error().code,
                     "shader '" + std::string(pack.String(pack.Shader(m.shader).value().name)) +
                         "' pass '" + pack::PassLabel(pack, pass) + "' variant '" +
                         pack::JoinKeywords(chosen) + "': " + e.error().message};
    }
    return {};
}

// A frame target sampled by name (the light pass's G-buffer and depth): nearest texels, clamped
// (a grab texture: bilinear).
// A shadow map: with the depth-comparison sampler.
Status DrawBuilder::TargetTexture(uint32_t target, pack::ResourceKind kind, Draw::Write& out) {
    VkSampler sampler = VK_NULL_HANDLE;
    if (Status e = frame_->targets[target].shadow_map
                       ? s_.ShadowSampler(sampler)
                       : s_.Sampler(TextureWrap::kClampToEdge, TextureWrap::kClampToEdge,
                                    !frame_->targets[target].filtered, sampler, true);
        !e.ok()) {
        return e;
    }
    out.type = kind == pack::ResourceKind::kSeparateImage ? VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE
               : kind == pack::ResourceKind::kSeparateSampler
                   ? VK_DESCRIPTOR_TYPE_SAMPLER
                   : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    out.image.sampler = kind == pack::ResourceKind::kSeparateImage ? VK_NULL_HANDLE : sampler;
    if (kind != pack::ResourceKind::kSeparateSampler) {
        out.target = int(target);  // RecordFrame fills in the view and layout
    }
    return {};
}

Status DrawBuilder::Textures(const MaterialInstance& m,
                             const pack::VariantRec& v,
                             int shadow_map,
                             Binding& out) {
    const pack::Pack& pack = s_.packs[m.pack]->pack;
    for (uint32_t module : pack.ModulesOf(v)) {
        const pack::ModuleRec mod = pack.Module(module).value();
        for (uint32_t r = 0; r < mod.resource_count; ++r) {
            const auto res =
                pack.Get<pack::ResourceRec>(pack::SectionTag::kResources, mod.first_resource + r)
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
            auto named = target_textures_.find(name);
            if (named != target_textures_.end() ||
                (shadow_map >= 0 && name == pack::kTextureShadowMap)) {
                const uint32_t target =
                    named != target_textures_.end() ? named->second : uint32_t(shadow_map);
                Draw::Write w{res.set, res.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
                if (Status e = TargetTexture(target, kind, w); !e.ok()) {
                    return e;
                }
                const float fw = float(frame_->width), fh = float(frame_->height);
                out.texel_sizes[name + "_TexelSize"] = {1.0f / fw, 1.0f / fh, fw, fh};
                out.textures.push_back(w);
                if (record_info_ && kind != pack::ResourceKind::kSeparateSampler) {
                    const FrameTarget& ft = frame_->targets[target];
                    const uint32_t side = ft.size;
                    out.texture_info.push_back({name, "frame target '" + ft.name + "'",
                                                side ? side : frame_->width,
                                                side ? side : frame_->height, ft.format, nullptr});
                }
                continue;
            }
            if (name == pack::kTextureShadowMap && (kind == pack::ResourceKind::kSeparateImage ||
                                                    kind == pack::ResourceKind::kSeparateSampler)) {
                // A depth map or cube compared with a comparison sampler, drawn without its
                // light's map (kiln test, shadows off): the renderer's map at depth 1, lit.
                Draw::Write w{res.set, res.binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE};
                if (kind == pack::ResourceKind::kSeparateSampler) {
                    w.type = VK_DESCRIPTOR_TYPE_SAMPLER;
                    if (Status e = s_.ShadowSampler(w.image.sampler); !e.ok()) {
                        return e;
                    }
                } else {
                    const vk::Image* map = nullptr;
                    if (Status e = s_.DefaultShadowMap(ShapeOf(res) == vk::ImageShape::kCube, map);
                        !e.ok()) {
                        return e;
                    }
                    w.image = {VK_NULL_HANDLE, map->view,
                               VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
                }
                out.texel_sizes[name + "_TexelSize"] = {1, 1, 1, 1};
                out.textures.push_back(w);
                if (record_info_ && kind == pack::ResourceKind::kSeparateImage) {
                    out.texture_info.push_back(
                        {name, "no shadow map drawn: the renderer's map at depth 1 (lit)", 1, 1,
                         VK_FORMAT_UNDEFINED, nullptr});
                }
                continue;
            }
            vk::ImageShape shape = vk::ImageShape::k2D;  // a lone sampler has none
            if (kind != pack::ResourceKind::kSeparateSampler) {
                const std::optional<vk::ImageShape> declared = ShapeOf(res);
                if (!declared) {
                    return Error{DiagCode::kRenderFailed,
                                 m.name + ": texture '" + name +
                                     "' is 1D or a texel buffer, which the runtime cannot bind"};
                }
                shape = *declared;
            }
            BoundTexture t;
            auto it = m.textures.find(name);
            if (Status e = resources_.textures->Get(
                    it == m.textures.end() ? UnsetTexture(name) : it->second, shape, t);
                !e.ok()) {
                return e;
            }
            if (!t.warning.empty()) {
                Warn(DiagCode::kTextureFallback, m.name + ": " + t.warning);
            }
            out.texel_sizes[name + "_TexelSize"] = {1.0f / float(t.width), 1.0f / float(t.height),
                                                    float(t.width), float(t.height)};
            if (record_info_ && kind != pack::ResourceKind::kSeparateSampler) {
                out.texture_info.push_back(
                    {name, t.source, t.width, t.height, t.format, t.thumbnail});
            }
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

// The variant's uniform and push-constant blocks, written from `lookup`.
void DrawBuilder::Uniforms(const pack::Pack& pack,
                           const pack::VariantRec& v,
                           const ValueLookup& lookup,
                           Draw& d) {
    for (uint32_t module : pack.ModulesOf(v)) {
        const pack::ModuleRec mod = pack.Module(module).value();
        for (uint32_t b = 0; b < mod.block_count; ++b) {
            const auto block =
                pack.Get<pack::BlockRec>(pack::SectionTag::kBlocks, mod.first_block + b).value();
            if (pack::BlockKind(block.kind) == pack::BlockKind::kPushConstant) {
                d.push.assign(d.pipeline->layout.push_constant_size, 0);
                WriteBlock(pack, block, lookup, d.push.data(), d.push.size());
                continue;
            }
            if (Written(d.writes, block.set, block.binding)) {
                continue;  // the textures' or an earlier module's
            }
            const VkDeviceSize offset =
                (uniforms_.size() + alignment_ - 1) / alignment_ * alignment_;
            uniforms_.resize(offset + block.size, 0);
            WriteBlock(pack, block, lookup, uniforms_.data() + offset, block.size);
            Draw::Write w{block.set, block.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
            w.offset = offset;
            w.range = block.size;
            d.writes.push_back(w);
        }
    }
}

void DrawBuilder::PlannedUniforms(const pack::Pack& pack,
                                  const pack::VariantRec& v,
                                  Binding& binding,
                                  const ValueLookup& fixed,
                                  std::span<const Values* const> per_draw,
                                  Draw& d) {
    size_t k = 0;
    for (uint32_t module : pack.ModulesOf(v)) {
        const pack::ModuleRec mod = pack.Module(module).value();
        for (uint32_t b = 0; b < mod.block_count; ++b, ++k) {
            const auto block =
                pack.Get<pack::BlockRec>(pack::SectionTag::kBlocks, mod.first_block + b).value();
            const bool push = pack::BlockKind(block.kind) == pack::BlockKind::kPushConstant;
            if (k == binding.plans.size()) {  // the binding's first draw
                Binding::BlockPlan& plan = binding.plans.emplace_back();
                plan.base.assign(push ? d.pipeline->layout.push_constant_size : block.size, 0);
                WriteBlock(pack, block, fixed, plan.base.data(), plan.base.size());
                for (uint32_t i = 0; i < block.member_count; ++i) {
                    const auto member = pack.Get<pack::MemberRec>(pack::SectionTag::kMembers,
                                                                  block.first_member + i)
                                            .value();
                    plan.members.emplace_back(std::string(pack.String(member.name)), member);
                }
                std::sort(plan.members.begin(), plan.members.end(),
                          [](const auto& x, const auto& y) { return x.first < y.first; });
            }
            const Binding::BlockPlan& plan = binding.plans[k];
            uint8_t* dst = nullptr;
            if (push) {
                d.push = plan.base;
                dst = d.push.data();
            } else if (Written(d.writes, block.set, block.binding)) {
                continue;  // the textures' or an earlier module's
            } else {
                const VkDeviceSize offset =
                    (uniforms_.size() + alignment_ - 1) / alignment_ * alignment_;
                uniforms_.resize(offset);
                uniforms_.insert(uniforms_.end(), plan.base.begin(), plan.base.end());
                dst = uniforms_.data() + offset;
                Draw::Write w{block.set, block.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
                w.offset = offset;
                w.range = block.size;
                d.writes.push_back(w);
            }
            for (const Values* table : per_draw) {
                if (!table) {
                    continue;
                }
                // Both sorted by name: one walk along the two.
                auto member = plan.members.begin();
                for (auto entry = table->begin();
                     entry != table->end() && member != plan.members.end();) {
                    const int order = entry->first.compare(member->first);
                    if (order == 0) {
                        WriteMember(member->second, entry->second, dst, plan.base.size());
                    }
                    if (order <= 0) {
                        ++entry;
                    }
                    if (order >= 0) {
                        ++member;
                    }
                }
            }
        }
    }
}

Status DrawBuilder::BuildForward(std::span<const DrawRequest> requests, std::vector<Draw>& draws) {
    for (const DrawRequest& r : requests) {
        if (Status e = Build(r, draws); !e.ok()) {
            return e;
        }
        (r.additive ? stats_.add_passes : stats_.base_passes)++;
    }
    return {};
}

Status DrawBuilder::Build(const DrawRequest& request, std::vector<Draw>& draws) {
    const MaterialInstance& m = *request.material;
    const uint32_t pass = request.pass;
    const bool additive = request.additive;
    LoadedPack& lp = *s_.packs[m.pack];
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
    // glTF 2.0, 3.5.3: a node whose transform has a negative determinant has its winding
    // reversed.
    const bool mirrored =
        (request.instance && glm::determinant(glm::mat3(request.instance->world)) < 0.0f) !=
        request.mirrored_view;
    auto [it, fresh] =
        bindings_.try_emplace({&m, pass, choice.variant, additive, mirrored, request.shadow_map});
    Binding& binding = it->second;
    if (fresh) {
        const std::vector<std::string> chosen = pack.KeywordsOf(pass, pack::VariantKey(v.key));
        binding.vertex_light =
            std::count(chosen.begin(), chosen.end(), pack::kKeywordVertexLight) > 0;
        binding.keywords = pack::JoinKeywords(chosen);
        if (Status e = Pipeline(m, pass, choice.variant, additive, mirrored, request.depth_only,
                                chosen, binding);
            !e.ok()) {
            bindings_.erase(it);
            return e;
        }
        if (Status e = Textures(m, v, request.shadow_map, binding); !e.ok()) {
            bindings_.erase(it);
            return e;
        }
    }
    if (!additive && binding.vertex_light) {
        ++stats_.vertex_lit;
    }
    Draw d;
    d.pipeline = binding.pipeline;
    d.writes = binding.textures;
    if (record_info_) {  // for the frame debugger only: strings per draw
        d.info.shader = std::string(pack.String(pack.Shader(m.shader).value().name));
        d.info.pass = pack::PassLabel(pack, pass);
        d.info.light_mode = std::string(pack::LightModeOf(pack, pass));
        d.info.keywords = binding.keywords;
        d.info.state = binding.state;
        d.info.light = request.light ? LightName(request.light) : std::string();
        if (request.instance) {
            d.info.object = ObjectLabel(scene_, *request.instance, m);
        }
        d.info.textures = binding.texture_info;
    }
    if (request.instance) {
        const uint32_t mesh = request.instance->mesh;
        const uint32_t primitive =
            uint32_t(request.primitive - scene_.meshes[mesh].primitives.data());
        if (Status e = resources_.Buffers(scene_, mesh, primitive, d.vertices, d.indices);
            !e.ok()) {
            return e;
        }
        d.index_count = uint32_t(request.primitive->indices.size());
        if (record_info_) {
            d.info.mesh =
                "mesh '" + scene_.meshes[mesh].name + "', primitive " + std::to_string(primitive);
            d.info.vertex_count = uint32_t(request.primitive->vertices.size());
        }
    } else {
        if (Status e = s_.ScreenTriangle(d.vertices, d.indices); !e.ok()) {
            return e;
        }
        d.index_count = 3;
        if (record_info_) {
            d.info.mesh = "the full-screen triangle";
            d.info.vertex_count = 3;
        }
    }
    d.info.index_count = record_info_ ? d.index_count : 0;

    // A light's values once per frame, however many objects it lights.
    auto [light_it, light_fresh] = light_values_.try_emplace(
        {request.light, additive ? std::vector<const Light*>{} : request.vertex});
    if (light_fresh) {
        light_it->second = LightValues(request.light, light_it->first.second);
    }
    const Values* lights = &light_it->second;
    Values with_sh;
    if (!additive && !request.sh.empty()) {
        // Read before the frame's probe: this object's ambient plus its SH lights.
        with_sh = *lights;
        with_sh.merge(ProbeValues(scene_, request.sh, request.center));
        lights = &with_sh;
        ++stats_.sh_lit;
    }
    glm::mat4 view(1.0f);
    if (const auto v_it = frame_values_.find("unity_MatrixV");
        v_it != frame_values_.end() && v_it->second.size() == 16) {
        view = glm::make_mat4(v_it->second.data());
    }
    auto [object_it, object_fresh] = object_values_.try_emplace(request.instance);
    if (object_fresh) {
        object_it->second =
            ObjectValues(request.instance ? request.instance->world : glm::mat4(1.0f), view);
    }
    const Values& object = object_it->second;
    const ValueLookup lookup = [&](std::string_view name) -> const std::vector<float>* {
        for (const Values* table : std::initializer_list<const Values*>{
                 request.values, &object, lights, &frame_values_, &binding.texel_sizes}) {
            if (!table) {
                continue;
            }
            if (auto found = table->find(name); found != table->end()) {
                return &found->second;
            }
        }
        auto found = m.values.find(name);
        return found == m.values.end() ? nullptr : &found->second;
    };
    if (!record_info_) {
        // The binding's values once (its plans), the draw's own over them.
        const ValueLookup fixed = [&](std::string_view name) -> const std::vector<float>* {
            for (const Values* table : {&frame_values_, &binding.texel_sizes}) {
                if (auto found = table->find(name); found != table->end()) {
                    return &found->second;
                }
            }
            auto found = m.values.find(name);
            return found == m.values.end() ? nullptr : &found->second;
        };
        const Values* per_draw[] = {lights, &object, request.values};  // lowest precedence first
        PlannedUniforms(pack, v, binding, fixed, per_draw, d);
    } else {  // the frame debugger's record of every member as written
        std::map<std::string, std::vector<float>, std::less<>> seen;
        const ValueLookup recording = [&](std::string_view name) -> const std::vector<float>* {
            const std::vector<float>* found = lookup(name);
            if (found) {
                seen.try_emplace(std::string(name), *found);
            }
            return found;
        };
        Uniforms(pack, v, recording, d);
        d.info.values.assign(seen.begin(), seen.end());
    }
    draws.push_back(std::move(d));
    return {};
}

}  // namespace kiln::runtime
