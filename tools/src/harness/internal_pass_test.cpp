// kiln test on the internal shaders' passes (harness/pass_test.h): the deferred light pass over a
// reference shader's G-buffer, and the screen-space shadow collector in a forward frame.
#include <algorithm>
#include <cmath>

#include "harness/pass_test.h"
#include "kiln/pack/engine_names.h"

namespace kiln::tools {

using runtime::DeferredPlan;
using runtime::ForwardPlan;
using runtime::FrameSettings;
using runtime::LightDraw;
using runtime::LightType;
using runtime::Shadows;
namespace {

bool IsShadowKeyword(const std::string& k) {
    return k == pack::kKeywordShadowsScreen || k == pack::kKeywordShadowsDepth ||
           k == pack::kKeywordShadowsCube || k == pack::kKeywordShadowsSoft;
}

// The pass of `shader` (its first SubShader) a light draw of `role` uses: the first pass, or
// the stencil mask's and the bounded light's by name.
std::optional<uint32_t> PassOfRole(const pack::Pack& pk, uint32_t shader, LightDraw::Role role) {
    const pack::ShaderRec sr = pk.Shader(shader).value();
    if (role == LightDraw::Role::kWhole) {
        return sr.pass_count ? std::optional(sr.first_pass) : std::nullopt;
    }
    const std::string_view want = role == LightDraw::Role::kMask ? pack::kPassDeferredLightMask
                                                                 : pack::kPassDeferredLightBounded;
    for (uint32_t p = sr.first_pass; p < sr.first_pass + sr.pass_count; ++p) {
        const pack::PassRec rec = pk.Pass(p).value();
        if (rec.subshader == 0 && pk.String(rec.name) == want) {
            return p;
        }
    }
    return std::nullopt;
}

// The deferred frame of the reference shader lit by one light of `type`, its light passes
// drawn by the variant's shader, the requests of the variant's pass with `keywords`.
struct LightFrame {
    PassTest& t;
    std::pair<uint32_t, uint32_t> reference;
    LightType type;
    bool ranged;

    bool Draw(const FrameSettings& settings, const std::vector<std::string>& keywords) {
        Harness& h = t.h;
        MaterialInstance m;
        runtime::InstanceFromDefaults(h.renderer.pack(reference.first), reference.first,
                                      reference.second, h.color, m);
        DeferredPlan plan;
        runtime::tool_access::HarnessDrawList(h.scene, m, {ShadowLight(type, ranged ? 8.0f : 0)},
                                              plan.list);
        DiagnosticList warnings;
        if (Status e = runtime::PlanDeferredRequests(runtime::tool_access::Packs(h.renderer),
                                                     h.scene, settings, h.color, plan, warnings);
            !e.ok()) {
            t.Fail("pipeline", e.error().message, false);
            return false;
        }
        if (!plan.light_material) {
            t.Fail("drawn", "the reference shader drew no G-buffer to light", false);
            return false;
        }
        // The light passes of the variant's own shader (its pack need not be the first).
        const pack::Pack& pk = h.renderer.pack(t.c.pack);
        MaterialInstance light;
        runtime::InstanceFromDefaults(pk, t.c.pack, t.c.shader, h.color, light);
        *plan.light_material = std::move(light);
        size_t matched = 0;
        for (LightDraw& l : plan.lights) {
            l.request.pass = PassOfRole(pk, t.c.shader, l.role).value_or(l.request.pass);
            if (l.request.pass == t.c.pass) {
                l.request.keywords = keywords;
                ++matched;
            }
        }
        if (matched == 0) {
            t.Fail("drawn", "the deferred path drew no light with this pass", false);
            return false;
        }
        return t.Draw(settings, plan);
    }
};

}  // namespace

void PassTest::LightPass() {
    const auto reference = ReferenceShader(h.renderer);
    if (!reference) {
        h.Skip(c, kNoReference);
        return;
    }
    const pack::Pack& pk = h.renderer.pack(c.pack);
    const std::string_view name = pk.String(pk.Pass(c.pass).value().name);
    const bool ranged =
        name == pack::kPassDeferredLightMask || name == pack::kPassDeferredLightBounded;
    const LightType type = Has(keywords, pack::kKeywordPoint) || keywords.empty()
                               ? LightType::kPoint
                           : Has(keywords, pack::kKeywordSpot) ? LightType::kSpot
                                                               : LightType::kDirectional;
    const bool shadowed = std::any_of(keywords.begin(), keywords.end(), IsShadowKeyword);
    FrameSettings settings = h.Settings(false);
    settings.shadows = Has(keywords, pack::kKeywordShadowsSoft) ? Shadows::kSoft
                       : shadowed                               ? Shadows::kHard
                                                                : Shadows::kOff;
    settings.shadow_resolution = kShadowResolution;
    settings.gbuffer.octahedral = Has(keywords, pack::kKeywordGBufferNormalsOct);
    properties = std::string("(defaults), ") + (ranged ? "ranged " : "") +
                 (type == LightType::kPoint  ? "point light"
                  : type == LightType::kSpot ? "spot light"
                                             : "directional light") +
                 (shadowed ? " with its shadow" : "");
    ++h.report.variants;
    LightFrame frame{*this, *reference, type, ranged};
    if (!frame.Draw(settings, keywords)) {
        return;
    }
    if (!(ImageMax(image) > 1e-4f)) {
        Fail("lit", "the light pass adds no light: the frame is black");
    }
    if (!shadowed) {
        return;
    }
    // The same frame without the shadow: the shadow only darkens, and darkens the plane where
    // the sphere's shadow falls in view.
    const LinearImage with_shadow = image;
    std::vector<std::string> plain;
    std::copy_if(keywords.begin(), keywords.end(), std::back_inserter(plain),
                 [](const std::string& k) { return !IsShadowKeyword(k); });
    settings.shadows = Shadows::kOff;
    if (!frame.Draw(settings, plain)) {
        return;
    }
    const LinearImage without = std::move(image);
    image = with_shadow;
    if (without.rgba.size() != image.rgba.size()) {
        return;
    }
    size_t darker = 0;
    float brighter = 0;
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
        float lit = 0, shade = 0;
        for (size_t k = 0; k < 3; ++k) {
            lit += without.rgba[i + k];
            shade += image.rgba[i + k];
            brighter = std::max(brighter, image.rgba[i + k] - without.rgba[i + k] -
                                              1e-3f * without.rgba[i + k] - 1e-4f);
        }
        darker += lit > 3e-3f && shade < 0.5f * lit;
    }
    if (brighter > 0) {
        Fail("shadow", "the shadow brightens a pixel by up to " + Describe(brighter) +
                           " against the frame without it");
    } else if (darker < 4) {
        Fail("shadow", "the shadow darkens " + std::to_string(darker) +
                           " pixels to less than half the frame without it, where the sphere's "
                           "shadow on the plane covers many");
    }
}

void PassTest::Collector() {
    const auto reference = ReferenceShader(h.renderer);
    if (!reference) {
        h.Skip(c, kNoReference);
        return;
    }
    FrameSettings settings = h.Settings(false);
    settings.shadows = Has(keywords, pack::kKeywordShadowsSoft) ? Shadows::kSoft : Shadows::kHard;
    settings.shadow_resolution = kShadowResolution;
    properties = "(defaults), directional light with its shadow";
    ++h.report.variants;
    MaterialInstance m;
    runtime::InstanceFromDefaults(h.renderer.pack(reference->first), reference->first,
                                  reference->second, h.color, m);
    ForwardPlan plan;
    runtime::tool_access::HarnessDrawList(h.scene, m, {ShadowLight(LightType::kDirectional, 0)},
                                          plan.list);
    DiagnosticList warnings;
    if (Status e = runtime::PlanForwardRequests(runtime::tool_access::Packs(h.renderer), h.scene,
                                                settings, h.color, plan, warnings);
        !e.ok()) {
        Fail("pipeline", e.error().message, false);
        return;
    }
    if (!plan.shadows.collect || !plan.shadows.collector) {
        Fail("drawn", "the forward path collected no screen-space shadows", false);
        return;
    }
    MaterialInstance collector;
    runtime::InstanceFromDefaults(h.renderer.pack(c.pack), c.pack, c.shader, h.color, collector);
    *plan.shadows.collector = std::move(collector);
    plan.shadows.collect->pass = c.pass;
    plan.shadows.collect->keywords = keywords;
    if (!Draw(settings, plan)) {
        return;
    }
    if (!(ImageMax(image) > 1e-4f)) {
        Fail("lit", "the frame is black");
    }
    const TargetValues* screen = Target(targets, "screen-space shadows");
    if (!screen) {
        Fail("drawn", "the frame has no screen-space shadow target");
        return;
    }
    // The sphere's shadow falls on the plane in view; the rest of the view is lit.
    const size_t shadowed = size_t(std::count_if(screen->values.begin(), screen->values.end(),
                                                 [](float v) { return v < 0.5f; }));
    const size_t lit = size_t(std::count_if(screen->values.begin(), screen->values.end(),
                                            [](float v) { return v > 0.99f; }));
    if (shadowed < 4 || lit < screen->values.size() / 2) {
        Fail("shadow", "the screen-space shadows hold " + std::to_string(shadowed) +
                           " shadowed and " + std::to_string(lit) + " lit of " +
                           std::to_string(screen->values.size()) +
                           " pixels, where the sphere's shadow covers some and most are lit");
    }
}

}  // namespace kiln::tools
