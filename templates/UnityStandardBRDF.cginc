// UnityStandardBRDF.cginc: Unity's BRDF entry points over KilnBRDF.cginc.
#ifndef UNITY_STANDARD_BRDF_INCLUDED
#define UNITY_STANDARD_BRDF_INCLUDED

#include "UnityCG.cginc"
#include "UnityLightingCommon.cginc"
#include "KilnBRDF.cginc"

// max(0, a . b): the clamped cosine of Lambert's law.
float DotClamped(float3 a, float3 b) {
    return saturate(dot(a, b));
}

float3 Unity_SafeNormalize(float3 v) {
    return SafeNormalize(v);
}

// Physically based shading for one direct light plus indirect light (what UNITY_BRDF_PBS names):
// Lambert diffuse, GGX / Smith height-correlated / Schlick specular (KilnBRDF.cginc), and
// Unity's indirect-specular terms (surface reduction 1 / (a^2 + 1) and Fresnel towards a grazing
// reflectance of smoothness + reflectivity). Colours are linear; the result is clamped to the
// binary16 range so a 16-bit float target never receives Inf.
float4 BRDF1_Unity_PBS(float3 diffColor, float3 specColor, float oneMinusReflectivity,
                       float smoothness, float3 normal, float3 viewDir, UnityLight light,
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
    float surfaceReduction = 1.0 / (a * a + 1.0);
    float grazing = saturate(smoothness + (1.0 - oneMinusReflectivity));
    float3 indirectSpecular =
        surfaceReduction * gi.specular * F_SchlickLerp(specColor, grazing, NoV);
    return float4(ClampToHalfRange(diffuse + specular + indirectSpecular), 1.0);
}

#endif  // UNITY_STANDARD_BRDF_INCLUDED
