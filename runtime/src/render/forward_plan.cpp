#include "render/forward_plan.h"

#include <algorithm>

#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "render/frame_values.h"
#include "render/shadow_plan.h"

namespace kiln::runtime {
namespace {

const char* TypeName(LightType type) {
    return type == LightType::kPoint ? "point" : type == LightType::kSpot ? "spot" : "directional";
}

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
        const bool base_mode =
            mode.empty() || mode == pack::kLightModeForwardBase || mode == pack::kLightModeAlways;
        if (rec.flags & pack::kPassGrab) {
            // A GrabPass copies where it stands among the object's base passes; under another
            // LightMode it has no place in the path (and no variant to draw).
            if (base_mode) {
                out.base.push_back(p);
            }
            continue;
        }
        if (base_mode) {
            out.base.push_back(p);
        } else if (mode == pack::kLightModeForwardAdd && !out.add) {
            out.add = p;
        } else if (mode == pack::kLightModeDeferred && !out.deferred) {
            out.deferred = p;
        } else if (mode == pack::kLightModeShadowCaster && !out.shadow_caster) {
            out.shadow_caster = p;
        }
    }
    return out;
}

DrawRequest ObjectRequest(const DrawItem& item, uint32_t pass) {
    DrawRequest r;
    r.instance = item.instance;
    r.primitive = item.primitive;
    r.material = item.material;
    r.pass = pass;
    r.center = item.center;
    r.keywords = item.material->keywords;
    return r;
}

std::string LightName(const Light* light) {
    return light ? std::string(TypeName(light->type)) + " light '" + light->name + "'"
                 : std::string("no light");
}

std::string ObjectLabel(const Scene& scene,
                        const Instance& instance,
                        const MaterialInstance& material) {
    const std::string& mesh = scene.meshes[instance.mesh].name;
    return material.name + " on " +
           (!instance.node.empty() ? "node '" + instance.node + "'"
            : !mesh.empty()        ? "mesh '" + mesh + "'"
                                   : std::string("an unnamed node"));
}

std::string Requester(const Scene& scene, const DrawItem& item) {
    return ObjectLabel(scene, *item.instance, *item.material) + ": ";
}

std::vector<DrawRequest*> ForwardReceivers(std::vector<DrawRequest>& requests) {
    std::vector<DrawRequest*> out;
    for (DrawRequest& r : requests) {
        if (r.light && (r.additive || r.light->type == LightType::kDirectional)) {
            out.push_back(&r);
        }
    }
    return out;
}

bool AddForwardRequests(const std::vector<const pack::Pack*>& packs,
                        const Scene& scene,
                        const FrameSettings& settings,
                        const DrawList& list,
                        const DrawItem& item,
                        std::vector<DrawRequest>& out,
                        DiagnosticList& warnings) {
    const MaterialInstance& m = *item.material;
    const ShaderPasses passes = PassesOf(*packs[m.pack], m.shader);
    if (passes.base.empty()) {
        WarnOnce(warnings, scene, DiagCode::kPassNotDrawn,
                 m.name +
                     ": the shader has no ForwardBase or untagged pass; objects using it "
                     "are not drawn by the forward path");
        return false;
    }
    const ObjectLights lights = LightsFor(list.lights, list.main, item.center, item.radius,
                                          settings.pixel_lights, settings.light_mode);
    const std::string who = Requester(scene, item);
    for (uint32_t pass : passes.base) {
        if (const std::optional<std::string_view> grab = packs[m.pack]->GrabTexture(pass)) {
            DrawRequest r = ObjectRequest(item, pass);
            r.grab = std::string(*grab);
            r.reason = who + "GrabPass into " +
                       (grab->empty() ? std::string(pack::kTextureGrab) : std::string(*grab));
            out.push_back(std::move(r));
            continue;
        }
        DrawRequest r{item.instance, item.primitive, &m, pass, false,      lights.main,
                      lights.vertex, lights.sh,      {}, {},   item.center};
        r.keywords = DrawKeywords(m, false, lights.main, !lights.vertex.empty());
        r.reason = who + "base pass, " +
                   (lights.main ? "main " + LightName(lights.main) : "no directional light");
        if (!lights.vertex.empty()) {
            r.reason += ", " + std::to_string(lights.vertex.size()) + " vertex light" +
                        (lights.vertex.size() == 1 ? "" : "s");
        }
        if (!lights.sh.empty()) {
            r.reason += ", " + std::to_string(lights.sh.size()) + " SH light" +
                        (lights.sh.size() == 1 ? "" : "s");
        }
        out.push_back(std::move(r));
    }
    if (passes.add) {
        for (const Light* light : lights.pixel) {
            DrawRequest r{
                item.instance, item.primitive, &m, *passes.add, true, light, {}, {}, {}, {},
                item.center};
            r.keywords = DrawKeywords(m, true, light, false);
            r.reason = who + "additive pass, " + LightName(light);
            out.push_back(std::move(r));
        }
    }
    return true;
}

Status PlanForward(const std::vector<const pack::Pack*>& packs,
                   const Scene& scene,
                   const FrameSettings& settings,
                   const glm::vec3& camera_position,
                   const ColorPipeline& color,
                   MaterialCache& materials,
                   ForwardPlan& out,
                   DiagnosticList& warnings) {
    if (Status e = BuildDrawList(packs, scene, settings, camera_position, color, materials,
                                 out.list, warnings);
        !e.ok()) {
        return e;
    }
    return PlanForwardRequests(packs, scene, settings, color, out, warnings);
}

Status PlanForwardRequests(const std::vector<const pack::Pack*>& packs,
                           const Scene& scene,
                           const FrameSettings& settings,
                           const ColorPipeline& color,
                           ForwardPlan& out,
                           DiagnosticList& warnings) {
    for (const DrawItem& item : out.list.items) {
        if (AddForwardRequests(packs, scene, settings, out.list, item, out.draws, warnings)) {
            ++out.objects;
        }
    }
    if (settings.shadows == Shadows::kOff) {
        return {};
    }
    return PlanShadows(packs, scene, settings, color, out.list, ForwardReceivers(out.draws),
                       out.shadows, warnings);
}

}  // namespace kiln::runtime
