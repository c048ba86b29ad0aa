#include "kiln/runtime/plan.h"

#include <memory>
#include <set>

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
    render::ForwardPlan plan;
    if (Status e = render::PlanForward(packs, scene, settings, camera.position, color, materials,
                                       plan, warnings);
        !e.ok()) {
        return e.error();
    }
    ScenePlan out;
    std::vector<std::unique_ptr<pack::VariantSelector>> selectors;
    for (const pack::Pack* p : packs) {
        selectors.push_back(
            std::make_unique<pack::VariantSelector>(*p, pack::MissingVariantPolicy::kError));
    }
    std::set<std::string> reported;
    for (const render::DrawRequest& r : plan.draws) {
        const Result<pack::VariantChoice> chosen =
            selectors[r.material->pack]->Select(r.pass, r.keywords, r.reason);
        if (!chosen && reported.insert(chosen.error().message).second) {
            out.missing.Error(chosen.error().code, scene.path, kNoPosition,
                              chosen.error().message + "; needed by " + r.reason);
        }
    }
    std::vector<const pack::VariantSelector*> views;
    for (const auto& s : selectors) {
        views.push_back(s.get());
    }
    out.usage.lookups = pack::UsageOf(views);
    std::set<pack::UsageMaterial> used;
    for (const render::MaterialInstance* m : plan.list.materials) {
        const pack::Pack& p = *packs[m->pack];
        used.insert({m->name, std::string(p.String(p.Shader(m->shader).value().name))});
    }
    out.usage.materials.assign(used.begin(), used.end());
    out.objects = plan.objects;
    out.draws = uint32_t(plan.draws.size());
    return out;
}

}  // namespace kiln::runtime
