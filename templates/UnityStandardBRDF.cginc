// UnityStandardBRDF.cginc: Unity's BRDF terms and its three Standard BRDFs over KilnBRDF.cginc.
// BRDF1 is the full model (GGX / Smith height-correlated / Schlick, Disney-free Lambert diffuse);
// BRDF2 and BRDF3 are Unity's cheaper approximations for lower quality tiers.
#ifndef UNITY_STANDARD_BRDF_INCLUDED
#define UNITY_STANDARD_BRDF_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityLightingCommon.cginc"
#include "KilnBRDF.cginc"

// ---- parameterizations (KilnBRDF.cginc has PerceptualRoughnessToRoughness and
// SmoothnessToPerceptualRoughness) ----
half RoughnessToPerceptualRoughness(half roughness) {
    return sqrt(max(roughness, 0.0));
}
half SmoothnessToRoughness(half smoothness) {
    return PerceptualRoughnessToRoughness(SmoothnessToPerceptualRoughness(smoothness));
}

inline half Pow4(half x) {
    return x * x * x * x;
}
inline float2 Pow4(float2 x) {
    return x * x * x * x;
}
inline half3 Pow4(half3 x) {
    return x * x * x * x;
}
inline half4 Pow4(half4 x) {
    return x * x * x * x;
}
inline half2 Pow5(half2 x) {
    return x * x * x * x * x;
}
inline half3 Pow5(half3 x) {
    return x * x * x * x * x;
}
inline half4 Pow5(half4 x) {
    return x * x * x * x * x;
}

inline float3 Unity_SafeNormalize(float3 inVec) {
    return SafeNormalize(inVec);
}

// ---- terms ----
// Schlick's Fresnel (Schlick 1994, eq. 24), towards 1 or towards F90.
inline half3 FresnelTerm(half3 F0, half cosA) {
    return F_Schlick(F0, cosA);
}
inline half3 FresnelLerp(half3 F0, half3 F90, half cosA) {
    return F_SchlickLerp(F0, F90, cosA);
}
// The same with (1 - cos)^4 (Unity's cheaper approximation).
inline half3 FresnelLerpFast(half3 F0, half3 F90, half cosA) {
    return lerp(F0, F90, Pow4(1.0 - saturate(cosA)));
}
// Burley's diffuse (Burley 2012, eq. 5) without the 1/pi (Kiln's light convention).
half DisneyDiffuse(half NdotV, half NdotL, half LdotH, half perceptualRoughness) {
    half fd90 = 0.5 + 2.0 * LdotH * LdotH * perceptualRoughness;
    half lightScatter = 1.0 + (fd90 - 1.0) * Pow5(1.0 - saturate(NdotL));
    half viewScatter = 1.0 + (fd90 - 1.0) * Pow5(1.0 - saturate(NdotV));
    return lightScatter * viewScatter;
}
// Separable Smith with Schlick's k: 1 / ((n.l (1-k) + k)(n.v (1-k) + k)); the caller applies the
// 1/4 of the microfacet denominator (as SmithBeckmannVisibilityTerm does).
inline half SmithVisibilityTerm(half NdotL, half NdotV, half k) {
    half gL = NdotL * (1 - k) + k;
    half gV = NdotV * (1 - k) + k;
    // guard: k = 0 at grazing angles gives 1 / 0; the bound is binary16's smallest normal value,
    // so the quotient stays finite in a --precision half build (Unity's 1e-5 gives 1e5 > 65504)
    return 1.0 / max(gL * gV, KILN_HALF_MIN);
}
// Beckmann's k = a sqrt(2/pi) (Schlick 1994).
inline half SmithBeckmannVisibilityTerm(half NdotL, half NdotV, half roughness) {
    half k = roughness * 0.797884560802865;
    return SmithVisibilityTerm(NdotL, NdotV, k) * 0.25;
}
// Height-correlated Smith visibility for GGX (Heitz 2014, eq. 99).
inline float SmithJointGGXVisibilityTerm(float NdotL, float NdotV, float roughness) {
    return V_SmithGGXCorrelated(NdotV, NdotL, roughness);
}
// GGX distribution (Walter et al. 2007, eq. 33) over pi (Unity's convention multiplies by pi).
inline float GGXTerm(float NdotH, float roughness) {
    return D_GGX(NdotH, roughness);
}
// Perceptual roughness -> Blinn-Phong exponent through a^4 (Walter et al. 2007, section 5.2).
inline half PerceptualRoughnessToSpecPower(half perceptualRoughness) {
    half m = PerceptualRoughnessToRoughness(perceptualRoughness);
    half sq = max(1e-4f, m * m);
    half n = (2.0 / sq) - 2.0;
    return max(n, 1e-4f);
}
// Normalized Blinn-Phong distribution (n + 2) / (2 pi) (n.h)^n.
inline half NDFBlinnPhongNormalizedTerm(half NdotH, half n) {
    return (n + 2.0) * (0.5 * KILN_INV_PI) * SafePow(NdotH, n);
}
// The cubemap mip whose filter width matches a Blinn-Phong exponent (McGuire et al. 2011).
float GetSpecPowToMip(float fSpecPow, int nMips) {
    float fSmulMaxT = (exp2(-10.0 / sqrt(max(fSpecPow, 1e-4))) - 0.00098) / 0.99902;
    return float(nMips - 1) * (1.0 - clamp(fSmulMaxT, 0.0, 1.0));
}

// ---- BRDF1: physically based shading for one direct light plus indirect light ----
// Lambert diffuse, GGX / Smith height-correlated / Schlick specular (KilnBRDF.cginc), and
// Unity's indirect-specular terms (surface reduction 1 / (a^2 + 1) and Fresnel towards a
// grazing reflectance of smoothness + reflectivity). Colours are linear; the result is clamped
// to the binary16 range so a 16-bit float target never receives Inf.
half4 BRDF1_Unity_PBS(half3 diffColor, half3 specColor, half oneMinusReflectivity,
                      half smoothness, float3 normal, float3 viewDir, UnityLight light,
                      UnityIndirect gi) {
    float a = PerceptualRoughnessToRoughness(SmoothnessToPerceptualRoughness(smoothness));
    // guard: unnormalized or zero inputs (interpolated normals, a zero light direction) stay
    // finite; SafeNormalize maps zero to zero
    float3 n = SafeNormalize(normal);
    float3 l = SafeNormalize(light.dir);
    float3 v = SafeNormalize(viewDir);
    float3 h = SafeNormalize(l + v);  // guard: l = -v gives h = 0 instead of NaN
    // guard: interpolated normals can face away from the viewer (n . v <= 0); use |n . v| as
    // Unity does and keep it above 1e-5 so the visibility term's denominator stays positive
    float NoV = max(abs(dot(n, v)), 1e-5);
    float NoL = saturate(dot(n, l));
    float NoH = saturate(dot(n, h));
    float LoH = saturate(dot(l, h));

    float3 diffuse = diffColor * (gi.diffuse + light.color * (NoL * Fd_Lambert()));
    float3 specular = BRDF_Specular(specColor, NoV, NoL, NoH, LoH, a) * light.color;
#if defined(_SPECULARHIGHLIGHTS_OFF)
    specular = 0.0;
#endif
    float surfaceReduction = 1.0 / (a * a + 1.0);
    float grazing = saturate(smoothness + (1.0 - oneMinusReflectivity));
    float3 indirectSpecular =
        surfaceReduction * gi.specular * F_SchlickLerp(specColor, grazing, NoV);
    return half4(ClampToHalfRange(diffuse + specular + indirectSpecular), 1.0);
}

// ---- BRDF2: GGX with the combined visibility-Fresnel approximation of Zioma 2015
// ("Optimizing PBR for Mobile", SIGGRAPH course): V F ~ 1 / ((l.h)^2 (a + 0.5)) ----
half4 BRDF2_Unity_PBS(half3 diffColor, half3 specColor, half oneMinusReflectivity,
                      half smoothness, float3 normal, float3 viewDir, UnityLight light,
                      UnityIndirect gi) {
    float3 n = SafeNormalize(normal);
    float3 l = SafeNormalize(light.dir);
    float3 v = SafeNormalize(viewDir);
    float3 h = SafeNormalize(l + v);
    half NoL = saturate(dot(n, l));
    float NoH = saturate(dot(n, h));
    half NoV = saturate(dot(n, v));
    float LoH = saturate(dot(l, h));
    half a = PerceptualRoughnessToRoughness(SmoothnessToPerceptualRoughness(smoothness));
    float a2 = a * a;
    float d = NoH * NoH * (a2 - 1.0) + 1.0;
    // guard: d and l.h are bounded away from 0 so the lobe stays finite
    float specularTerm = a2 / (max(d * d, 1e-7) * max(0.1, LoH * LoH) * (a + 0.5) * 4.0);
#if defined(_SPECULARHIGHLIGHTS_OFF)
    specularTerm = 0.0;
#endif
    half surfaceReduction = 1.0 - 0.28 * a * SmoothnessToPerceptualRoughness(smoothness);
    half grazing = saturate(smoothness + (1.0 - oneMinusReflectivity));
    half3 color = (diffColor + specularTerm * specColor) * light.color * NoL +
                  gi.diffuse * diffColor +
                  surfaceReduction * gi.specular * FresnelLerpFast(specColor, grazing, NoV);
    return half4(ClampToHalfRange(color), 1.0);
}

// ---- BRDF3: normalized Blinn-Phong on the reflection vector (Unity's low tier) ----
// rlPow4: (reflection . light)^4 and (1 - n.v)^4 in x and y.
half3 BRDF3_Direct(half3 diffColor, half3 specColor, half rlPow4, half smoothness) {
    half n = PerceptualRoughnessToSpecPower(SmoothnessToPerceptualRoughness(smoothness));
    // (r.l)^n from (r.l)^4: raise to n / 4
    half specular = (n + 2.0) * (0.5 * KILN_INV_PI) * SafePow(rlPow4, n * 0.25) * KILN_PI;
#if defined(_SPECULARHIGHLIGHTS_OFF)
    specular = 0.0;
#endif
    return diffColor + specular * specColor;
}
half3 BRDF3_Indirect(half3 diffColor, half3 specColor, UnityIndirect indirect, half grazingTerm,
                     half fresnelTerm) {
    half3 c = indirect.diffuse * diffColor;
    c += indirect.specular * lerp(specColor, grazingTerm, fresnelTerm);
    return c;
}
half4 BRDF3_Unity_PBS(half3 diffColor, half3 specColor, half oneMinusReflectivity,
                      half smoothness, float3 normal, float3 viewDir, UnityLight light,
                      UnityIndirect gi) {
    float3 n = SafeNormalize(normal);
    float3 v = SafeNormalize(viewDir);
    float3 reflDir = reflect(-v, n);
    half NoL = saturate(dot(n, light.dir));
    half NoV = saturate(dot(n, v));
    half2 rlPow4AndFresnel = Pow4(float2(dot(reflDir, light.dir), 1.0 - NoV));
    half grazing = saturate(smoothness + (1.0 - oneMinusReflectivity));
    half3 color = BRDF3_Direct(diffColor, specColor, max(rlPow4AndFresnel.x, 0.0), smoothness);
    color *= light.color * NoL;
    color += BRDF3_Indirect(diffColor, specColor, gi, grazing, rlPow4AndFresnel.y);
    return half4(ClampToHalfRange(color), 1.0);
}

#include "UnityDeprecated.cginc"

#endif  // UNITY_STANDARD_BRDF_INCLUDED
