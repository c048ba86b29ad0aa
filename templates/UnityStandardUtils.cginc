// UnityStandardUtils.cginc: the Standard shader's parameterizations and helpers with Unity's
// names: metallic and specular workflows, energy conservation, premultiplied alpha, normal maps,
// ambient SH split between vertex and pixel, box-projected reflections, parallax. Like Unity
// 5's (which the lecture was written against), it also includes UnityDeprecated.cginc, so
// DotClamped is available to code that includes only this file.
#ifndef UNITY_STANDARD_UTILS_INCLUDED
#define UNITY_STANDARD_UTILS_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityDeprecated.cginc"
#include "KilnBRDF.cginc"
#include "KilnClassicLighting.cginc"

// Strongest channel of the specular colour: the share of light the specular layer reflects.
half SpecularStrength(half3 specular) {
#if (SHADER_TARGET < 30)
    return specular.r;  // Unity's cheap path for shader model 2
#else
    return SpecularStrength_Max(specular);
#endif
}

// Scales the albedo so diffuse + specular reflectance stays <= 1 (lecture "Energy
// conservation"); oneMinusReflectivity receives the diffuse weight.
inline half3 EnergyConservationBetweenDiffuseAndSpecular(half3 albedo, half3 specColor,
                                                         out half oneMinusReflectivity) {
    return EnergyConservation_Diffuse(albedo, specColor, oneMinusReflectivity);
}

inline half OneMinusReflectivityFromMetallic(half metallic) {
    return OneMinusReflectivity_Metallic(metallic);
}

// Metallic workflow: base colour and metallic -> diffuse colour (returned), specular colour and
// the diffuse weight (glTF 2.0, Appendix B.3.5).
inline half3 DiffuseAndSpecularFromMetallic(half3 albedo, half metallic, out half3 specColor,
                                            out half oneMinusReflectivity) {
    specColor = SpecularColor_Metallic(albedo, metallic);
    oneMinusReflectivity = OneMinusReflectivity_Metallic(metallic);
    return albedo * oneMinusReflectivity;
}

// Premultiplied transparency (_ALPHAPREMULTIPLY_ON): the diffuse part fades with alpha while
// the reflected part stays; the output alpha grows by the reflectivity.
inline half3 PreMultiplyAlpha(half3 diffColor, half alpha, half oneMinusReflectivity,
                              out half outModifiedAlpha) {
#if defined(_ALPHAPREMULTIPLY_ON)
    diffColor *= alpha;
    outModifiedAlpha = 1.0 - oneMinusReflectivity + alpha * oneMinusReflectivity;
#else
    outModifiedAlpha = alpha;
#endif
    return diffColor;
}

// One-step parallax offset of the UV (Kaneko et al. 2001 with offset limiting).
half2 ParallaxOffset1Step(half h, half height, half3 viewDir) {
    h = h * height - height / 2.0;
    half3 v = SafeNormalize(viewDir);
    v.z += 0.42;
    return h * (v.xy / v.z);
}

half LerpOneTo(half b, half t) {
    return lerp(1.0, b, t);
}
half3 LerpWhiteTo(half3 b, half t) {
    return lerp(half3(1.0, 1.0, 1.0), b, t);
}

// ---- normal maps with a bump scale ----
half3 UnpackScaleNormalDXT5nm(half4 packednormal, half bumpScale) {
    half3 normal;
    normal.xy = (packednormal.wy * 2 - 1) * bumpScale;
    // guard: a scaled |xy| > 1 would make sqrt's argument negative
    normal.z = sqrt(saturate(1.0 - dot(normal.xy, normal.xy)));
    return normal;
}
half3 UnpackScaleNormalRGorAG(half4 packednormal, half bumpScale) {
    packednormal.x *= packednormal.w;
    half3 normal;
    normal.xy = (packednormal.xy * 2 - 1) * bumpScale;
    normal.z = sqrt(saturate(1.0 - dot(normal.xy, normal.xy)));
    return normal;
}
// Kiln's RGB normal maps (docs/unity-compat.md): UnpackNormalWithScale.
half3 UnpackScaleNormal(half4 packednormal, half bumpScale) {
    return UnpackNormalWithScale(packednormal, bumpScale);
}

// Detail normal over a base normal, both tangent space (whiteout blending, Barré-Brisebois and
// Hill 2012, "Blending in Detail").
half3 BlendNormals(half3 n1, half3 n2) {
    return SafeNormalize(half3(n1.xy + n2.xy, n1.z * n2.z));
}

// Rows tangent, binormal, normal; the binormal's sign is the vertex's times the object's
// handedness (unity_WorldTransformParams.w = -1 for a mirroring transform).
half3x3 CreateTangentToWorldPerVertex(half3 normal, half3 tangent, half tangentSign) {
    half sign = tangentSign * unity_WorldTransformParams.w;
    half3 binormal = cross(normal, tangent) * sign;
    return half3x3(tangent, binormal, normal);
}

// ---- ambient SH: the L2 band per vertex, L0 and L1 per pixel (or all per pixel) ----
half3 ShadeSHPerVertex(half3 normal, half3 ambient) {
#if UNITY_SAMPLE_FULL_SH_PER_PIXEL
    // everything per pixel
#elif (SHADER_TARGET < 30) || UNITY_STANDARD_SIMPLE
    ambient += ShadeSH9(half4(normal, 1.0));
#else
    ambient += SHEvalLinearL2(half4(normal, 1.0));  // clamped per pixel with the rest
#endif
    return ambient;
}
half3 ShadeSHPerPixel(half3 normal, half3 ambient, float3 worldPos) {
#if (SHADER_TARGET < 30) || UNITY_STANDARD_SIMPLE
    return ambient;  // all per vertex
#else
    half3 l0l1 = SHEvalLinearL0L1(half4(normal, 1.0));
#if UNITY_LIGHT_PROBE_PROXY_VOLUME
    if (unity_ProbeVolumeParams.x == 1.0)
        l0l1 = SHEvalLinearL0L1_SampleProbeVolume(half4(normal, 1.0), worldPos);
#endif
#if UNITY_SAMPLE_FULL_SH_PER_PIXEL
    l0l1 += SHEvalLinearL2(half4(normal, 1.0));
#endif
    // guard: the truncated SH series can ring below zero
    return max(half3(0, 0, 0), ambient + l0l1);
#endif
}

// Reflection direction for a box-projected reflection probe (cubemapCenter.w > 0): the point
// where the ray from worldPos leaves the probe's box, seen from the probe's centre.
inline float3 BoxProjectedCubemapDirection(float3 worldRefl, float3 worldPos, float4 cubemapCenter,
                                           float4 boxMin, float4 boxMax) {
    UNITY_BRANCH
    if (cubemapCenter.w > 0.0) {
        float3 dir = SafeNormalize(worldRefl);
        // guard: a zero component makes the slab distance +-Inf, which min() discards
        float3 rbmax = (boxMax.xyz - worldPos) / dir;
        float3 rbmin = (boxMin.xyz - worldPos) / dir;
        float3 rbminmax = (dir > 0.0f) ? rbmax : rbmin;
        float fa = min(min(rbminmax.x, rbminmax.y), rbminmax.z);
        worldPos -= cubemapCenter.xyz;
        worldRefl = worldPos + dir * fa;
    }
    return worldRefl;
}

// ---- bump mapping from a height field's screen-space derivatives (Mikkelsen 2010) ----
half3 CalculateSurfaceGradient(half3 n, half3 dpdx, half3 dpdy, half dhdx, half dhdy) {
    half3 r1 = cross(dpdy, n);
    half3 r2 = cross(n, dpdx);
    // guard: a degenerate screen-space frame has determinant 0
    half det = dot(dpdx, r1);
    return (r1 * dhdx + r2 * dhdy) / (abs(det) < 1e-12 ? 1e-12 : det);
}
half3 PerturbNormal(half3 n, half3 dpdx, half3 dpdy, half dhdx, half dhdy) {
    return SafeNormalize(n - CalculateSurfaceGradient(n, dpdx, dpdy, dhdx, dhdy));
}
half3 CalculateSurfaceNormal(half3 position, half3 normal, half2 gradient, half2 uv) {
    half3 dpdx = ddx(position);
    half3 dpdy = ddy(position);
    half dhdx = dot(gradient, ddx(uv));
    half dhdy = dot(gradient, ddy(uv));
    return PerturbNormal(normal, dpdx, dpdy, dhdx, dhdy);
}

#endif  // UNITY_STANDARD_UTILS_INCLUDED
