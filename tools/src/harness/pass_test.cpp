#include "harness/pass_test.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

#include "harness/shadow_map_check.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "kiln/pack/render_state.h"

namespace kiln::tools {

using runtime::DeferredPlan;
using runtime::DrawItem;
using runtime::DrawRequest;
using runtime::ForwardPlan;
using runtime::FrameSettings;
using runtime::Light;
using runtime::LightDraw;
using runtime::LightType;
using runtime::Shadows;
using runtime::tool_access::TargetValues;
bool Has(const std::vector<std::string>& keywords, const char* word) {
    return std::find(keywords.begin(), keywords.end(), word) != keywords.end();
}

const TargetValues* Target(const std::vector<TargetValues>& targets, std::string_view prefix) {
    for (const TargetValues& t : targets) {
        if (t.name.rfind(prefix, 0) == 0) {
            return &t;
        }
    }
    return nullptr;
}

// The brightest channel of the image: the frame's light.
float ImageMax(const LinearImage& img) {
    float most = 0;
    for (size_t i = 0; i < img.rgba.size(); ++i) {
        most = i % 4 != 3 && std::isfinite(img.rgba[i]) ? std::max(most, img.rgba[i]) : most;
    }
    return most;
}

// The harness's shadowed light: above the sphere and a little behind it, so that the sphere's
// top and the plane are lit and its shadow falls on the plane in front of it, where the camera
// sees it. `range` 0: unlimited.
Light ShadowLight(LightType type, float range) {
    Light l = HarnessLight(type, 4.0f);
    l.name = "harness shadowed light";
    l.position = glm::vec3(0.3f, 3.0f, -0.6f);
    l.direction = glm::normalize(kHarnessSphereCentre - l.position);
    l.range = range;
    return l;
}

// A shader of the loaded packs whose passes draw the scene around an internal shader's pass:
// Kiln/StandardMetallic where loaded, else the first with a ForwardBase (or untagged) pass, a
// Deferred pass and a ShadowCaster pass.
std::optional<std::pair<uint32_t, uint32_t>> ReferenceShader(const Renderer& renderer) {
    std::optional<std::pair<uint32_t, uint32_t>> first;
    for (uint32_t p = 0; p < renderer.pack_count(); ++p) {
        const pack::Pack& pk = renderer.pack(p);
        for (uint32_t sh = 0; sh < pk.Count(pack::SectionTag::kShaders); ++sh) {
            const runtime::ShaderPasses passes = runtime::PassesOf(pk, sh);
            if (passes.base.empty() || !passes.deferred || !passes.shadow_caster) {
                continue;
            }
            if (pk.String(pk.Shader(sh).value().name) == pack::kShaderStandardMetallic) {
                return std::pair{p, sh};
            }
            first = first ? first : std::pair{p, sh};
        }
    }
    return first;
}

namespace {

// A depth target as a grey image (its stored depth in each channel, opaque).
LinearImage DepthImage(const TargetValues& t) {
    LinearImage out;
    out.width = t.width;
    out.height = t.height;
    for (float z : t.values) {
        out.rgba.insert(out.rgba.end(), {z, z, z, 1.0f});
    }
    return out;
}

}  // namespace

std::optional<ShadowReference> PassTest::ObjectSeenFrom(const glm::mat4& view_projection,
                                                        uint32_t size,
                                                        const MaterialInstance& m,
                                                        const runtime::Light& light,
                                                        bool mirrored) {
    const runtime::ShaderPasses passes = runtime::PassesOf(h.renderer.pack(c.pack), c.shader);
    if (passes.base.empty()) {
        return std::nullopt;
    }
    FrameSettings settings = h.Settings(false);
    settings.width = settings.height = size;
    runtime::CameraSetup camera;
    camera.name = "the light";
    camera.projection = view_projection;  // unity_MatrixVP is projection x view
    camera.position = light.position;
    HarnessPass draw;
    draw.material = &m;
    draw.pass = passes.base[0];
    draw.keywords = m.keywords;
    draw.pixel_light = false;
    draw.mirrored = mirrored;
    LinearImage drawn;
    std::vector<TargetValues> frame;
    if (!DrawHarnessPass(h.renderer, h.color, h.scene, settings, camera, draw, drawn, &frame)
             .ok()) {
        return std::nullopt;
    }
    const TargetValues* depth = Target(frame, "depth");
    if (!depth || depth->values.size() * 4 != drawn.rgba.size()) {
        return std::nullopt;
    }
    ShadowReference out;
    out.depth = depth->values;
    for (size_t i = 0; i < out.depth.size(); ++i) {
        // Covered: depth written, or alpha coverage (a pass without ZWrite).
        out.covered.push_back(out.depth[i] < 1.0f || drawn.rgba[i * 4 + 3] > 0.5f);
    }
    return out;
}

void PassTest::ShadowCaster() {
    const bool cube = Has(keywords, pack::kKeywordShadowsCube);
    properties = std::string("(defaults), ") + (cube ? "point" : "spot") + " light's map";
    MaterialInstance m;
    h.Material(c, m);
    FrameSettings settings = h.Settings(false);
    settings.shadows = Shadows::kHard;
    settings.shadow_resolution = kShadowResolution;
    ForwardPlan plan;
    runtime::tool_access::HarnessDrawList(
        h.scene, m, {ShadowLight(cube ? LightType::kPoint : LightType::kSpot, 0)}, plan.list);
    const Light& light = plan.list.lights[0];
    plan.shadows.lights = {&light};
    for (const DrawItem& item : plan.list.items) {
        DrawRequest r = runtime::ObjectRequest(item, c.pass);
        r.keywords = keywords;
        r.reason = "kiln test: shadow caster";
        (cube ? plan.shadows.cube_casters : plan.shadows.casters).push_back(std::move(r));
    }
    if (!Draw(settings, plan)) {
        return;
    }
    const runtime::LightShadow shadow = runtime::ShadowOf(light, runtime::SceneBounds(h.scene),
                                                          runtime::ShadowMapSize(settings, light));
    size_t faces = 0;
    for (const TargetValues& t : targets) {
        if (t.name.rfind("shadow map:", 0) != 0 || t.layer >= shadow.view_projection.size()) {
            continue;
        }
        ++faces;
        const std::optional<ShadowReference> reference =
            ObjectSeenFrom(shadow.view_projection[t.layer], t.width, m, light, cube);
        const ShadowMapCheck check =
            CheckShadowMap(t, shadow.view_projection[t.layer], shadow.depth_bias,
                           reference ? &*reference : nullptr);
        if (!check.coverage.empty() || !check.depth.empty()) {
            image = DepthImage(t);  // what a failure keeps: the map, not the empty frame
        }
        if (!check.coverage.empty()) {
            Fail("coverage", check.coverage);
        }
        if (!check.depth.empty()) {
            Fail("depth", check.depth);
        }
    }
    if (faces != shadow.view_projection.size()) {
        Fail("coverage", "the frame has " + std::to_string(faces) + " of the light's " +
                             std::to_string(shadow.view_projection.size()) + " map faces");
    }
}

void PassTest::Deferred() {
    MaterialInstance m;
    h.Material(c, m);
    FrameSettings settings = h.Settings(false);
    settings.gbuffer.octahedral = Has(keywords, pack::kKeywordGBufferNormalsOct);
    DeferredPlan plan;
    runtime::tool_access::HarnessDrawList(h.scene, m, {HarnessLight(LightType::kDirectional, 4.0f)},
                                          plan.list);
    DiagnosticList warnings;
    if (Status e = runtime::PlanDeferredRequests(runtime::tool_access::Packs(h.renderer), h.scene,
                                                 settings, h.color, plan, warnings);
        !e.ok()) {
        h.Skip(c, "not drawn: " + e.error().message);
        return;
    }
    if (plan.gbuffer.empty()) {
        h.Skip(c, "its shader is in a transparent queue, which the deferred path draws forward");
        return;
    }
    // A G-buffer pass without depth writes is a decal over a surface drawn before it (Unity's
    // terrain add passes): the light pass lights only pixels with depth.
    const pack::Pack& pk = h.renderer.pack(c.pack);
    const Result<pack::PassState> state = pack::ResolvePassState(
        pk, c.pass,
        [&](std::string_view name) -> std::optional<float> {
            const auto it = m.values.find(std::string(name));
            return it != m.values.end() && !it->second.empty() ? std::optional(it->second[0])
                                                               : std::nullopt;
        },
        m.overrides);
    if (state && !state.value().zwrite) {
        h.Skip(c,
               "its Deferred pass writes no depth (a decal over what was drawn before it), so "
               "the light pass lights none of it");
        return;
    }

    for (DrawRequest& r : plan.gbuffer) {
        r.pass = c.pass;
        r.keywords = keywords;
    }
    ++h.report.variants;
    if (!Draw(settings, plan)) {
        return;
    }
    CheckNormals(settings.gbuffer.octahedral);
    if (!(CentreMax(image, 0) > 1e-4f)) {
        Fail("lit", "the sphere is black where the light faces it (brightest channel " +
                        Describe(CentreMax(image, 0)) + ")");
    }
}

// Every covered pixel's G-buffer normal decodes to a unit vector facing the camera.
void PassTest::CheckNormals(bool octahedral) {
    const TargetValues* normals = Target(targets, "gbuffer2");
    const TargetValues* depth = Target(targets, "depth");
    if (!normals || !depth || normals->values.size() != depth->values.size() * 4) {
        Fail("normal", "the frame has no G-buffer normals to read");
        return;
    }
    const glm::mat4 inverse = glm::inverse(h.camera.projection * h.camera.view);
    size_t bad = 0, first = 0;
    float worst = 0;
    for (size_t i = 0; i < depth->values.size(); ++i) {
        const float z = depth->values[i];
        if (!(z < 1.0f)) {
            continue;
        }
        const float* e = &normals->values[i * 4];
        glm::vec3 n(e[0] * 2 - 1, e[1] * 2 - 1, e[2] * 2 - 1);
        float error = std::abs(glm::length(n) - 1.0f);
        if (octahedral) {  // any (x, y) is a direction: the length is not checked
            n = glm::vec3(n.x, n.y, 1.0f - std::abs(n.x) - std::abs(n.y));
            const float t = std::max(-n.z, 0.0f);
            n.x += n.x >= 0 ? -t : t;
            n.y += n.y >= 0 ? -t : t;
            n = glm::normalize(n);
            error = 0;
        }
        const uint32_t x = uint32_t(i % depth->width), y = uint32_t(i / depth->width);
        const glm::vec4 ndc(2 * (float(x) + 0.5f) / float(depth->width) - 1,
                            1 - 2 * (float(y) + 0.5f) / float(depth->height), z, 1);
        const glm::vec4 p = inverse * ndc;
        const glm::vec3 to_eye = glm::normalize(h.camera.position - glm::vec3(p) / p.w);
        // Unit within the 10-bit quantisation and a margin (0.02); facing the camera within
        // a normal's tilt at the silhouette (-0.1).
        const float facing = glm::dot(glm::normalize(n), to_eye);
        if (!(error <= 0.02f) || !(facing >= -0.1f)) {
            first = bad++ == 0 ? i : first;
            worst = std::max(worst, error);
        }
    }
    if (bad > 0) {
        Fail("normal", std::to_string(bad) +
                           " covered pixels' G-buffer normals are not unit vectors facing "
                           "the camera (the first at pixel " +
                           std::to_string(first % depth->width) + ", " +
                           std::to_string(first / depth->width) + "; the largest length error " +
                           Describe(worst) + ")");
    }
}

std::optional<PassKind> KindOf(const pack::Pack& pk, std::string_view name, uint32_t pass) {
    const std::string_view mode = pack::LightModeOf(pk, pass);
    if (name == pack::kShaderDeferredShading) {
        return PassKind::kDeferredLight;
    }
    if (name == pack::kShaderScreenSpaceShadows) {
        return PassKind::kCollector;
    }
    if (mode.empty() || mode == pack::kLightModeAlways || mode == pack::kLightModeForwardBase ||
        mode == pack::kLightModeForwardAdd) {
        return PassKind::kForward;
    }
    if (mode == pack::kLightModeShadowCaster) {
        return PassKind::kShadowCaster;
    }
    if (mode == pack::kLightModeDeferred) {
        return PassKind::kDeferred;
    }
    return std::nullopt;
}

std::string Unreachable(PassKind kind,
                        std::string_view pass_name,
                        const std::vector<std::string>& k) {
    if (kind != PassKind::kDeferredLight) {
        return "";
    }
    if (pass_name == pack::kPassDeferredLightMask) {
        return k.empty() ? "" : "never drawn: the stencil mask is drawn without keywords";
    }
    if (Has(k, pack::kKeywordPointCookie) || Has(k, pack::kKeywordDirectionalCookie)) {
        return "never drawn: the runtime has no light cookies";
    }
    const bool directional = Has(k, pack::kKeywordDirectional), point = Has(k, pack::kKeywordPoint),
               spot = Has(k, pack::kKeywordSpot);
    if (int(directional) + int(point) + int(spot) != 1) {
        return "never drawn: a light pass is drawn with one of DIRECTIONAL, POINT and SPOT";
    }
    if (pass_name == pack::kPassDeferredLightBounded && directional) {
        return "never drawn: a directional light has no range, and the LIGHT pass draws it";
    }
    if (Has(k, pack::kKeywordShadowsScreen) && !directional) {
        return "never drawn: SHADOWS_SCREEN is a directional light's shadow";
    }
    if (Has(k, pack::kKeywordShadowsDepth) && !spot) {
        return "never drawn: SHADOWS_DEPTH is a spot light's shadow in the light pass";
    }
    if (Has(k, pack::kKeywordShadowsCube) && !point) {
        return "never drawn: SHADOWS_CUBE is a point light's shadow";
    }
    if (Has(k, pack::kKeywordShadowsSoft) && !Has(k, pack::kKeywordShadowsDepth) &&
        !Has(k, pack::kKeywordShadowsCube)) {
        return "never drawn: SHADOWS_SOFT filters a spot or point light's shadow map (a "
               "directional light's is filtered by the screen-space collector)";
    }
    return "";
}

void Harness::TestOtherPass(PassKind kind, const Case& c) {
    PassTest t{*this, c};
    switch (kind) {
        case PassKind::kShadowCaster:
            ++report.variants;
            t.ShadowCaster();
            return;
        case PassKind::kDeferred:
            t.Deferred();
            return;
        case PassKind::kDeferredLight:
            t.LightPass();
            return;
        case PassKind::kCollector:
            t.Collector();
            return;
        case PassKind::kForward:
            return;
    }
}

}  // namespace kiln::tools
