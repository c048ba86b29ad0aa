#include "kiln/runtime/plan.h"

#include <memory>
#include <set>

#include "render/render_path.h"

namespace kiln::runtime {

Result<ScenePlan> PlanScene(const std::vector<const pack::Pack*>& packs,
                            const Scene& scene,
                            const FrameSettings& settings,
                            const ColorPipeline& color,
                            DiagnosticList& warnings) {
    if (packs.empty()) {
        return Error{DiagCode::kRenderFailed, "no variant pack loaded"};
    }
    CameraSetup camera;
    if (Status e = ChooseCamera(scene, settings, camera); !e.ok()) {
        return e.error();
    }
    const PathRenderer* path = FindPathRenderer(settings.path.name);
    if (!path) {
        return UnknownPath(settings.path.name);
    }
    MaterialCache materials;
    const PlanInputs in{packs, scene, settings, camera, color, materials, warnings};
    Result<std::unique_ptr<PathPlan>> planned = path->Plan(in);
    if (!planned) {
        return planned.error();
    }
    const PathPlan& plan = *planned.value();
    std::vector<const DrawRequest*> requests;
    plan.Requests(requests);
    ScenePlan out;
    std::vector<std::unique_ptr<pack::VariantSelector>> selectors;
    for (const pack::Pack* p : packs) {
        selectors.push_back(
            std::make_unique<pack::VariantSelector>(*p, pack::MissingVariantPolicy::kError));
    }
    std::set<std::string> reported;
    for (const DrawRequest* r : requests) {
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
    std::vector<const MaterialInstance*> used_instances;
    plan.Materials(used_instances);
    for (const MaterialInstance* m : used_instances) {
        const pack::Pack& p = *packs[m->pack];
        used.insert({m->name, std::string(p.String(p.Shader(m->shader).value().name))});
    }
    out.usage.materials.assign(used.begin(), used.end());
    out.objects = plan.Objects();
    out.draws = uint32_t(requests.size());
    return out;
}

}  // namespace kiln::runtime
