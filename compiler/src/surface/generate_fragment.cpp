// frag_surf of a generated surface-shader pass: fill the Input struct from the interpolators,
// call the surface function, then light as the pass does (Unity manual, "Surface Shader lighting
// models"): the forward passes call Lighting<Name> with the pixel light (after Lighting<Name>_GI
// in the base pass, which adds the ambient and lightmaps), the deferred pass writes the G-buffer
// through Lighting<Name>_Deferred, the shadow caster only clips, the meta pass returns albedo and
// emission for the lightmapper.
#include "surface/generate_parts.h"

namespace kiln::surface {
namespace {

std::string FillInput(const SurfaceShader& s, const Interpolators& in) {
    std::string out = "    " + s.input.name + " surfIN;\n";
    out += "    UNITY_INITIALIZE_OUTPUT(" + s.input.name + ", surfIN);\n";
    if (s.tangent_space) {
        out += "    float3 worldPos = float3(IN.tSpace0.w, IN.tSpace1.w, IN.tSpace2.w);\n";
        for (int i = 0; i < 3; ++i) {
            const std::string n = std::to_string(i);
            out += "    float3 _unity_tbn_" + n + " = IN.tSpace" + n + ".xyz;\n";
        }
    } else {
        out += "    float3 worldPos = IN.worldPos;\n";
    }
    out += "    float3 worldViewDir = normalize(UnityWorldSpaceViewDir(worldPos));\n";
    for (const InputMember& m : s.input.members) {
        const std::string to = "    surfIN." + m.name;
        std::string o;
        switch (m.kind) {
            case InputKind::kTexcoord:
                o += to + ".xy = IN." + PackName(m) + ";\n";
                break;
            case InputKind::kViewDir:
                o += to + (s.tangent_space ? " = _unity_tbn_0 * worldViewDir.x + _unity_tbn_1 * "
                                             "worldViewDir.y + _unity_tbn_2 * worldViewDir.z;\n"
                                           : " = worldViewDir;\n");
                break;
            case InputKind::kWorldPos:
                o += to + " = worldPos;\n";
                break;
            case InputKind::kWorldNormal:
                o += to + (s.tangent_space ? " = 0.0;\n" : " = normalize(IN.worldNormal);\n");
                break;
            case InputKind::kWorldRefl:
                o += to + (s.tangent_space ? " = -worldViewDir;\n"
                                           : " = reflect(-worldViewDir, IN.worldNormal);\n");
                break;
            case InputKind::kScreenPos:
                o += to + " = IN.screenPos;\n";
                break;
            case InputKind::kColor:
                o += to + " = IN.color;\n";
                break;
            case InputKind::kFacing:
                o += to + " = facing ? 1.0 : -1.0;\n";
                break;
            case InputKind::kCustom:
                break;
        }
        out += o.empty() ? "" : Guarded(m, o);
    }
    for (const InputMember* m : in.custom) {
        const bool fog = m->semantic == "FOG";
        out += Guarded(*m, std::string(fog ? "#if defined(FOG_LINEAR) || defined(FOG_EXP) || "
                                             "defined(FOG_EXP2)\n"
                                           : "") +
                               "    surfIN." + m->name + " = IN." + PackName(*m) + ";\n" +
                               (fog ? "#endif\n" : ""));
    }
    if (s.tangent_space && s.input.internal_data) {
        for (int i = 0; i < 3; ++i) {
            const std::string n = std::to_string(i);
            out += "    surfIN.internalSurfaceTtoW" + n + " = _unity_tbn_" + n + ";\n";
        }
    }
    return out;
}

// The output struct, the surface function's call, the alpha test and the world normal.
std::string CallSurface(const SurfaceShader& s) {
    std::string o = "    " + s.output_type + " o;\n";
    o += "    UNITY_INITIALIZE_OUTPUT(" + s.output_type + ", o);\n";
    if (s.PhysicallyBasedOutput())
        o += "    o.Occlusion = 1.0;\n";
    o += s.tangent_space ? "    o.Normal = fixed3(0, 0, 1);\n"
                         : "    o.Normal = normalize(IN.worldNormal);\n";
    o += "    " + s.directive.function.text + "(surfIN, o);\n";
    if (s.directive.alpha_test)
        o += "    clip(o.Alpha - " + s.directive.alpha_test->text + ");\n";
    if (s.tangent_space) {
        o += "    float3 worldN;\n";
        for (int i = 0; i < 3; ++i) {
            const std::string n = std::to_string(i);
            o += "    worldN." + std::string(1, "xyz"[i]) + " = dot(_unity_tbn_" + n +
                 ", o.Normal);\n";
        }
        o += "    o.Normal = normalize(worldN);\n";
    }
    if (s.directive.Has("dithercrossfade"))
        o += "#ifdef LOD_FADE_CROSSFADE\n    UNITY_APPLY_DITHER_CROSSFADE(IN.pos.xy);\n#endif\n";
    return o;
}

// The view direction argument of a model that takes one: the half vector with `halfasview`.
std::string ViewArgument(const SurfaceShader& s) {
    return s.directive.Has("halfasview") ? "normalize(lightDir + worldViewDir)" : "worldViewDir";
}

std::string GIInput(const SurfaceShader& s) {
    std::string o =
        "    UnityGI gi;\n    UNITY_INITIALIZE_OUTPUT(UnityGI, gi);\n"
        "    gi.indirect.diffuse = 0;\n    gi.indirect.specular = 0;\n"
        "    gi.light.color = _LightColor0.rgb;\n    gi.light.dir = lightDir;\n"
        "    UnityGIInput giInput;\n    UNITY_INITIALIZE_OUTPUT(UnityGIInput, giInput);\n"
        "    giInput.light = gi.light;\n    giInput.worldPos = worldPos;\n"
        "    giInput.worldViewDir = worldViewDir;\n    giInput.atten = atten;\n"
        "#if defined(LIGHTMAP_ON) || defined(DYNAMICLIGHTMAP_ON)\n"
        "    giInput.lightmapUV = IN.lmap;\n#else\n    giInput.lightmapUV = 0.0;\n#endif\n"
        "#if UNITY_SHOULD_SAMPLE_SH\n    giInput.ambient = IN.sh;\n#else\n"
        "    giInput.ambient.rgb = 0.0;\n#endif\n"
        "    giInput.probeHDR[0] = unity_SpecCube0_HDR;\n"
        "    giInput.probeHDR[1] = unity_SpecCube1_HDR;\n"
        "#if defined(UNITY_SPECCUBE_BLENDING) || defined(UNITY_SPECCUBE_BOX_PROJECTION)\n"
        "    giInput.boxMin[0] = unity_SpecCube0_BoxMin;\n#endif\n"
        "#ifdef UNITY_SPECCUBE_BOX_PROJECTION\n"
        "    giInput.boxMax[0] = unity_SpecCube0_BoxMax;\n"
        "    giInput.probePosition[0] = unity_SpecCube0_ProbePosition;\n"
        "    giInput.boxMax[1] = unity_SpecCube1_BoxMax;\n"
        "    giInput.boxMin[1] = unity_SpecCube1_BoxMin;\n"
        "    giInput.probePosition[1] = unity_SpecCube1_ProbePosition;\n#endif\n";
    if (s.model.Find(LightingForm::kGI)) {
        o += "    " + s.model.Find(LightingForm::kGI)->name + "(o, giInput, gi);\n";
    } else {
        // A model without a _GI function: the pixel light, attenuated, and the ambient.
        o += "    gi.light.color *= atten;\n    gi.indirect.diffuse = giInput.ambient;\n";
    }
    return o;
}

// c += the lighting function of the forward passes.
std::string ForwardLight(const SurfaceShader& s, bool base) {
    const LightingFunction& f = *s.model.Forward();
    std::string o =
        "#ifndef USING_DIRECTIONAL_LIGHT\n"
        "    fixed3 lightDir = normalize(UnityWorldSpaceLightDir(worldPos));\n#else\n"
        "    fixed3 lightDir = _WorldSpaceLightPos0.xyz;\n#endif\n"
        "    UNITY_LIGHT_ATTENUATION(atten, IN, worldPos)\n    fixed4 c = 0;\n";
    const bool legacy =
        f.form == LightingForm::kForwardLegacy || f.form == LightingForm::kForwardLegacyView;
    const bool view =
        f.form == LightingForm::kForwardView || f.form == LightingForm::kForwardLegacyView;
    if (legacy) {
        o += "    c += " + f.name + "(o, lightDir, " + (view ? ViewArgument(s) + ", " : "") +
             "atten);\n";
        if (base) {
            o += "#if UNITY_SHOULD_SAMPLE_SH && !defined(LIGHTMAP_ON)\n"
                 "    c.rgb += o.Albedo * IN.sh;\n#endif\n";
        }
    } else {
        if (base) {
            o += GIInput(s);
        } else {
            o += "    UnityGI gi;\n    UNITY_INITIALIZE_OUTPUT(UnityGI, gi);\n"
                 "    gi.indirect.diffuse = 0;\n    gi.indirect.specular = 0;\n"
                 "    gi.light.color = _LightColor0.rgb * atten;\n    gi.light.dir = lightDir;\n";
        }
        o += "    c += " + f.name + "(o, " + (view ? ViewArgument(s) + ", " : "") + "gi);\n";
    }
    if (base)
        o += "    c.rgb += o.Emission;\n";
    if (s.directive.final_color)
        o += "    " + s.directive.final_color->text + "(surfIN, o, c);\n";
    if (AppliesFog(s, base ? PassKind::kForwardBase : PassKind::kForwardAdd))
        o += "    UNITY_APPLY_FOG(IN.fogCoord, c);\n";
    if (!Blended(s.directive) && !s.directive.Has("keepalpha"))
        o += "    UNITY_OPAQUE_ALPHA(c.a);\n";
    return o + "    return c;\n";
}

std::string Deferred(const SurfaceShader& s) {
    const LightingFunction* f = s.model.Find(LightingForm::kDeferredView);
    const bool view = f != nullptr;
    if (!f)
        f = s.model.Find(LightingForm::kDeferred);
    std::string o = "    half atten = 1;\n    fixed3 lightDir = half3(0, 1, 0);\n";
    o += GIInput(s);
    o += "    gi.light.color = 0;\n";
    o += "    outEmission = " + f->name + "(o, " + (view ? "worldViewDir, " : "") +
         "gi, outGBuffer0, outGBuffer1, outGBuffer2);\n";
    o += "#if defined(SHADOWS_SHADOWMASK) && (UNITY_ALLOWED_MRT_COUNT > 4)\n"
         "    outShadowMask = UnityGetRawBakedOcclusions(IN.lmap.xy, worldPos);\n#endif\n";
    if (s.directive.final_gbuffer) {
        o += "    " + s.directive.final_gbuffer->text +
             "(surfIN, o, outGBuffer0, outGBuffer1, outGBuffer2, outEmission);\n";
    }
    return o;
}

std::string Signature(PassKind kind, const Interpolators& in) {
    const std::string facing = in.facing ? ", bool facing : SV_IsFrontFace" : "";
    if (kind != PassKind::kDeferred)
        return "fixed4 frag_surf(v2f_surf IN" + facing + ") : SV_Target {\n";
    return "void frag_surf(v2f_surf IN" + facing +
           ", out half4 outGBuffer0 : SV_Target0, out half4 outGBuffer1 : SV_Target1,\n"
           "               out half4 outGBuffer2 : SV_Target2, out half4 outEmission : "
           "SV_Target3\n"
           "#if defined(SHADOWS_SHADOWMASK) && (UNITY_ALLOWED_MRT_COUNT > 4)\n"
           "               , out half4 outShadowMask : SV_Target4\n#endif\n) {\n";
}

}  // namespace

std::string FragmentProgram(const SurfaceShader& s, PassKind kind, const Interpolators& in) {
    std::string o = "\n" + Signature(kind, in);
    if (s.vertex_input.instance_id)
        o += "    UNITY_SETUP_INSTANCE_ID(IN);\n";
    o += FillInput(s, in) + CallSurface(s);
    switch (kind) {
        case PassKind::kForwardBase:
        case PassKind::kForwardAdd:
            o += ForwardLight(s, kind == PassKind::kForwardBase);
            break;
        case PassKind::kDeferred:
            o += Deferred(s);
            break;
        case PassKind::kShadowCaster:
            o += "    SHADOW_CASTER_FRAGMENT(IN)\n";
            break;
        case PassKind::kMeta:
            o +=
                "    UnityMetaInput metaIN;\n    UNITY_INITIALIZE_OUTPUT(UnityMetaInput, metaIN);\n"
                "    metaIN.Albedo = o.Albedo;\n    metaIN.Emission = o.Emission;\n"
                "    return UnityMetaFragment(metaIN);\n";
            break;
    }
    return o + "}\n";
}

}  // namespace kiln::surface
