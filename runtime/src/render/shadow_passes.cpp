#include "render/shadow_passes.h"

#include "kiln/pack/engine_names.h"

namespace kiln::runtime {
namespace {

const char* const kFaceNames[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

// A colour target for a depth pass of `size` (0: the frame's), which the casters' fragment
// stages write with their colour writes masked off: without one, their SV_Target output would
// have no attachment (valid, but a validation-layer warning). One per size, shared.
uint32_t UnusedColor(Frame& frame, uint32_t size, ShadowFrame& out) {
    if (auto it = out.unused_colors.find(size); it != out.unused_colors.end()) {
        return it->second;
    }
    FrameTarget color{"unused colour of the shadow passes", VK_FORMAT_R8_UNORM, false, {}, false};
    color.size = size;
    color.shown = false;
    frame.targets.push_back(color);
    return out.unused_colors[size] = uint32_t(frame.targets.size() - 1);
}

// One pass drawing every caster of `requests` into `target` (a cube's `layer`) with `values`.
Status CasterPass(DrawBuilder& builder,
                  Frame& frame,
                  const std::string& name,
                  uint32_t target,
                  uint32_t layer,
                  const std::vector<DrawRequest>& requests,
                  const Light* light,
                  const Values& values,
                  ShadowFrame& out) {
    const uint32_t color = UnusedColor(frame, frame.targets[target].size, out);
    FramePass& pass = frame.passes.emplace_back();
    pass.name = name;
    pass.colors = {color};
    pass.depth = target;
    pass.layer = layer;
    builder.BeginPass(frame, pass);
    for (const DrawRequest& caster : requests) {
        DrawRequest& r = out.requests.emplace_back(caster);
        r.light = light;
        r.values = &values;
        r.mirrored_view = frame.targets[target].cube;  // cube faces are left-handed views
        r.depth_only = true;
        if (Status e = builder.Build(r, pass.draws); !e.ok()) {
            return e;
        }
        ++out.draws;
    }
    return {};
}

}  // namespace

Status AddShadowPasses(Renderer::State& s,
                       DrawBuilder& builder,
                       const FrameSettings& settings,
                       const ShadowPlan& plan,
                       const std::optional<std::pair<glm::vec3, glm::vec3>>& bounds,
                       Frame& frame,
                       ShadowFrame& out) {
    if (plan.lights.empty()) {
        return {};
    }
    if (!bounds) {
        return Error{DiagCode::kRenderFailed, "internal: a shadowed frame without scene bounds"};
    }
    VkFormat format = VK_FORMAT_UNDEFINED;
    if (Status e = s.ShadowMapFormat(format); !e.ok()) {
        return e;
    }
    std::optional<uint32_t> camera_depth;
    for (const Light* light : plan.lights) {
        const bool cube = light->type == LightType::kPoint;
        const uint32_t size = ShadowMapSize(settings, *light);
        const LightShadow& shadow = out.shadows.emplace_back(ShadowOf(*light, *bounds, size));
        FrameTarget map{"shadow map: " + LightName(light), format, true, {}, false};
        map.clear.depthStencil = {1.0f, 0};
        map.shadow_map = true;
        map.size = size;
        map.cube = cube;
        const uint32_t map_target = uint32_t(frame.targets.size());
        frame.targets.push_back(map);
        for (uint32_t face = 0; face < shadow.view_projection.size(); ++face) {
            const std::string name =
                "shadows: " + LightName(light) + (cube ? std::string(" ") + kFaceNames[face] : "");
            if (Status e = CasterPass(builder, frame, name, map_target, face,
                                      cube ? plan.cube_casters : plan.casters, light,
                                      shadow.caster[face], out);
                !e.ok()) {
                return e;
            }
        }
        if (light->type != LightType::kDirectional) {
            out.receivers[light] = {map_target, &shadow.receiver};
            out.sampled.push_back(map_target);
            continue;
        }
        // Directional: collected into a screen-space texture from the camera's depth, which the
        // ShadowCaster passes draw once for every directional light (without a bias).
        if (!camera_depth) {
            FrameTarget depth{"camera depth (shadow casters)", s.depth_format, true, {}, true};
            depth.clear.depthStencil = {1.0f, 0};
            camera_depth = uint32_t(frame.targets.size());
            frame.targets.push_back(depth);
            out.camera_depth["unity_LightShadowBias"] = {0, 0, 0, 0};
            if (Status e = CasterPass(builder, frame, "camera depth", *camera_depth, 0,
                                      plan.casters, nullptr, out.camera_depth, out);
                !e.ok()) {
                return e;
            }
        }
        FrameTarget screen{
            "screen-space shadows: " + LightName(light), VK_FORMAT_R8_UNORM, false, {}, false};
        screen.clear.color = {{1, 1, 1, 1}};
        const uint32_t screen_target = uint32_t(frame.targets.size());
        frame.targets.push_back(screen);
        FramePass& collect = frame.passes.emplace_back();
        collect.name = "screen-space shadows: " + LightName(light);
        collect.colors = {screen_target};
        collect.sampled = {*camera_depth, map_target};
        builder.BeginPass(
            frame, collect,
            {{pack::kTextureCameraDepth, *camera_depth}, {pack::kTextureShadowMap, map_target}});
        DrawRequest& r = out.requests.emplace_back(*plan.collect);
        r.light = light;
        r.additive = false;
        r.values = &shadow.receiver;
        if (Status e = builder.Build(r, collect.draws); !e.ok()) {
            return e;
        }
        ++out.draws;
        out.receivers[light] = {screen_target, &shadow.receiver};
        out.sampled.push_back(screen_target);
    }
    return {};
}

std::vector<DrawRequest> WithShadows(std::span<const DrawRequest> requests,
                                     const ShadowFrame& shadows) {
    std::vector<DrawRequest> out(requests.begin(), requests.end());
    for (DrawRequest& r : out) {
        if (auto it = shadows.receivers.find(r.light); r.light && it != shadows.receivers.end()) {
            r.shadow_map = int(it->second.target);
            r.values = it->second.values;
        }
    }
    return out;
}

}  // namespace kiln::runtime
