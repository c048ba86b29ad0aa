// A toy third render path, "toy" (unlit-only), made by implementing the render-path interface
// (render/render_path.h) and nothing else: every object of the draw list drawn once with its
// shader's first ForwardBase (or untagged) pass, without lights, into one colour target and a
// depth buffer. It registers itself when the program starts, so linking this file adds
// `--path toy` to a program: tests/runtime/toy_path_test.cpp renders and plans with it, and the
// toy kiln / kiln-render pair built from the unchanged tools/ mains plus this file strips a
// pack to it (kiln compile --scene --path toy --verify-scene). Nothing of the forward or
// deferred paths is touched.
#include "render/render_path.h"

#include "kiln/pack/reader.h"
#include "render/draw_list.h"

namespace kiln::test {
namespace {

using runtime::BuildInputs;
using runtime::Frame;
using runtime::FramePass;
using runtime::FrameTarget;
using runtime::PathPlan;
using runtime::PlanInputs;

class ToyPlan final : public PathPlan {
  public:
    void Requests(std::vector<const runtime::DrawRequest*>& out) const override {
        for (const runtime::DrawRequest& r : draws) {
            out.push_back(&r);
        }
    }
    void Materials(std::vector<const runtime::MaterialInstance*>& out) const override {
        out.insert(out.end(), list.materials.begin(), list.materials.end());
    }
    uint32_t Objects() const override { return uint32_t(draws.size()); }
    Status Build(BuildInputs& in, Frame& frame) const override {
        FrameTarget color{"color", in.state.color_format, false, {}};
        color.clear.color = {
            {in.settings.background.r, in.settings.background.g, in.settings.background.b, 0}};
        FrameTarget depth{"depth", in.state.depth_format, true, {}};
        depth.clear.depthStencil = {1.0f, 0};
        frame.targets = {color, depth};
        frame.output = 0;
        FramePass& pass = frame.passes.emplace_back();
        pass.name = "toy";
        pass.colors = {0};
        pass.depth = 1;
        in.builder.BeginPass(frame, pass);
        for (const runtime::DrawRequest& r : draws) {
            if (Status e = in.builder.Build(r, pass.draws); !e.ok()) {
                return e;
            }
        }
        return {};
    }

    runtime::DrawList list;  // the requests point into it
    std::vector<runtime::DrawRequest> draws;
};

class ToyPath final : public runtime::PathRenderer {
  public:
    std::string_view Name() const override { return "toy"; }
    std::string_view Summary() const override {
        return "a test's unlit-only path: each object's first ForwardBase pass, without lights";
    }
    Result<std::unique_ptr<PathPlan>> Plan(const PlanInputs& in) const override {
        auto plan = std::make_unique<ToyPlan>();
        if (Status e = runtime::BuildDrawList(in.packs, in.scene, in.settings, in.camera.position,
                                              in.color, in.materials, plan->list, in.warnings);
            !e.ok()) {
            return e.error();
        }
        for (const runtime::DrawItem& item : plan->list.items) {
            const runtime::MaterialInstance& m = *item.material;
            const runtime::ShaderPasses passes = runtime::PassesOf(*in.packs[m.pack], m.shader);
            for (uint32_t pass : passes.base) {
                if (in.packs[m.pack]->GrabTexture(pass)) {
                    continue;  // a copy, not a draw
                }
                runtime::DrawRequest r = runtime::ObjectRequest(item, pass);
                r.reason = runtime::Requester(in.scene, item) + "toy path, unlit";
                plan->draws.push_back(std::move(r));
                break;
            }
        }
        return std::unique_ptr<PathPlan>(std::move(plan));
    }
    std::string Counts(const runtime::FrameStats& stats) const override {
        return std::to_string(stats.objects) + " unlit draws";
    }
};

const bool kRegistered = runtime::RegisterPathRenderer(std::make_unique<ToyPath>());

}  // namespace

bool ToyPathRegistered() {
    return kRegistered;
}

}  // namespace kiln::test
