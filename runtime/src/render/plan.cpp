#include "kiln/runtime/plan.h"

#include <memory>
#include <set>

#include "render/deferred_plan.h"
#include "render/forward_plan.h"
#include "render/frame_values.h"

namespace kiln::runtime {

Result<ScenePlan> PlanScene(const std::vector<const pack::Pack*>& packs,
                            const Scene& scene,
                            const FrameSettings& settings,
                            const ColorPipeline& color,
                            DiagnosticList& warnings) {
    if (packs.empty()) {
        return Error{DiagCode::kRenderFailed, "no variant pack loaded"};
    }
    render::CameraSetup camera;
    if (Status e = render::ChooseCamera(scene, settings, camera); !e.ok()) {
        return e.error();
    }
    render::MaterialCache materials;
    // The path's requests, in drawing order, and the list they came from.
    render::ForwardPlan forward;
    render::DeferredPlan deferred;
    std::vector<const render::DrawRequest*> requests;
    const bool is_deferred = settings.path == RenderPath::kDeferred;
    if (is_deferred) {
        if (Status e = render::PlanDeferred(packs, scene, settings, camera.position, color,
                                            materials, deferred, warnings);
            !e.ok()) {
            return e.error();
        }
        for (const render::DrawRequest& r : deferred.gbuffer) {
            requests.push_back(&r);
        }
        for (const render::LightDraw& l : deferred.lights) {
            requests.push_back(&l.request);
        }
        for (const render::DrawRequest& r : deferred.forward) {
            requests.push_back(&r);
        }
    } else {
        if (Status e = render::PlanForward(packs, scene, settings, camera.position, color,
                                           materials, forward, warnings);
            !e.ok()) {
            return e.error();
        }
        for (const render::DrawRequest& r : forward.draws) {
            requests.push_back(&r);
        }
        const render::ShadowPlan& shadows = forward.shadows;
        if (!shadows.lights.empty()) {  // the shadow passes' draws
            for (const auto* casters : {&shadows.casters, &shadows.cube_casters}) {
                for (const render::DrawRequest& r : *casters) {
                    requests.push_back(&r);
                }
            }
            if (shadows.collect) {
                requests.push_back(&*shadows.collect);
            }
        }
    }
    const render::DrawList& list = is_deferred ? deferred.list : forward.list;
    ScenePlan out;
    std::vector<std::unique_ptr<pack::VariantSelector>> selectors;
    for (const pack::Pack* p : packs) {
        selectors.push_back(
            std::make_unique<pack::VariantSelector>(*p, pack::MissingVariantPolicy::kError));
    }
    std::set<std::string> reported;
    for (const render::DrawRequest* r : requests) {
        if (r->grab) {
            continue;  // a copy, no variant
        }
        const Result<pack::VariantChoice> chosen =
            selectors[r->material->pack]->Select(r->pass, r->keywords, r->reason);
        if (!chosen && reported.insert(chosen.error().message).second) {
            out.missing.Error(chosen.error().code, scene.path, kNoPosition,
                              chosen.error().message + "; needed by " + r->reason);
        }
    }
    std::vector<const pack::VariantSelector*> views;
    for (const auto& s : selectors) {
        views.push_back(s.get());
    }
    out.usage.lookups = pack::UsageOf(views);
    std::set<pack::UsageMaterial> used;
    std::vector<const render::MaterialInstance*> used_instances = list.materials;
    if (deferred.light_material) {
        used_instances.push_back(&*deferred.light_material);
    }
    if (forward.shadows.collect) {
        used_instances.push_back(&*forward.shadows.collector);
    }
    for (const render::MaterialInstance* m : used_instances) {
        const pack::Pack& p = *packs[m->pack];
        used.insert({m->name, std::string(p.String(p.Shader(m->shader).value().name))});
    }
    out.usage.materials.assign(used.begin(), used.end());
    out.objects = is_deferred ? deferred.objects : forward.objects;
    out.draws = uint32_t(requests.size());
    return out;
}

}  // namespace kiln::runtime
