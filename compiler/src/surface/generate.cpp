#include "surface/generate.h"

#include "surface/generate_parts.h"

namespace kiln::surface {
namespace {

// What goes before the shader's own code: the pass's pragmas, the defines the alpha modes set
// for the Standard lighting functions, the include files the lighting needs, and INTERNAL_DATA
// with WorldNormalVector / WorldReflectionVector (the tangent frame when the surface function
// writes a per-pixel normal, else the interpolated world vectors).
std::string Header(const SurfaceShader& s, const PlannedPass& pass, PassKind kind) {
    std::string o = "#pragma vertex vert_surf\n#pragma fragment frag_surf\n";
    for (const std::string& p : pass.pragmas)
        o += "#pragma " + p + "\n";
    if (s.directive.Has("dithercrossfade") && kind != PassKind::kMeta && !s.declares_crossfade)
        o += "#pragma multi_compile _ LOD_FADE_CROSSFADE\n";
    switch (EffectiveAlpha(s.directive)) {
        case AlphaMode::kFade:
        case AlphaMode::kBlend:
            o += "#define _ALPHABLEND_ON 1\n";
            break;
        case AlphaMode::kPremul:
            o += "#define _ALPHAPREMULTIPLY_ON 1\n";
            break;
        default:
            break;
    }
    if (s.directive.alpha_test)
        o += "#define _ALPHATEST_ON 1\n";
    o += "#include \"UnityCG.cginc\"\n#include \"Lighting.cginc\"\n";
    if (s.PhysicallyBasedOutput())
        o += "#include \"UnityPBSLighting.cginc\"\n";
    o += "#include \"AutoLight.cginc\"\n";
    if (kind == PassKind::kMeta)
        o += "#include \"UnityMetaPass.cginc\"\n";
    if (s.tangent_space) {
        o += "#define INTERNAL_DATA half3 internalSurfaceTtoW0; half3 internalSurfaceTtoW1; "
             "half3 internalSurfaceTtoW2;\n"
             "#define WorldReflectionVector(data, normal) reflect(data.worldRefl, "
             "half3(dot(data.internalSurfaceTtoW0, normal), dot(data.internalSurfaceTtoW1, "
             "normal), dot(data.internalSurfaceTtoW2, normal)))\n"
             "#define WorldNormalVector(data, normal) fixed3(dot(data.internalSurfaceTtoW0, "
             "normal), dot(data.internalSurfaceTtoW1, normal), dot(data.internalSurfaceTtoW2, "
             "normal))\n";
    } else {
        o += "#define INTERNAL_DATA\n#define WorldReflectionVector(data, normal) "
             "data.worldRefl\n#define WorldNormalVector(data, normal) normal\n";
    }
    return o;
}

}  // namespace

PassKind KindOf(const PlannedPass& pass) {
    if (pass.light_mode == "ForwardBase")
        return PassKind::kForwardBase;
    if (pass.light_mode == "ForwardAdd")
        return PassKind::kForwardAdd;
    if (pass.light_mode == "Deferred")
        return PassKind::kDeferred;
    if (pass.light_mode == "ShadowCaster")
        return PassKind::kShadowCaster;
    return PassKind::kMeta;
}

std::vector<GeneratedPass> GenerateSurfacePasses(const SurfaceShader& shader) {
    std::vector<GeneratedPass> out;
    for (PlannedPass& plan : PlanSurfacePasses(shader.directive, shader.model)) {
        const PassKind kind = KindOf(plan);
        GeneratedPass g;
        g.header = Header(shader, plan, kind);
        const Interpolators interp = PlanInterpolators(shader, kind);
        g.tail = V2fStruct(interp) + VertexProgram(shader, kind, interp) +
                 FragmentProgram(shader, kind, interp);
        g.plan = std::move(plan);
        out.push_back(std::move(g));
    }
    return out;
}

}  // namespace kiln::surface
