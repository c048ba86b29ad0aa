// UnityPBSLighting.cginc: the physically based lighting entry points with Unity's names:
// UNITY_BRDF_PBS (chosen by the UNITY_PBS_USE_BRDF1/2/3 quality macro Kiln's compile environment
// defines), the Standard and StandardSpecular lighting functions over SurfaceOutputStandard*,
// their GI and deferred forms.
#ifndef UNITY_PBS_LIGHTING_INCLUDED
#define UNITY_PBS_LIGHTING_INCLUDED

#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityLightingCommon.cginc"
#include "UnityGBuffer.cginc"
#include "UnityGlobalIllumination.cginc"

// UNITY_BRDF_PBS(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
//                light, indirect) -> half4 linear colour (docs/shader-library.md).
#if !defined(UNITY_BRDF_PBS)
#if SHADER_TARGET < 30 || defined(UNITY_PBS_USE_BRDF3)
#define UNITY_BRDF_PBS BRDF3_Unity_PBS
#elif defined(UNITY_PBS_USE_BRDF2)
#define UNITY_BRDF_PBS BRDF2_Unity_PBS
#else
// UNITY_PBS_USE_BRDF1, and the choice when -U removed every quality macro.
#define UNITY_BRDF_PBS BRDF1_Unity_PBS
#endif
#endif

// Indirect light with ambient occlusion already applied by the GI function.
inline half3 BRDF_Unity_Indirect(half3 baseColor, half3 specColor, half oneMinusReflectivity,
                                 half smoothness, half3 normal, half3 viewDir, half occlusion,
                                 UnityGI gi) {
    return half3(0, 0, 0);  // Unity's BRDFs already include the indirect terms
}
#if !defined(UNITY_BRDF_GI)
#define UNITY_BRDF_GI BRDF_Unity_Indirect
#endif

#define UNITY_GLOSSY_ENV_FROM_SURFACE(x, s, data)                             \
    Unity_GlossyEnvironmentData g;                                            \
    g.roughness = SmoothnessToPerceptualRoughness(s.Smoothness);              \
    g.reflUVW = reflect(-data.worldViewDir, s.Normal);

#if defined(UNITY_PASS_DEFERRED) && UNITY_ENABLE_REFLECTION_BUFFERS
#define UNITY_GI(x, s, data) x = UnityGlobalIllumination(data, s.Occlusion, s.Normal);
#else
#define UNITY_GI(x, s, data)                 \
    UNITY_GLOSSY_ENV_FROM_SURFACE(g, s, data); \
    x = UnityGlobalIllumination(data, s.Occlusion, s.Normal, g);
#endif

// ---- metallic workflow ----
struct SurfaceOutputStandard {
    fixed3 Albedo;    // base colour
    float3 Normal;
    half3 Emission;
    half Metallic;    // 0 dielectric, 1 metal
    half Smoothness;  // perceptual smoothness, 1 - roughness
    half Occlusion;
    fixed Alpha;
};
inline half4 LightingStandard(SurfaceOutputStandard s, float3 viewDir, UnityGI gi) {
    s.Normal = SafeNormalize(s.Normal);
    half oneMinusReflectivity;
    half3 specColor;
    s.Albedo = DiffuseAndSpecularFromMetallic(s.Albedo, s.Metallic, specColor, oneMinusReflectivity);
    half outputAlpha;
    s.Albedo = PreMultiplyAlpha(s.Albedo, s.Alpha, oneMinusReflectivity, outputAlpha);
    half4 c = UNITY_BRDF_PBS(s.Albedo, specColor, oneMinusReflectivity, s.Smoothness, s.Normal,
                             viewDir, gi.light, gi.indirect);
    c.a = outputAlpha;
    return c;
}
inline half4 LightingStandard_Deferred(SurfaceOutputStandard s, float3 viewDir, UnityGI gi,
                                       out half4 outGBuffer0, out half4 outGBuffer1,
                                       out half4 outGBuffer2) {
    half oneMinusReflectivity;
    half3 specColor;
    s.Albedo = DiffuseAndSpecularFromMetallic(s.Albedo, s.Metallic, specColor, oneMinusReflectivity);
    half4 c = UNITY_BRDF_PBS(s.Albedo, specColor, oneMinusReflectivity, s.Smoothness, s.Normal,
                             viewDir, gi.light, gi.indirect);
    UnityStandardData data;
    data.diffuseColor = s.Albedo;
    data.occlusion = s.Occlusion;
    data.specularColor = specColor;
    data.smoothness = s.Smoothness;
    data.normalWorld = s.Normal;
    UnityStandardDataToGbuffer(data, outGBuffer0, outGBuffer1, outGBuffer2);
    return half4(c.rgb + s.Emission, 1);
}
inline void LightingStandard_GI(SurfaceOutputStandard s, UnityGIInput data, inout UnityGI gi) {
#if defined(UNITY_PASS_DEFERRED) && UNITY_ENABLE_REFLECTION_BUFFERS
    gi = UnityGlobalIllumination(data, s.Occlusion, s.Normal);
#else
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(
        s.Smoothness, data.worldViewDir, s.Normal,
        lerp(unity_ColorSpaceDielectricSpec.rgb, s.Albedo, s.Metallic));
    gi = UnityGlobalIllumination(data, s.Occlusion, s.Normal, g);
#endif
}

// ---- specular workflow ----
struct SurfaceOutputStandardSpecular {
    fixed3 Albedo;    // diffuse colour
    fixed3 Specular;  // specular colour
    float3 Normal;
    half3 Emission;
    half Smoothness;
    half Occlusion;
    fixed Alpha;
};
inline half4 LightingStandardSpecular(SurfaceOutputStandardSpecular s, float3 viewDir,
                                      UnityGI gi) {
    s.Normal = SafeNormalize(s.Normal);
    half oneMinusReflectivity;
    s.Albedo = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular,
                                                           oneMinusReflectivity);
    half outputAlpha;
    s.Albedo = PreMultiplyAlpha(s.Albedo, s.Alpha, oneMinusReflectivity, outputAlpha);
    half4 c = UNITY_BRDF_PBS(s.Albedo, s.Specular, oneMinusReflectivity, s.Smoothness, s.Normal,
                             viewDir, gi.light, gi.indirect);
    c.a = outputAlpha;
    return c;
}
inline half4 LightingStandardSpecular_Deferred(SurfaceOutputStandardSpecular s, float3 viewDir,
                                               UnityGI gi, out half4 outGBuffer0,
                                               out half4 outGBuffer1, out half4 outGBuffer2) {
    half oneMinusReflectivity;
    s.Albedo = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular,
                                                           oneMinusReflectivity);
    half4 c = UNITY_BRDF_PBS(s.Albedo, s.Specular, oneMinusReflectivity, s.Smoothness, s.Normal,
                             viewDir, gi.light, gi.indirect);
    UnityStandardData data;
    data.diffuseColor = s.Albedo;
    data.occlusion = s.Occlusion;
    data.specularColor = s.Specular;
    data.smoothness = s.Smoothness;
    data.normalWorld = s.Normal;
    UnityStandardDataToGbuffer(data, outGBuffer0, outGBuffer1, outGBuffer2);
    return half4(c.rgb + s.Emission, 1);
}
inline void LightingStandardSpecular_GI(SurfaceOutputStandardSpecular s, UnityGIInput data,
                                        inout UnityGI gi) {
#if defined(UNITY_PASS_DEFERRED) && UNITY_ENABLE_REFLECTION_BUFFERS
    gi = UnityGlobalIllumination(data, s.Occlusion, s.Normal);
#else
    Unity_GlossyEnvironmentData g =
        UnityGlossyEnvironmentSetup(s.Smoothness, data.worldViewDir, s.Normal, s.Specular);
    gi = UnityGlobalIllumination(data, s.Occlusion, s.Normal, g);
#endif
}

#endif  // UNITY_PBS_LIGHTING_INCLUDED
