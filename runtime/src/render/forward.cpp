// The lecture's forward path (render/render_path.h). The draw list (render/forward_plan.h: passes,
// lights and keywords per primitive) becomes draws (render/draw_builder.h): the variant each asks
// for, its pipeline, uniform bytes and descriptors, decided on the CPU; then one command buffer
// records them all. With shadows, the shadow passes (render/shadow_passes.h) come first.
#include "render/draw_builder.h"
#include "render/forward_plan.h"
#include "render/frame.h"
#include "render/grab_pass.h"
#include "render/render_path.h"
#include "render/renderer_state.h"
#include "render/shadow_passes.h"

namespace kiln::runtime {
namespace {

// The forward frame of `plan`: one pass into the colour target and the depth buffer; with MSAA
// both have settings.msaa samples per pixel and the colour is resolved (averaged) into a
// single-sample target at the end of the pass, before the display transform reads it.
Status BuildForwardFrame(BuildInputs& in, const ForwardPlan& plan, Frame& frame) {
    Renderer::State& s = in.state;
    const FrameSettings& settings = in.settings;
    const uint32_t samples = settings.msaa;
    FrameTarget color_target{"color", s.color_format, false, {}};
    // Alpha 0: not covered (the frame's alpha is coverage; resolved, the covered fraction).
    color_target.clear.color = {
        {settings.background.r, settings.background.g, settings.background.b, 0}};
    color_target.samples = VkSampleCountFlagBits(samples);
    FrameTarget depth_target{"depth", s.depth_format, true, {}};
    depth_target.clear.depthStencil = {1.0f, 0};
    depth_target.samples = VkSampleCountFlagBits(samples);
    frame.targets = {color_target, depth_target};
    frame.output = 0;
    if (samples > 1) {
        FrameTarget resolved{"color (resolved)", s.color_format, false, {}};
        frame.targets.push_back(resolved);
        frame.output = 2;
    }
    // The shadow passes first (their targets after the forward pass's).
    ShadowFrame shadows;
    if (Status e = AddShadowPasses(s, in.builder, settings, plan.shadows, in.resources.bounds,
                                   frame, shadows);
        !e.ok()) {
        return e;
    }
    FramePass forward;
    forward.name = "forward";
    forward.colors = {0};
    forward.depth = 1;
    if (samples > 1) {
        forward.resolves = {2};
    }
    forward.sampled = shadows.sampled;
    if (Status e = BuildForwardPasses(in.builder, frame, forward, frame.output,
                                      WithShadows(plan.draws, shadows), in.stats);
        !e.ok()) {
        return e;
    }
    in.stats.shadow_draws = shadows.draws;
    return {};
}

// A forward plan as a PathPlan: the path's own (ForwardPathPlan), or one its caller keeps.
class ForwardPlanView : public PathPlan {
  public:
    explicit ForwardPlanView(const ForwardPlan& plan) : plan_(plan) {}
    void Requests(std::vector<const DrawRequest*>& out) const override {
        for (const DrawRequest& r : plan_.draws) {
            out.push_back(&r);
        }
        ShadowRequests(plan_.shadows, out);
    }
    void Materials(std::vector<const MaterialInstance*>& out) const override {
        out.insert(out.end(), plan_.list.materials.begin(), plan_.list.materials.end());
        if (plan_.shadows.collect) {
            out.push_back(&*plan_.shadows.collector);
        }
    }
    uint32_t Objects() const override { return plan_.objects; }
    Status Build(BuildInputs& in, Frame& frame) const override {
        return BuildForwardFrame(in, plan_, frame);
    }

  private:
    const ForwardPlan& plan_;
};

struct ForwardPlanStore {
    ForwardPlan plan;
};

class ForwardPathPlan final : private ForwardPlanStore, public ForwardPlanView {
  public:
    ForwardPathPlan() : ForwardPlanView(ForwardPlanStore::plan) {}
    ForwardPlan& Store() { return ForwardPlanStore::plan; }
};

class ForwardPath final : public PathRenderer {
  public:
    std::string_view Name() const override { return "forward"; }
    std::string_view Summary() const override {
        return "each object's ForwardBase passes lit by the main directional light, then one "
               "ForwardAdd pass per further pixel light";
    }
    Result<std::unique_ptr<PathPlan>> Plan(const PlanInputs& in) const override {
        auto out = std::make_unique<ForwardPathPlan>();
        if (Status e = PlanForward(in.packs, in.scene, in.settings, in.camera.position, in.color,
                                   in.materials, out->Store(), in.warnings);
            !e.ok()) {
            return e.error();
        }
        return std::unique_ptr<PathPlan>(std::move(out));
    }
};

}  // namespace

std::unique_ptr<PathRenderer> MakeForwardPath() {
    return std::make_unique<ForwardPath>();
}

std::unique_ptr<PathPlan> ViewForwardPlan(const ForwardPlan& plan) {
    return std::make_unique<ForwardPlanView>(plan);
}

}  // namespace kiln::runtime
