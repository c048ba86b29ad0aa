#include "scene/gltf_extensions.h"

#include <tiny_gltf.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <utility>

namespace kiln::runtime {
namespace {

constexpr std::array<std::string_view, 5> kSupported = {
    "KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_materials_unlit",
    "KHR_mesh_quantization", "KHR_texture_transform"};

// Extensions Kiln does not implement that files commonly carry, named for messages.
constexpr std::array<std::pair<std::string_view, std::string_view>, 24> kKnown = {{
    {"KHR_draco_mesh_compression", "Draco mesh compression"},
    {"EXT_meshopt_compression", "meshoptimizer buffer compression"},
    {"KHR_meshopt_compression", "meshoptimizer buffer compression"},
    {"KHR_texture_basisu", "KTX2 / Basis Universal textures"},
    {"EXT_texture_webp", "WebP textures"},
    {"EXT_texture_avif", "AVIF textures"},
    {"MSFT_texture_dds", "DDS textures"},
    {"KHR_materials_pbrSpecularGlossiness", "the specular-glossiness material workflow"},
    {"KHR_materials_transmission", "transmission"},
    {"KHR_materials_volume", "volume (thickness and attenuation)"},
    {"KHR_materials_ior", "index of refraction"},
    {"KHR_materials_specular", "the specular layer"},
    {"KHR_materials_clearcoat", "clear coat"},
    {"KHR_materials_sheen", "sheen"},
    {"KHR_materials_iridescence", "iridescence"},
    {"KHR_materials_anisotropy", "anisotropy"},
    {"KHR_materials_dispersion", "dispersion"},
    {"KHR_materials_diffuse_transmission", "diffuse transmission"},
    {"KHR_materials_variants", "material variants"},
    {"KHR_animation_pointer", "animation pointers"},
    {"KHR_xmp_json_ld", "XMP metadata"},
    {"EXT_mesh_gpu_instancing", "GPU instancing (the instances are not drawn)"},
    {"EXT_lights_image_based", "image-based lights"},
    {"MSFT_lod", "levels of detail"},
}};

std::string Named(std::string_view name) {
    const std::string_view what = ExtensionDescription(name);
    return "'" + std::string(name) + "'" + (what.empty() ? "" : " (" + std::string(what) + ")");
}

}  // namespace

bool IsSupportedExtension(std::string_view name) {
    return std::find(kSupported.begin(), kSupported.end(), name) != kSupported.end();
}

std::string_view ExtensionDescription(std::string_view name) {
    for (const auto& [known, what] : kKnown) {
        if (known == name) {
            return what;
        }
    }
    return {};
}

Status CheckRequiredExtensions(const std::string& path, const std::vector<std::string>& required) {
    for (const std::string& name : required) {
        if (!IsSupportedExtension(name)) {
            return Error{DiagCode::kUnsupportedExtension,
                         path + ": the file requires extension " + Named(name) +
                             ", which Kiln does not support (it reads KHR_lights_punctual, "
                             "KHR_materials_emissive_strength, KHR_materials_unlit, "
                             "KHR_mesh_quantization and KHR_texture_transform)"};
        }
    }
    return {};
}

std::vector<std::string> RequiredExtensionsOf(std::string_view json) {
    std::vector<std::string> out;
    const nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    if (!doc.is_object()) {
        return out;
    }
    const auto it = doc.find("extensionsRequired");
    if (it == doc.end() || !it->is_array()) {
        return out;
    }
    for (const nlohmann::json& name : *it) {
        if (name.is_string()) {
            out.push_back(name.get<std::string>());
        }
    }
    return out;
}

void WarnIgnoredFeatures(const tinygltf::Model& model,
                         const std::string& path,
                         DiagnosticList& diags) {
    auto warn = [&](const std::string& message) {
        diags.Warning(DiagCode::kSceneContentIgnored, path, kNoPosition, message);
    };
    for (const std::string& name : model.extensionsUsed) {
        if (!IsSupportedExtension(name)) {
            warn("extension " + Named(name) +
                 " is not supported; the file uses it optionally "
                 "and is drawn without it");
        }
    }
    if (!model.skins.empty()) {
        warn(std::to_string(model.skins.size()) +
             " skin(s) ignored: skinned meshes are drawn in their bind pose");
    }
    if (!model.animations.empty()) {
        warn(std::to_string(model.animations.size()) +
             " animation(s) ignored: the scene is drawn at its rest pose");
    }
    size_t morphed = 0;
    for (const tinygltf::Mesh& mesh : model.meshes) {
        for (const tinygltf::Primitive& p : mesh.primitives) {
            morphed += p.targets.empty() ? 0 : 1;
        }
    }
    if (morphed > 0) {
        warn("morph targets of " + std::to_string(morphed) +
             " primitive(s) ignored: meshes are drawn without them (weights 0)");
    }
}

}  // namespace kiln::runtime
