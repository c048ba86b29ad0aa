#include "scene/gltf_material.h"

#include <tiny_gltf.h>

#include <cmath>

namespace kiln::runtime {
namespace {

TextureWrap WrapOf(int gl) {
    switch (gl) {
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
            return TextureWrap::kClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
            return TextureWrap::kMirroredRepeat;
        default:  // REPEAT, glTF's default
            return TextureWrap::kRepeat;
    }
}

// A finite number of a JSON value, else `fallback`.
float NumberOr(const tinygltf::Value& v, float fallback) {
    if (!v.IsNumber()) {
        return fallback;
    }
    const double d = v.GetNumberAsDouble();
    return std::isfinite(d) ? float(d) : fallback;
}

// KHR_texture_transform (offset, rotation, scale, texCoord) of a textureInfo's extensions.
void ReadTransform(const tinygltf::ExtensionMap& extensions, TextureRef& ref) {
    const auto it = extensions.find("KHR_texture_transform");
    if (it == extensions.end() || !it->second.IsObject()) {
        return;
    }
    const tinygltf::Value& t = it->second;
    auto pair = [&](const char* key, glm::vec2& out) {
        const tinygltf::Value& v = t.Get(key);
        if (v.IsArray() && v.ArrayLen() == 2) {
            out = glm::vec2(NumberOr(v.Get(0), out.x), NumberOr(v.Get(1), out.y));
        }
    };
    pair("offset", ref.offset);
    pair("scale", ref.uv_scale);
    ref.rotation = NumberOr(t.Get("rotation"), 0.0f);
    if (const tinygltf::Value& tc = t.Get("texCoord"); tc.IsInt() && tc.GetNumberAsInt() >= 0) {
        ref.texcoord = tc.GetNumberAsInt();
    }
}

struct MapReader {
    const tinygltf::Model& m;
    const std::string& path;
    const std::string& material;
    DiagnosticList& diags;

    TextureRef Read(const char* map,
                    int texture,
                    int texcoord,
                    float scale,
                    const tinygltf::ExtensionMap& extensions) const {
        TextureRef ref;
        if (texture < 0 || size_t(texture) >= m.textures.size()) {
            return ref;
        }
        const tinygltf::Texture& t = m.textures[size_t(texture)];
        if (t.source < 0 || size_t(t.source) >= m.images.size()) {
            return ref;
        }
        ref.image = t.source;
        ref.texcoord = texcoord;
        ref.scale = scale;
        if (t.sampler >= 0 && size_t(t.sampler) < m.samplers.size()) {
            const tinygltf::Sampler& s = m.samplers[size_t(t.sampler)];
            ref.wrap_s = WrapOf(s.wrapS);
            ref.wrap_t = WrapOf(s.wrapT);
            ref.nearest = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
        }
        ReadTransform(extensions, ref);
        if (ref.texcoord > 1) {
            diags.Warning(DiagCode::kSceneContentIgnored, path, kNoPosition,
                          "material '" + material + "': " + map + " reads TEXCOORD_" +
                              std::to_string(ref.texcoord) +
                              ", and Kiln's vertex has TEXCOORD_0 and TEXCOORD_1; it reads "
                              "TEXCOORD_0 instead");
            ref.texcoord = 0;
        }
        return ref;
    }
};

}  // namespace

SceneMaterial ReadGltfMaterial(const tinygltf::Model& m,
                               size_t index,
                               const std::string& path,
                               DiagnosticList& diags) {
    const tinygltf::Material& g = m.materials[index];
    SceneMaterial s;
    s.name = g.name;
    const std::string label = g.name.empty() ? "#" + std::to_string(index) : g.name;
    const MapReader maps{m, path, label, diags};
    const auto& pbr = g.pbrMetallicRoughness;
    for (int i = 0; i < 4 && size_t(i) < pbr.baseColorFactor.size(); ++i) {
        s.base_color[i] = float(pbr.baseColorFactor[size_t(i)]);
    }
    s.metallic = float(pbr.metallicFactor);
    s.roughness = float(pbr.roughnessFactor);
    for (int i = 0; i < 3 && size_t(i) < g.emissiveFactor.size(); ++i) {
        s.emissive[i] = float(g.emissiveFactor[size_t(i)]);
    }
    if (auto it = g.extensions.find("KHR_materials_emissive_strength"); it != g.extensions.end()) {
        s.emissive *= NumberOr(it->second.Get("emissiveStrength"), 1.0f);
    }
    s.unlit = g.extensions.count("KHR_materials_unlit") > 0;
    const auto& base = pbr.baseColorTexture;
    s.base_color_texture =
        maps.Read("baseColorTexture", base.index, base.texCoord, 1, base.extensions);
    const auto& mr = pbr.metallicRoughnessTexture;
    s.metallic_roughness_texture =
        maps.Read("metallicRoughnessTexture", mr.index, mr.texCoord, 1, mr.extensions);
    const auto& normal = g.normalTexture;
    s.normal_texture = maps.Read("normalTexture", normal.index, normal.texCoord,
                                 float(normal.scale), normal.extensions);
    const auto& occlusion = g.occlusionTexture;
    s.occlusion_texture = maps.Read("occlusionTexture", occlusion.index, occlusion.texCoord,
                                    float(occlusion.strength), occlusion.extensions);
    const auto& emissive = g.emissiveTexture;
    s.emissive_texture =
        maps.Read("emissiveTexture", emissive.index, emissive.texCoord, 1, emissive.extensions);
    s.alpha_mode = g.alphaMode == "MASK"    ? AlphaMode::kMask
                   : g.alphaMode == "BLEND" ? AlphaMode::kBlend
                                            : AlphaMode::kOpaque;
    s.alpha_cutoff = float(g.alphaCutoff);
    s.double_sided = g.doubleSided;
    return s;
}

}  // namespace kiln::runtime
