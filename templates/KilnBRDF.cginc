// KilnBRDF.cginc: the microfacet specular BRDF (GGX / Smith height-correlated / Schlick) and its
// parameterization, after Filament's "Physically Based Rendering in Filament" (section 4.4-4.6).
//
// Conventions: a = roughness = perceptualRoughness^2 (Burley 2012), perceptualRoughness =
// 1 - smoothness (Unity). Light colours follow Unity's convention: C = irradiance / pi (the
// runtime turns glTF lux and candela into C, docs/runtime.md "Light units"), so the rendering
// equation term f * E * (n . l) is f * pi * C * (n . l); BRDF_Specular below includes that pi.
#ifndef KILN_BRDF_INCLUDED
#define KILN_BRDF_INCLUDED

#include "KilnCommon.cginc"

// Smallest perceptual roughness: GGX at a = 0 is a Dirac delta (D = 0/0 at n . h = 1). 0.045 is
// Filament's fp32 limit (MIN_PERCEPTUAL_ROUGHNESS); D stays below 1e5.
#define KILN_MIN_PERCEPTUAL_ROUGHNESS 0.045

float SmoothnessToPerceptualRoughness(float smoothness) {
    return 1.0 - saturate(smoothness);
}

// a = perceptualRoughness^2 (Burley 2012, section 5.4), clamped away from the delta.
float PerceptualRoughnessToRoughness(float perceptualRoughness) {
    // guard: roughness 0 makes D_GGX 0/0 at n . h = 1 (clamp perceptual roughness)
    float p = clamp(perceptualRoughness, KILN_MIN_PERCEPTUAL_ROUGHNESS, 1.0);
    return p * p;
}

// GGX / Trowbridge-Reitz normal distribution (Walter et al. 2007, eq. 33):
// D(h) = chi+(n . h) a^2 / (pi * ((n . h)^2 (a^2 - 1) + 1)^2).
float D_GGX(float NoH, float a) {
    float a2 = a * a;
    // (n . h)^2 a^2 + (1 - n . h)(1 + n . h): 1 - n . h is exact near n . h = 1, where the
    // shorter (n . h a^2 - n . h) n . h + 1 cancels to a few digits at the smallest roughness
    // (0.6% error in D's peak in fp32; kiln stability)
    float d = NoH * NoH * a2 + (1.0 - NoH) * (1.0 + NoH);
    // guard: d >= a^2 > 0 for n . h in [0, 1] and a > 0; the max only absorbs rounding
    float D = a2 / (KILN_PI * max(d * d, 1e-20));
    // chi+: no microfacet faces away from the normal. Callers pass saturate(n . h), which is 0
    // for a half vector below the surface (a back-facing view), where D must be 0, not a^2 / pi
    return NoH > 0.0 ? D : 0.0;
}

// Height-correlated Smith visibility V = G / (4 (n . l)(n . v)) for GGX (Heitz 2014, eq. 99;
// Filament eq. 15): V = 0.5 / (n.l sqrt((n.v)^2 (1 - a^2) + a^2) + n.v sqrt((n.l)^2 (1 - a^2) + a^2)).
float V_SmithGGXCorrelated(float NoV, float NoL, float a) {
    float a2 = a * a;
    float lambdaV = NoL * sqrt((NoV * NoV) * (1.0 - a2) + a2);
    float lambdaL = NoV * sqrt((NoL * NoL) * (1.0 - a2) + a2);
    // guard: at n . v -> 0 and n . l -> 0 the denominator vanishes (V -> Inf); it is multiplied
    // by n . l afterwards, so bounding it keeps the product finite. The bound only acts when
    // both cosines are below ~1e-12 / a: with the callers' n . v >= 1e-5 the sum is at least
    // 1e-5 a >= 2e-8 and V is exact (a 1e-7 bound cut V by 5x at grazing n . l; kiln stability)
    return 0.5 / max(lambdaV + lambdaL, 1e-12);
}

// Schlick's Fresnel approximation (Schlick 1994, eq. 24): F = F0 + (1 - F0)(1 - v . h)^5.
float3 F_Schlick(float3 f0, float VoH) {
    // guard: saturate keeps the base of the fifth power in [0, 1]
    return f0 + (1.0 - f0) * Pow5(1.0 - saturate(VoH));
}

// Schlick towards a grazing reflectance f90 instead of 1 (used for the indirect specular).
float3 F_SchlickLerp(float3 f0, float3 f90, float VoH) {
    return lerp(f0, f90, Pow5(1.0 - saturate(VoH)));
}

// Lambertian diffuse BRDF 1/pi, times the pi of the light convention (C = E / pi): 1.
float Fd_Lambert() {
    return 1.0;
}

// ---- alternatives, chosen per build by the dispatch below ----

// Normalized Blinn-Phong distribution with the exponent matched to GGX's roughness,
// n = 2 / a^2 - 2 (Walter et al. 2007, section 5.2): D = (n + 2) / (2 pi) (n . h)^n.
float D_BlinnPhong(float NoH, float a) {
    // guard: a >= 0.045^2 from PerceptualRoughnessToRoughness keeps n finite; SafePow takes
    // n . h = 0 and n = 0
    float n = max(2.0 / max(a * a, 1e-12) - 2.0, 0.0);
    float D = (n + 2.0) * (0.5 * KILN_INV_PI) * SafePow(saturate(NoH), n);
    return NoH > 0.0 ? D : 0.0;  // chi+, as D_GGX (n = 0 would light n . h = 0 with 1 / pi)
}

// Hammon's approximation of the height-correlated Smith visibility (GDC 2017, "PBR Diffuse
// Lighting for GGX+Smith Microsurfaces", slide 82; Filament eq. 16):
// V = 0.5 / lerp(2 (n.l)(n.v), n.l + n.v, a).
float V_SmithGGXCorrelatedFast(float NoV, float NoL, float a) {
    // guard: the denominator is 0 only when n . l = n . v = 0; bounded as the exact form is
    return 0.5 / max(lerp(2.0 * NoL * NoV, NoL + NoV, a), 1e-12);
}

// The exact Fresnel reflectance of an unpolarized dielectric (Cook and Torrance 1982, eq. in
// section 4.1; Walter et al. 2007, eq. 22), with the index of refraction from f0:
// eta = (1 + sqrt(f0)) / (1 - sqrt(f0)), g = sqrt(eta^2 - 1 + c^2),
// F = (g - c)^2 / (2 (g + c)^2) (1 + ((c (g + c) - 1) / (c (g - c) + 1))^2), c = v . h.
float F_ExactChannel(float f0, float c) {
    // guard: f0 -> 1 (metals) makes eta infinite; sqrt(f0) <= 0.9999 keeps it finite (F ~ 1)
    float s = sqrt(clamp(f0, 0.0, 0.9998));
    float eta = (1.0 + s) / (1.0 - s);
    c = saturate(c);
    float g = sqrt(eta * eta - 1.0 + c * c);  // eta >= 1: the root's argument is >= c^2
    float a = (g - c) / (g + c);
    float b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);  // c (g - c) + 1 >= 1 > 0
    return 0.5 * a * a * (1.0 + b * b);
}
float3 F_Exact(float3 f0, float VoH) {
    return float3(F_ExactChannel(f0.r, VoH), F_ExactChannel(f0.g, VoH),
                  F_ExactChannel(f0.b, VoH));
}

// ---- the BRDF choices (Filament surface_brdf.fs's distribution / visibility / fresnel) ----
// One build uses one of each, chosen by defining a macro (kiln compile -D, or before including):
//   distribution: GGX (default) or KILN_BRDF_D_BLINN_PHONG
//   visibility:   height-correlated Smith (default) or KILN_BRDF_V_SMITH_FAST (Hammon)
//   fresnel:      Schlick (default) or KILN_BRDF_F_EXACT
// kiln report compares packs built with each (docs/accuracy.md, "BRDF choices").
float Distribution(float NoH, float a) {
#if defined(KILN_BRDF_D_BLINN_PHONG)
    return D_BlinnPhong(NoH, a);
#else
    return D_GGX(NoH, a);
#endif
}
float Visibility(float NoV, float NoL, float a) {
#if defined(KILN_BRDF_V_SMITH_FAST)
    return V_SmithGGXCorrelatedFast(NoV, NoL, a);
#else
    return V_SmithGGXCorrelated(NoV, NoL, a);
#endif
}
float3 Fresnel(float3 f0, float VoH) {
#if defined(KILN_BRDF_F_EXACT)
    return F_Exact(f0, VoH);
#else
    return F_Schlick(f0, VoH);
#endif
}

// The specular term of the rendering equation for one light, with the convention's pi:
// pi * D * V * F * (n . l).
float3 BRDF_Specular(float3 f0, float NoV, float NoL, float NoH, float LoH, float a) {
    float D = Distribution(NoH, a);
    float V = Visibility(NoV, NoL, a);
    float3 F = Fresnel(f0, LoH);
    return (KILN_PI * D * V * NoL) * F;
}

// Reflectance at normal incidence of dielectrics: 4% (glTF 2.0 specification, Appendix B,
// "dielectric_brdf" with ior 1.5: ((1.5 - 1) / (1.5 + 1))^2 = 0.04).
#define KILN_DIELECTRIC_F0 0.04

// Metallic-roughness to specular parameters (glTF 2.0, Appendix B.3.5): f0 = lerp(0.04, base,
// metallic); the diffuse colour keeps the share of light not reflected by the dielectric layer,
// (1 - 0.04)(1 - metallic), as in Unity's DiffuseAndSpecularFromMetallic.
float OneMinusReflectivity_Metallic(float metallic) {
    return (1.0 - KILN_DIELECTRIC_F0) * (1.0 - saturate(metallic));
}
float3 SpecularColor_Metallic(float3 baseColor, float metallic) {
    return lerp(float3(KILN_DIELECTRIC_F0, KILN_DIELECTRIC_F0, KILN_DIELECTRIC_F0), baseColor,
                saturate(metallic));
}

#endif  // KILN_BRDF_INCLUDED
