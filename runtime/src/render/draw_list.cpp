#include "render/draw_list.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <limits>

#include "kiln/pack/engine_names.h"
#include "render/frame_values.h"

namespace kiln::runtime {

Status MaterialCache::For(const std::vector<const pack::Pack*>& packs,
                          const Scene& scene,
                          const ColorPipeline& color,
                          int index,
                          const MaterialInstance*& out) {
    if (slots_.size() != scene.materials.size() + 1) {
        slots_.assign(scene.materials.size() + 1, nullptr);
    }
    const size_t slot = index < 0 ? scene.materials.size() : size_t(index);
    if (slots_[slot]) {
        out = slots_[slot];
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
        if (Status e = InstanceFromMaterialFile(packs, it->second, color, inst); !e.ok()) {
            return e;
        }
    } else {
        const char* wanted = gltf.unlit ? pack::kShaderUnlit : pack::kShaderStandardMetallic;
        bool found = false;
        for (uint32_t p = 0; p < packs.size() && !found; ++p) {
            if (auto shader = packs[p]->FindShader(wanted)) {
                InstanceFromDefaults(*packs[p], p, *shader, color, inst);
                found = true;
            }
        }
        if (!found) {
            return Error{DiagCode::kRenderFailed,
                         "glTF material '" + gltf.name + "' needs shader '" + wanted +
                             "', which is in none of the loaded packs (add the shipped "
                             "materials.kpack)"};
        }
        ApplyGltfMaterial(gltf, inst);
        if (index >= 0 && gltf.name.empty()) {
            inst.name = "glTF material #" + std::to_string(index);  // for messages
        }
    }
    out = slots_[slot] = &store_.emplace_back(std::move(inst));
    return {};
}

std::pair<glm::vec3, float> WorldSphere(const Primitive& prim, const glm::mat4& world) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-lo);
    if (prim.bounds_min.x <= prim.bounds_max.x) {
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 local((corner & 1) ? prim.bounds_max.x : prim.bounds_min.x,
                                  (corner & 2) ? prim.bounds_max.y : prim.bounds_min.y,
                                  (corner & 4) ? prim.bounds_max.z : prim.bounds_min.z);
            const glm::vec3 w(world * glm::vec4(local, 1));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    } else {  // a scene built by hand without ComputeBounds
        for (const MeshVertex& v : prim.vertices) {
            const glm::vec3 w(world * glm::vec4(glm::make_vec3(v.position), 1));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    }
    if (lo.x > hi.x) {
        return {glm::vec3(world[3]), 0.0f};
    }
    return {(lo + hi) * 0.5f, glm::length(hi - lo) * 0.5f};
}

void WarnOnce(DiagnosticList& warnings, const Scene& scene, DiagCode code, std::string message) {
    const auto& all = warnings.all();
    if (std::none_of(all.begin(), all.end(),
                     [&](const Diagnostic& d) { return d.message == message; })) {
        warnings.Warning(code, scene.path, kNoPosition, std::move(message));
    }
}

Status BuildDrawList(const std::vector<const pack::Pack*>& packs,
                     const Scene& scene,
                     const FrameSettings& settings,
                     const glm::vec3& camera_position,
                     const ColorPipeline& color,
                     MaterialCache& materials,
                     DrawList& out,
                     DiagnosticList& warnings) {
    out.lights = scene.lights;
    if (out.lights.empty() && settings.default_light) {
        Light key;
        key.name = "default light";
        key.type = LightType::kDirectional;
        key.direction = glm::normalize(glm::vec3(-0.35f, -0.8f, -0.5f));
        key.intensity = 3.14159265f;  // pi lux: _LightColor0 = 1, Unity's default light
        out.lights.push_back(key);
        WarnOnce(warnings, scene, DiagCode::kDefaultLight,
                 "the scene has no KHR_lights_punctual lights: lit by a default directional "
                 "light of pi lux (Unity's intensity 1) shining along (-0.35, -0.8, -0.5)");
    }
    out.main = MainLight(out.lights);

    std::vector<DrawItem> transparent;
    for (const Instance& inst : scene.instances) {
        for (const Primitive& prim : scene.meshes[inst.mesh].primitives) {
            const MaterialInstance* m = nullptr;
            if (Status e = materials.For(packs, scene, color, prim.material, m); !e.ok()) {
                return e;
            }
            if (std::find(out.materials.begin(), out.materials.end(), m) == out.materials.end()) {
                out.materials.push_back(m);
            }
            const auto [center, radius] = WorldSphere(prim, inst.world);
            const float depth = glm::length(center - camera_position);
            (m->transparent ? transparent : out.items)
                .push_back({&inst, &prim, m, center, radius, depth});
        }
    }
    std::stable_sort(transparent.begin(), transparent.end(),
                     [](const DrawItem& a, const DrawItem& b) { return a.depth > b.depth; });
    out.items.insert(out.items.end(), transparent.begin(), transparent.end());
    return {};
}

}  // namespace kiln::runtime
