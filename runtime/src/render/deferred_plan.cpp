#include "render/deferred_plan.h"

#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "render/shadow_plan.h"

namespace kiln::runtime {
namespace {

const char* LightKeyword(LightType type) {
    return type == LightType::kPoint  ? pack::kKeywordPoint
           : type == LightType::kSpot ? pack::kKeywordSpot
                                      : pack::kKeywordDirectional;
}

// The light pass's passes: the first (Unity draws pass 0 of Internal-DeferredShading per light),
// and the mask and bounded passes when the shader has both.
struct LightPasses {
    uint32_t whole = 0;
    std::optional<uint32_t> mask, bounded;
};

// The light pass's shader (the first loaded pack's) as a material with its defaults, and its
// passes, of its first SubShader.
Status LightMaterial(const std::vector<const pack::Pack*>& packs,
                     const ColorPipeline& color,
                     MaterialInstance& out,
                     LightPasses& passes) {
    for (uint32_t p = 0; p < packs.size(); ++p) {
        const std::optional<uint32_t> shader = packs[p]->FindShader(pack::kShaderDeferredShading);
        if (!shader) {
            continue;
        }
        const pack::ShaderRec rec = packs[p]->Shader(*shader).value();
        if (rec.pass_count == 0) {
            return Error{DiagCode::kRenderFailed, std::string("shader '") +
                                                      pack::kShaderDeferredShading +
                                                      "' has no pass to light the G-buffer with"};
        }
        InstanceFromDefaults(*packs[p], p, *shader, color, out);
        out.name = std::string("the deferred light pass (") + pack::kShaderDeferredShading + ")";
        passes.whole = rec.first_pass;
        for (uint32_t k = rec.first_pass; k < rec.first_pass + rec.pass_count; ++k) {
            const pack::PassRec pass = packs[p]->Pass(k).value();
            const std::string_view name = packs[p]->String(pass.name);
            if (pass.subshader != 0) {
                continue;
            }
            if (name == pack::kPassDeferredLightMask) {
                passes.mask = k;
            } else if (name == pack::kPassDeferredLightBounded) {
                passes.bounded = k;
            }
        }
        if (!passes.mask || !passes.bounded) {
            passes.mask.reset();
            passes.bounded.reset();
        }
        return {};
    }
    return Error{DiagCode::kRenderFailed,
                 std::string("the deferred path needs shader '") + pack::kShaderDeferredShading +
                     "' to light the G-buffer, which is in none of the loaded packs (add the "
                     "shipped materials.kpack, built from materials/internal/"
                     "DeferredShading.shader)"};
}

}  // namespace

Status PlanDeferred(const std::vector<const pack::Pack*>& packs,
                    const Scene& scene,
                    const FrameSettings& settings,
                    const glm::vec3& camera_position,
                    const ColorPipeline& color,
                    MaterialCache& materials,
                    DeferredPlan& out,
                    DiagnosticList& warnings) {
    if (Status e = BuildDrawList(packs, scene, settings, camera_position, color, materials,
                                 out.list, warnings);
        !e.ok()) {
        return e;
    }
    return PlanDeferredRequests(packs, scene, settings, color, out, warnings);
}

Status PlanDeferredRequests(const std::vector<const pack::Pack*>& packs,
                            const Scene& scene,
                            const FrameSettings& settings,
                            const ColorPipeline& color,
                            DeferredPlan& out,
                            DiagnosticList& warnings) {
    const bool octahedral = settings.gbuffer.octahedral;
    std::vector<const DrawItem*> forward;
    for (const DrawItem& item : out.list.items) {
        const MaterialInstance& m = *item.material;
        const ShaderPasses passes = PassesOf(*packs[m.pack], m.shader);
        if (m.transparent || !passes.deferred) {
            forward.push_back(&item);
            continue;
        }
        DrawRequest r = ObjectRequest(item, *passes.deferred);
        // Ambient from the light probes, as the forward base pass asks for it.
        r.keywords.emplace_back(pack::kKeywordLightProbeSH);
        if (octahedral) {
            r.keywords.emplace_back(pack::kKeywordGBufferNormalsOct);
        }
        r.reason = Requester(scene, item) + "deferred pass";
        out.gbuffer.push_back(std::move(r));
        ++out.objects;
    }
    if (!out.gbuffer.empty()) {
        LightPasses passes;
        MaterialInstance light_material;
        if (Status e = LightMaterial(packs, color, light_material, passes); !e.ok()) {
            return e;
        }
        out.light_material = std::move(light_material);
        for (const Light& light : out.list.lights) {
            DrawRequest r;
            r.material = &*out.light_material;
            r.pass = passes.whole;
            r.additive = true;
            r.light = &light;
            r.keywords = {LightKeyword(light.type)};
            if (octahedral) {
                r.keywords.emplace_back(pack::kKeywordGBufferNormalsOct);
            }
            r.reason = "deferred light pass, " + LightName(&light);
            const bool ranged = light.type != LightType::kDirectional && light.range > 0;
            if (!ranged || !passes.mask) {
                out.lights.push_back({std::move(r), LightDraw::Role::kWhole});
                continue;
            }
            DrawRequest mask;
            mask.material = r.material;
            mask.pass = *passes.mask;
            mask.light = &light;
            mask.reason = "deferred light mask, " + LightName(&light);
            out.lights.push_back({std::move(mask), LightDraw::Role::kMask});
            r.pass = *passes.bounded;
            out.lights.push_back({std::move(r), LightDraw::Role::kBounded});
        }
    }
    for (const DrawItem* item : forward) {
        if (AddForwardRequests(packs, scene, settings, out.list, *item, out.forward, warnings)) {
            ++out.objects;
        }
    }
    if (settings.shadows == Shadows::kOff) {
        return {};
    }
    // The lights' passes receive their shadows (not a ranged light's stencil mask), and so do
    // the objects drawn forward.
    std::vector<DrawRequest*> receivers = ForwardReceivers(out.forward);
    for (LightDraw& l : out.lights) {
        if (l.role != LightDraw::Role::kMask) {
            receivers.push_back(&l.request);
        }
    }
    return PlanShadows(packs, scene, settings, color, out.list, receivers, out.shadows, warnings);
}

}  // namespace kiln::runtime
