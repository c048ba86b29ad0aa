#include "render/material_binding.h"

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "kiln/base/files.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/names.h"
#include "kiln/pack/pass_id.h"
#include "scene/gltf_input.h"

namespace kiln::runtime {
namespace {

using pack::PropertyType;
using pack::SectionTag;

bool HasAttribute(const pack::Pack& pack, const pack::PropertyRec& p, std::string_view name) {
    for (uint32_t i = 0; i < p.attribute_count; ++i) {
        const auto a =
            pack.Get<pack::AttributeRec>(SectionTag::kAttributes, p.first_attribute + i).value();
        if (pack.String(a.name) == name) {
            return true;
        }
    }
    return false;
}

std::optional<pack::PropertyRec> FindProperty(const pack::Pack& pack,
                                              uint32_t shader,
                                              std::string_view name) {
    const pack::ShaderRec s = pack.Shader(shader).value();
    for (uint32_t i = 0; i < s.property_count; ++i) {
        const auto p =
            pack.Get<pack::PropertyRec>(SectionTag::kProperties, s.first_property + i).value();
        if (pack.String(p.name) == name) {
            return p;
        }
    }
    return std::nullopt;
}

// sRGB-authored values become linear: Colors always, Floats/Vectors/Ranges marked [Gamma].
void Decode(const pack::Pack& pack,
            const pack::PropertyRec& p,
            const ColorPipeline& color,
            std::vector<float>& v) {
    const auto type = PropertyType(p.type);
    const bool gamma = HasAttribute(pack, p, "Gamma");
    if (type == PropertyType::kColor || (gamma && type == PropertyType::kVector)) {
        v.resize(4, type == PropertyType::kColor ? 1.0f : 0.0f);
        color.SrgbToLinear(v.data(), HasAttribute(pack, p, "HDR") || gamma);
    } else if (gamma && !v.empty()) {
        float rgb[3] = {v[0], v[0], v[0]};
        color.SrgbToLinear(rgb, true);
        v[0] = rgb[0];
    }
}

}  // namespace

void InstanceFromDefaults(const pack::Pack& pack,
                          uint32_t pack_index,
                          uint32_t shader,
                          const ColorPipeline& color,
                          MaterialInstance& out) {
    MaterialInstance m;
    m.pack = pack_index;
    m.shader = shader;
    m.transparent = pack::IsTransparentShader(pack, shader);  // its Queue tag
    m.name = "shader '" + std::string(pack.String(pack.Shader(shader).value().name)) + "' defaults";
    const pack::ShaderRec s = pack.Shader(shader).value();
    for (uint32_t i = 0; i < s.property_count; ++i) {
        const auto p =
            pack.Get<pack::PropertyRec>(SectionTag::kProperties, s.first_property + i).value();
        const std::string name(pack.String(p.name));
        const auto type = PropertyType(p.type);
        if (pack::IsTextureProperty(type)) {
            TextureBinding t;
            t.default_name = std::string(pack.String(p.texture_default));
            t.srgb = !(HasAttribute(pack, p, "Normal") || HasAttribute(pack, p, "Linear") ||
                       pack::FindDefaultTexture(t.default_name) ==
                           pack::FindDefaultTexture(pack::kDefaultTextureBump));
            m.textures[name] = t;
            m.values[name + "_ST"] = {1, 1, 0, 0};
            continue;
        }
        std::vector<float> v(p.default_value.begin(), p.default_value.end());
        if (type != PropertyType::kColor && type != PropertyType::kVector) {
            v.resize(1);
        }
        Decode(pack, p, color, v);
        m.values[name] = v;
    }
    out = std::move(m);
}

Status InstanceFromMaterialFile(const std::vector<const pack::Pack*>& packs,
                                const std::string& path,
                                const ColorPipeline& color,
                                MaterialInstance& out) {
    Result<std::string> text = base::ReadRegularFile(path, material::kMaxFileBytes);
    if (!text) {
        return Error{DiagCode::kCannotReadFile, text.error().message};
    }
    material::Material mat;
    DiagnosticList issues;
    // The first error, with its code and position; warnings (a texture not found) are left to
    // `kiln validate`.
    auto first_error = [&]() -> Status {
        for (const Diagnostic& d : issues.all()) {
            if (d.severity >= Severity::kError) {
                return Error{d.code, d.file + ":" + std::to_string(d.range.begin.line) + ":" +
                                         std::to_string(d.range.begin.column) + ": " + d.message};
            }
        }
        return {};
    };
    if (!material::ParseMaterial(text.value(), path, mat, issues)) {
        if (Status e = first_error(); !e.ok()) {
            return e;
        }
        return Error{DiagCode::kRenderFailed, path + ": not a valid material file"};
    }
    // The first pack holding the shader wins (packs are searched in the order given).
    for (uint32_t pi = 0; pi < packs.size(); ++pi) {
        const pack::Pack& pack = *packs[pi];
        const std::optional<uint32_t> shader = pack.FindShader(mat.shader);
        if (!shader) {
            continue;
        }
        const std::string dir = std::filesystem::path(path).parent_path().string();
        issues = DiagnosticList();
        material::ValidateMaterial(mat, pack, dir, issues);
        if (Status e = first_error(); !e.ok()) {
            return e;
        }
        MaterialInstance m;
        InstanceFromDefaults(pack, pi, *shader, color, m);
        m.name = path;
        for (const material::PropertyValue& v : mat.properties) {
            const std::optional<pack::PropertyRec> p = FindProperty(pack, *shader, v.name);
            if (!p) {
                continue;  // validated above
            }
            if (v.kind == material::PropertyValue::Kind::kTexture) {
                TextureBinding& t = m.textures[v.name];
                if (!v.texture.empty()) {
                    const std::filesystem::path file = std::filesystem::path(dir) / v.texture;
                    if (std::filesystem::exists(file)) {
                        t.source = TextureBinding::Source::kFile;
                        t.file = file.string();
                    }
                }
                m.values[v.name + "_ST"] = {float(v.scale[0]), float(v.scale[1]),
                                            float(v.offset[0]), float(v.offset[1])};
                continue;
            }
            std::vector<float> numbers(v.numbers.begin(), v.numbers.end());
            if (PropertyType(p->type) == PropertyType::kColor && numbers.size() == 3) {
                numbers.push_back(1.0f);
            }
            numbers.resize(std::max<size_t>(numbers.size(), 1), 0.0f);
            Decode(pack, *p, color, numbers);
            m.values[v.name] = numbers;
        }
        m.keywords = material::EnabledKeywords(mat, pack, *shader);
        for (const material::RenderStateOverride& o : mat.render_state) {
            m.overrides.push_back({o.field, o.values});
        }
        out = std::move(m);
        return {};
    }
    std::vector<std::string> shaders;
    for (const pack::Pack* pack : packs) {
        for (uint32_t i = 0; i < pack->Count(pack::SectionTag::kShaders); ++i) {
            shaders.emplace_back(pack->String(pack->Shader(i).value().name));
        }
    }
    return Error{DiagCode::kRenderFailed, path + ":" + std::to_string(mat.shader_pos.line) + ":" +
                                              std::to_string(mat.shader_pos.column) + ": shader '" +
                                              mat.shader + "' is in none of the loaded packs" +
                                              pack::DidYouMean(mat.shader, shaders)};
}

void ApplyGltfMaterial(const SceneMaterial& g, MaterialInstance& m) {
    m.name = "glTF material '" + g.name + "'";
    auto set = [&](const char* name, std::vector<float> v) { m.values[name] = std::move(v); };
    auto texture = [&](const char* name, const TextureRef& ref, bool srgb, const char* keyword) {
        if (ref.image < 0) {
            return false;
        }
        TextureBinding& t = m.textures[name];
        // KHR_texture_transform: scale and offset as Unity's tiling and offset, the rotation
        // and the UV set beside them.
        set((std::string(name) + "_ST").c_str(),
            {ref.uv_scale.x, ref.uv_scale.y, ref.offset.x, ref.offset.y});
        set((std::string(name) + "_UV").c_str(), {float(ref.texcoord), ref.rotation, 0.0f, 0.0f});
        t.source = TextureBinding::Source::kSceneImage;
        t.image = ref.image;
        t.srgb = srgb;
        t.wrap_u = ref.wrap_s;
        t.wrap_v = ref.wrap_t;
        t.nearest = ref.nearest;
        if (keyword) {
            m.keywords.emplace_back(keyword);
        }
        return true;
    };
    set("_Color", {g.base_color.r, g.base_color.g, g.base_color.b, g.base_color.a});
    texture("_MainTex", g.base_color_texture, true, nullptr);
    if (g.alpha_mode == AlphaMode::kMask) {
        m.keywords.emplace_back("_ALPHATEST_ON");
        set("_Cutoff", {g.alpha_cutoff});
    } else if (g.alpha_mode == AlphaMode::kBlend) {
        m.transparent = true;
        m.overrides.push_back({"Blend", {"SrcAlpha", "OneMinusSrcAlpha"}});
        m.overrides.push_back({"ZWrite", {"Off"}});
        m.add_overrides.push_back({"Blend", {"SrcAlpha", "One"}});
    }
    if (g.double_sided) {
        m.overrides.push_back({"Cull", {"Off"}});
    }
    if (g.unlit) {
        return;  // KHR_materials_unlit: the base colour alone (Kiln/Unlit)
    }
    set("_Metallic", {g.metallic});
    set("_Roughness", {g.roughness});
    texture("_MetallicGlossMap", g.metallic_roughness_texture, false, "_METALLICGLOSSMAP");
    if (texture("_BumpMap", g.normal_texture, false, "_NORMALMAP")) {
        set("_BumpScale", {g.normal_texture.scale});
    }
    if (texture("_OcclusionMap", g.occlusion_texture, false, "_OCCLUSIONMAP")) {
        set("_OcclusionStrength", {g.occlusion_texture.scale});
    }
    if (g.emissive != glm::vec3(0.0f)) {
        set("_EmissionColor", {g.emissive.r, g.emissive.g, g.emissive.b, 1.0f});
        texture("_EmissionMap", g.emissive_texture, true, nullptr);
        m.keywords.emplace_back("_EMISSION");
    }
}

void WriteMember(const pack::MemberRec& member,
                 const std::vector<float>& value,
                 uint8_t* dst,
                 size_t dst_size) {
    if (member.offset >= dst_size) {
        return;
    }
    std::memset(dst + member.offset, 0, std::min(size_t{member.size}, dst_size - member.offset));
    const size_t bytes =
        std::min({size_t{member.size}, value.size() * 4, dst_size - member.offset});
    const auto base = pack::BaseType(member.base_type);
    for (size_t k = 0; k < bytes / 4; ++k) {
        const float f = value[k];
        if (base == pack::BaseType::kInt || base == pack::BaseType::kBool) {
            const int32_t x = int32_t(f);
            std::memcpy(dst + member.offset + k * 4, &x, 4);
        } else if (base == pack::BaseType::kUInt) {
            const uint32_t x = f > 0 ? uint32_t(f) : 0u;
            std::memcpy(dst + member.offset + k * 4, &x, 4);
        } else {
            std::memcpy(dst + member.offset + k * 4, &f, 4);
        }
    }
}

void WriteBlock(const pack::Pack& pack,
                const pack::BlockRec& block,
                const ValueLookup& lookup,
                uint8_t* dst,
                size_t dst_size) {
    for (uint32_t i = 0; i < block.member_count; ++i) {
        const auto member =
            pack.Get<pack::MemberRec>(SectionTag::kMembers, block.first_member + i).value();
        if (const std::vector<float>* value = lookup(pack.String(member.name))) {
            WriteMember(member, *value, dst, dst_size);
        }
    }
}

}  // namespace kiln::runtime
