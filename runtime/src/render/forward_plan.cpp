#include "render/forward_plan.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <limits>

#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "render/frame_values.h"

namespace kiln::render {
namespace {

using runtime::Light;
using runtime::LightType;

const char* TypeName(LightType type) {
    return type == LightType::kPoint ? "point" : type == LightType::kSpot ? "spot" : "directional";
}

std::string LightName(const Light* light) {
    return light ? std::string(TypeName(light->type)) + " light '" + light->name + "'"
                 : std::string("no light");
}

// Material instances, built on first use: a sidecar .material, else the glTF material on
// Kiln/StandardMetallic. Slot materials.size() is glTF's default material.
struct Materials {
    const std::vector<const pack::Pack*>& packs;
    const runtime::Scene& scene;
    const runtime::ColorPipeline& color;
    std::deque<MaterialInstance>& store;
    std::vector<const MaterialInstance*> slots;

    Status For(int index, const MaterialInstance*& m) {
        const size_t slot = index < 0 ? scene.materials.size() : size_t(index);
        if (slots[slot]) {
            m = slots[slot];
            return {};
        }
        runtime::SceneMaterial gltf;
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
            bool found = false;
            for (uint32_t p = 0; p < packs.size() && !found; ++p) {
                if (auto shader = packs[p]->FindShader(pack::kShaderStandardMetallic)) {
                    InstanceFromDefaults(*packs[p], p, *shader, color, inst);
                    found = true;
                }
            }
            if (!found) {
                return Error{DiagCode::kRenderFailed,
                             "glTF material '" + gltf.name + "' needs shader '" +
                                 std::string(pack::kShaderStandardMetallic) +
                                 "', which is in none of the loaded packs (add the shipped "
                                 "materials.kpack)"};
            }
            ApplyGltfMaterial(gltf, inst);
            if (index >= 0 && gltf.name.empty()) {
                inst.name = "glTF material #" + std::to_string(index);  // for messages
            }
        }
        m = slots[slot] = &store.emplace_back(std::move(inst));
        return {};
    }
};

struct Item {
    const runtime::Instance* instance;
    const runtime::Primitive* primitive;
    const MaterialInstance* material;
    glm::vec3 center;
    float radius, depth;
};

// The keywords a draw asks for: the material's, then the light's (kiln/pack/engine_names.h).
std::vector<std::string> DrawKeywords(const MaterialInstance& m,
                                      bool additive,
                                      const Light* light,
                                      bool vertex_lights) {
    std::vector<std::string> keywords = m.keywords;
    if (additive) {
        const LightType type = light ? light->type : LightType::kDirectional;
        keywords.emplace_back(type == LightType::kPoint  ? pack::kKeywordPoint
                              : type == LightType::kSpot ? pack::kKeywordSpot
                                                         : pack::kKeywordDirectional);
        return keywords;
    }
    keywords.emplace_back(pack::kKeywordDirectional);
    // Objects without lightmaps take ambient light from the light probes (unity_SH*), as in
    // Unity; passes that do not declare the keyword ignore it.
    keywords.emplace_back(pack::kKeywordLightProbeSH);
    if (vertex_lights) {
        keywords.emplace_back(pack::kKeywordVertexLight);
    }
    return keywords;
}

}  // namespace

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

void WarnOnce(DiagnosticList& warnings,
              const runtime::Scene& scene,
              DiagCode code,
              std::string message) {
    const auto& all = warnings.all();
    if (std::none_of(all.begin(), all.end(),
                     [&](const Diagnostic& d) { return d.message == message; })) {
        warnings.Warning(code, scene.path, kNoPosition, std::move(message));
    }
}

Status PlanForward(const std::vector<const pack::Pack*>& packs,
                   const runtime::Scene& scene,
                   const runtime::FrameSettings& settings,
                   const glm::vec3& camera_position,
                   const runtime::ColorPipeline& color,
                   ForwardPlan& out,
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
    const Light* main = MainLight(out.lights);

    Materials materials{packs, scene, color, out.materials, {}};
    materials.slots.assign(scene.materials.size() + 1, nullptr);
    std::vector<Item> opaque, transparent;
    for (const runtime::Instance& inst : scene.instances) {
        for (const runtime::Primitive& prim : scene.meshes[inst.mesh].primitives) {
            const MaterialInstance* m = nullptr;
            if (Status e = materials.For(prim.material, m); !e.ok()) {
                return e;
            }
            glm::vec3 lo(std::numeric_limits<float>::max()), hi(-lo);
            for (const runtime::MeshVertex& v : prim.vertices) {
                const glm::vec3 w(inst.world * glm::vec4(glm::make_vec3(v.position), 1));
                lo = glm::min(lo, w);
                hi = glm::max(hi, w);
            }
            const glm::vec3 center = (lo + hi) * 0.5f;
            const float depth = glm::length(center - camera_position);
            (m->transparent ? transparent : opaque)
                .push_back({&inst, &prim, m, center, glm::length(hi - lo) * 0.5f, depth});
        }
    }
    std::stable_sort(transparent.begin(), transparent.end(),
                     [](const Item& a, const Item& b) { return a.depth > b.depth; });
    opaque.insert(opaque.end(), transparent.begin(), transparent.end());

    for (const Item& item : opaque) {
        const MaterialInstance& m = *item.material;
        const ShaderPasses passes = PassesOf(*packs[m.pack], m.shader);
        if (passes.base.empty()) {
            WarnOnce(warnings, scene, DiagCode::kPassNotDrawn,
                     m.name +
                         ": the shader has no ForwardBase or untagged pass; objects using it "
                         "are not drawn by the forward path");
            continue;
        }
        const ObjectLights lights =
            LightsFor(out.lights, main, item.center, item.radius, settings.pixel_lights);
        const std::string& mesh = scene.meshes[item.instance->mesh].name;
        const std::string who = m.name + " on " +
                                (!item.instance->node.empty() ? "node '" + item.instance->node + "'"
                                 : !mesh.empty()              ? "mesh '" + mesh + "'"
                                                              : std::string("an unnamed node")) +
                                ": ";
        for (uint32_t pass : passes.base) {
            DrawRequest r{item.instance, item.primitive, &m, pass, false,
                          lights.main,   lights.vertex,  {}, {}};
            r.keywords = DrawKeywords(m, false, lights.main, !lights.vertex.empty());
            r.reason = who + "base pass, " +
                       (lights.main ? "main " + LightName(lights.main) : "no directional light");
            if (!lights.vertex.empty()) {
                r.reason += ", " + std::to_string(lights.vertex.size()) + " vertex light" +
                            (lights.vertex.size() == 1 ? "" : "s");
            }
            out.draws.push_back(std::move(r));
        }
        if (passes.add) {
            for (const Light* light : lights.pixel) {
                DrawRequest r{
                    item.instance, item.primitive, &m, *passes.add, true, light, {}, {}, {}};
                r.keywords = DrawKeywords(m, true, light, false);
                r.reason = who + "additive pass, " + LightName(light);
                out.draws.push_back(std::move(r));
            }
        }
        ++out.objects;
    }
    return {};
}

}  // namespace kiln::render
