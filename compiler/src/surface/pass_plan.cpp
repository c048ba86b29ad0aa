#include "surface/pass_plan.h"

namespace kiln::surface {
namespace {

// The base pass's blending: alpha modes and decals draw over what is there, without depth writes.
std::vector<std::string> BaseState(const SurfaceDirective& d) {
    if (d.decal == DecalMode::kAdd)
        return {"ZWrite Off", "Blend One One"};
    if (d.decal == DecalMode::kBlend)
        return {"ZWrite Off", "Blend SrcAlpha OneMinusSrcAlpha"};
    switch (EffectiveAlpha(d)) {
        case AlphaMode::kFade:
        case AlphaMode::kBlend:
            return {"ZWrite Off", "Blend SrcAlpha OneMinusSrcAlpha", "ColorMask RGB"};
        case AlphaMode::kPremul:
            return {"ZWrite Off", "Blend One OneMinusSrcAlpha", "ColorMask RGB"};
        default:
            return {};
    }
}

// Further lights add up; a faded surface adds each light by its alpha.
std::vector<std::string> AddState(const SurfaceDirective& d) {
    const AlphaMode alpha = EffectiveAlpha(d);
    if (alpha == AlphaMode::kFade || alpha == AlphaMode::kBlend || d.decal == DecalMode::kBlend)
        return {"ZWrite Off", "Blend SrcAlpha One"};
    return {"ZWrite Off", "Blend One One"};
}

// The lightmap, shadow and vertex-light options as the fwdbase shortcut's modifiers.
std::string Modifiers(const SurfaceDirective& d, std::initializer_list<const char*> names) {
    std::string out;
    for (const char* n : names) {
        if (d.Has(n))
            out += std::string(" ") + n;
    }
    return out;
}

void Common(const SurfaceDirective& d, PlannedPass& p, bool fog, bool instancing) {
    if (instancing && !d.Has("noinstancing"))
        p.pragmas.push_back("multi_compile_instancing");
    // A finalcolor: function applies fog itself (Unity's generator leaves it out then).
    if (fog && !d.Has("nofog") && !d.final_color)
        p.pragmas.push_back("multi_compile_fog");
}

}  // namespace

bool Blended(const SurfaceDirective& d) {
    return EffectiveAlpha(d) != AlphaMode::kOpaque || d.decal != DecalMode::kNone;
}

AlphaMode EffectiveAlpha(const SurfaceDirective& d) {
    if (d.alpha != AlphaMode::kAuto)
        return d.alpha;
    return d.PhysicallyBased() ? AlphaMode::kPremul : AlphaMode::kFade;
}

std::vector<PlannedPass> PlanSurfacePasses(const SurfaceDirective& d, const LightingModel& model) {
    std::vector<PlannedPass> out;
    const bool forward = !d.excluded_paths.count("forward");
    if (forward) {
        PlannedPass base{"FORWARD", "ForwardBase", "UNITY_PASS_FORWARDBASE", BaseState(d), {}};
        Common(d, base, true, true);
        base.pragmas.push_back(
            std::string(Blended(d) ? "multi_compile_fwdbasealpha" : "multi_compile_fwdbase") +
            Modifiers(d, {"noshadow", "nolightmap", "nodynlightmap", "nodirlightmap",
                          "novertexlights", "noshadowmask"}));
        out.push_back(std::move(base));
        if (!d.Has("noforwardadd")) {
            PlannedPass add{
                "FORWARD_DELTA", "ForwardAdd", "UNITY_PASS_FORWARDADD", AddState(d), {}};
            Common(d, add, true, false);
            add.pragmas.push_back(std::string(d.Has("fullforwardshadows")
                                                  ? "multi_compile_fwdadd_fullshadows"
                                                  : "multi_compile_fwdadd") +
                                  Modifiers(d, {"noshadow"}));
            out.push_back(std::move(add));
        }
    }
    // The G-buffer holds one opaque surface: no deferred pass for blended ones, except an additive
    // decal, which adds into it (the terrain's AddPass). A custom model needs its _Deferred form.
    const bool deferred_model = d.BuiltinLighting() || model.Find(LightingForm::kDeferred) ||
                                model.Find(LightingForm::kDeferredView);
    if (!d.excluded_paths.count("deferred") && deferred_model &&
        (!Blended(d) || d.decal == DecalMode::kAdd)) {
        PlannedPass deferred{"DEFERRED", "Deferred", "UNITY_PASS_DEFERRED", {}, {}};
        if (d.decal == DecalMode::kAdd)
            deferred.state = {"ZWrite Off", "Blend One One"};
        Common(d, deferred, false, true);
        deferred.pragmas.push_back("exclude_renderers nomrt");
        deferred.pragmas.push_back(
            "multi_compile_prepassfinal" +
            Modifiers(d, {"nolightmap", "nodynlightmap", "nodirlightmap", "noshadowmask"}));
        out.push_back(std::move(deferred));
    }
    // A shadow caster with addshadow, and when a vertex: function moves the vertices of an
    // opaque surface (the fallback's shadow caster would cast the unmodified mesh).
    if (d.Has("addshadow") || (d.vertex && !Blended(d))) {
        PlannedPass shadow{"ShadowCaster",
                           "ShadowCaster",
                           "UNITY_PASS_SHADOWCASTER",
                           {"ZWrite On", "ZTest LEqual"},
                           {}};
        Common(d, shadow, false, true);
        shadow.pragmas.push_back("multi_compile_shadowcaster");
        out.push_back(std::move(shadow));
    }
    if (!d.Has("nometa")) {
        PlannedPass meta{"Meta", "Meta", "UNITY_PASS_META", {"Cull Off"}, {}};
        meta.pragmas.push_back("shader_feature EDITOR_VISUALIZATION");
        out.push_back(std::move(meta));
    }
    return out;
}

}  // namespace kiln::surface
