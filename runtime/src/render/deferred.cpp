// DrawDeferred: the lecture's deferred path as a frame of three passes (render/frame.h):
//   gbuffer   each opaque object's Deferred pass into RT0-RT3 and depth (cleared);
//   lighting  the light pass per light, additively into RT3, sampling RT0-RT2 and depth (read-only,
//             its stencil cleared for the masks): a full-screen triangle at a fixed depth; for a
//             ranged light scissored to its sphere on screen, with a stencil mask at the sphere's
//             near depth and the light at its far depth
//             (materials/internal/DeferredShading.shader), so pixels outside the light's reach are
//             not shaded;
//   forward   the objects the deferred path cannot draw, with their forward passes, into RT3
//             over the G-buffer pass's depth.
// RT3, the light buffer, is the frame's output. With shadows, the shadow passes come first
// (render/shadow_passes.h), as on the forward path: each light's pass samples its light's map
// (spot: SHADOWS_DEPTH, point: SHADOWS_CUBE) or, for a directional light, the screen-space
// shadows collected from the camera's depth (SHADOWS_SCREEN), as Unity's deferred path does.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

#include "kiln/pack/engine_names.h"
#include "render/deferred_plan.h"
#include "render/draw_builder.h"
#include "render/frame.h"
#include "render/frame_values.h"
#include "render/grab_pass.h"
#include "render/render_path.h"
#include "render/renderer_state.h"
#include "render/shadow_passes.h"

namespace kiln::runtime {
namespace {

// The largest depth below the cleared 1.0 (2^-24 below it: exact in float and in D24): light draws
// without a range are drawn here with ZTest GEqual, so background pixels are never shaded.
constexpr float kFarthest = 1.0f - 1.0f / 16777216.0f;

VkFormat NormalFormat(GBufferSettings::Normals n) {
    switch (n) {
        case GBufferSettings::Normals::kRGBA8:
            return VK_FORMAT_R8G8B8A8_UNORM;
        case GBufferSettings::Normals::kRGBA16F:
            return VK_FORMAT_R16G16B16A16_SFLOAT;
        case GBufferSettings::Normals::kRGB10A2:
            break;
    }
    return VK_FORMAT_A2B10G10R10_UNORM_PACK32;
}

// Where a light of limited range can reach: the screen rectangle of its sphere and the sphere's
// depth range. `visible` false: nothing on screen (behind the camera or off the frame).
struct LightReach {
    bool visible = true;
    std::optional<VkRect2D> scissor;  // none: the whole frame
    float zmin = 0, zmax = kFarthest;
};

LightReach ReachOf(const Light& light, const CameraSetup& camera, uint32_t width, uint32_t height) {
    LightReach out;
    if (light.type == LightType::kDirectional || !(light.range > 0)) {
        return out;  // unlimited: every pixel with geometry
    }
    const glm::vec3 c(camera.view * glm::vec4(light.position, 1));
    const float r = light.range;
    const bool ortho = camera.projection[2][3] == 0.0f;
    // View space looks down -z: distances in front of the camera are -z.
    const float dnear = -c.z - r, dfar = -c.z + r;
    if (dfar <= camera.znear || (camera.zfar > 0 && dnear >= camera.zfar)) {
        out.visible = false;
        return out;
    }
    auto depth_at = [&](float d) {
        const glm::vec4 clip = camera.projection * glm::vec4(0, 0, -d, 1);
        return std::clamp(clip.z / clip.w, 0.0f, 1.0f);
    };
    // Widened by a few D24 steps for the depth buffer's rounding.
    const float slack = 4.0f / 16777216.0f;
    out.zmin = dnear <= camera.znear ? 0.0f : std::max(0.0f, depth_at(dnear) - slack);
    out.zmax = camera.zfar > 0 && dfar >= camera.zfar ? kFarthest
                                                      : std::min(kFarthest, depth_at(dfar) + slack);
    if (!ortho && dnear <= camera.znear) {
        return out;  // the sphere reaches the camera: its projection is unbounded
    }
    // The projected corners of the sphere's view-space box bound it on screen.
    float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 p = c + glm::vec3((k & 1) ? r : -r, (k & 2) ? r : -r, (k & 4) ? r : -r);
        const glm::vec4 clip = camera.projection * glm::vec4(p, 1);
        const float x = clip.x / clip.w, y = clip.y / clip.w;
        // Clip-space +y is the top row (the viewport is flipped).
        x0 = std::min(x0, (x * 0.5f + 0.5f) * float(width));
        x1 = std::max(x1, (x * 0.5f + 0.5f) * float(width));
        y0 = std::min(y0, (0.5f - y * 0.5f) * float(height));
        y1 = std::max(y1, (0.5f - y * 0.5f) * float(height));
    }
    const float left = std::clamp(std::floor(x0), 0.0f, float(width));
    const float right = std::clamp(std::ceil(x1), 0.0f, float(width));
    const float top = std::clamp(std::floor(y0), 0.0f, float(height));
    const float bottom = std::clamp(std::ceil(y1), 0.0f, float(height));
    if (right <= left || bottom <= top) {
        out.visible = false;
        return out;
    }
    out.scissor =
        VkRect2D{{int32_t(left), int32_t(top)}, {uint32_t(right - left), uint32_t(bottom - top)}};
    return out;
}

// The deferred frame of `plan` (the passes this file's comment lists), after the shadow passes
// when a light casts.
Status BuildDeferredFrame(BuildInputs& in, const DeferredPlan& plan, Frame& frame) {
    Renderer::State& s = in.state;
    const FrameSettings& settings = in.settings;
    VkFormatProperties depth_props;
    vkGetPhysicalDeviceFormatProperties(s.context.physical, s.depth_format, &depth_props);
    if (!plan.lights.empty() &&
        !(depth_props.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT)) {
        return Error{DiagCode::kRenderFailed,
                     "the device cannot sample its depth format, which the deferred light pass "
                     "reads (use --path forward)"};
    }
    enum : uint32_t { kRT0, kRT1, kRT2, kRT3, kDepth };
    frame.targets = {
        {"gbuffer0 (diffuse)", VK_FORMAT_R8G8B8A8_SRGB, false, {}, false},
        {"gbuffer1 (specular)", VK_FORMAT_R8G8B8A8_SRGB, false, {}, false},
        {"gbuffer2 (normal)", NormalFormat(settings.gbuffer.normals), false, {}, false},
        {"light (emission, ambient, lights)", s.color_format, false, {}, true},
        {"depth", s.depth_format, true, {}, true},
    };
    // Alpha 0: not covered (the frame's alpha is coverage; the Deferred passes write 1).
    frame.targets[kRT3].clear.color = {
        {settings.background.r, settings.background.g, settings.background.b, 0}};
    frame.targets[kDepth].clear.depthStencil = {1.0f, 0};
    frame.output = kRT3;

    DrawBuilder& builder = in.builder;
    FrameStats& stats = in.stats;
    ShadowFrame shadows;
    if (Status e = AddShadowPasses(s, builder, settings, plan.shadows, in.resources.bounds, frame,
                                   shadows);
        !e.ok()) {
        return e;
    }
    stats.shadow_draws = shadows.draws;
    FramePass& gbuffer = frame.passes.emplace_back();
    gbuffer.name = "gbuffer";
    gbuffer.colors = {kRT0, kRT1, kRT2, kRT3};
    gbuffer.depth = kDepth;
    builder.BeginPass(frame, gbuffer);
    for (const DrawRequest& r : plan.gbuffer) {
        if (Status e = builder.Build(r, gbuffer.draws); !e.ok()) {
            return e;
        }
        ++stats.gbuffer_draws;
    }

    if (!plan.lights.empty()) {
        FramePass& lighting = frame.passes.emplace_back();
        lighting.name = "lighting";
        lighting.colors = {kRT3};
        lighting.depth = kDepth;
        lighting.clear = false;
        lighting.depth_read_only = true;
        lighting.sampled = {kRT0, kRT1, kRT2, kDepth};
        lighting.sampled.insert(lighting.sampled.end(), shadows.sampled.begin(),
                                shadows.sampled.end());
        builder.BeginPass(frame, lighting,
                          {{pack::kTextureGBuffer0, kRT0},
                           {pack::kTextureGBuffer1, kRT1},
                           {pack::kTextureGBuffer2, kRT2},
                           {pack::kTextureCameraDepth, kDepth}});
        for (const LightDraw& l : plan.lights) {
            const LightReach reach =
                ReachOf(*l.request.light, in.camera, frame.width, frame.height);
            if (!reach.visible) {
                continue;
            }
            if (Status e = builder.Build(WithShadows({&l.request, 1}, shadows)[0], lighting.draws);
                !e.ok()) {
                return e;
            }
            Draw& d = lighting.draws.back();
            d.scissor = reach.scissor;
            switch (l.role) {
                case LightDraw::Role::kWhole:
                    d.depth = kFarthest;
                    ++stats.light_passes;
                    break;
                case LightDraw::Role::kMask:
                    d.depth = reach.zmin;
                    d.joins_next = true;
                    break;
                case LightDraw::Role::kBounded:
                    d.depth = reach.zmax;
                    ++stats.light_passes;
                    break;
            }
        }
    }

    if (!plan.forward.empty()) {
        FramePass forward;
        forward.name = "forward";
        forward.colors = {kRT3};
        forward.depth = kDepth;
        forward.clear = false;
        forward.sampled = shadows.sampled;
        if (Status e = BuildForwardPasses(builder, frame, forward, kRT3,
                                          WithShadows(plan.forward, shadows), stats);
            !e.ok()) {
            return e;
        }
    }
    return {};
}

// A deferred plan as a PathPlan: the path's own (DeferredPathPlan), or one its caller keeps.
class DeferredPlanView : public PathPlan {
  public:
    explicit DeferredPlanView(const DeferredPlan& plan) : plan_(plan) {}
    void Requests(std::vector<const DrawRequest*>& out) const override {
        for (const DrawRequest& r : plan_.gbuffer) {
            out.push_back(&r);
        }
        for (const LightDraw& l : plan_.lights) {
            out.push_back(&l.request);
        }
        for (const DrawRequest& r : plan_.forward) {
            out.push_back(&r);
        }
        ShadowRequests(plan_.shadows, out);
    }
    void Materials(std::vector<const MaterialInstance*>& out) const override {
        out.insert(out.end(), plan_.list.materials.begin(), plan_.list.materials.end());
        if (plan_.light_material) {
            out.push_back(&*plan_.light_material);
        }
        if (plan_.shadows.collect) {
            out.push_back(&*plan_.shadows.collector);
        }
    }
    uint32_t Objects() const override { return plan_.objects; }
    Status Build(BuildInputs& in, Frame& frame) const override {
        return BuildDeferredFrame(in, plan_, frame);
    }

  private:
    const DeferredPlan& plan_;
};

struct DeferredPlanStore {
    DeferredPlan plan;
};

class DeferredPathPlan final : private DeferredPlanStore, public DeferredPlanView {
  public:
    DeferredPathPlan() : DeferredPlanView(DeferredPlanStore::plan) {}
    DeferredPlan& Store() { return DeferredPlanStore::plan; }
};

class DeferredPath final : public PathRenderer {
  public:
    std::string_view Name() const override { return "deferred"; }
    std::string_view Summary() const override {
        return "a G-buffer from the objects' Deferred passes lit per light in screen space; the "
               "rest drawn forward after it";
    }
    void Adjust(FrameSettings& settings,
                const Scene& scene,
                DiagnosticList& warnings) const override {
        if (settings.msaa > 1) {  // as Unity's deferred path
            settings.msaa = 1;
            warnings.Warning(DiagCode::kRenderWarning, scene.path, kNoPosition,
                             "MSAA is off for the deferred path, whose light pass reads one "
                             "G-buffer sample: drawn with 1 sample per pixel");
        }
    }
    Result<std::unique_ptr<PathPlan>> Plan(const PlanInputs& in) const override {
        auto out = std::make_unique<DeferredPathPlan>();
        if (Status e = PlanDeferred(in.packs, in.scene, in.settings, in.camera.position, in.color,
                                    in.materials, out->Store(), in.warnings);
            !e.ok()) {
            return e.error();
        }
        return std::unique_ptr<PathPlan>(std::move(out));
    }
    std::string Counts(const FrameStats& stats) const override {
        return std::to_string(stats.gbuffer_draws) + " G-buffer draws, " +
               std::to_string(stats.light_passes) + " light passes";
    }
};

}  // namespace

std::unique_ptr<PathRenderer> MakeDeferredPath() {
    return std::make_unique<DeferredPath>();
}

std::unique_ptr<PathPlan> ViewDeferredPlan(const DeferredPlan& plan) {
    return std::make_unique<DeferredPlanView>(plan);
}

}  // namespace kiln::runtime
