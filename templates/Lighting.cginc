// Lighting.cginc: the classic lighting models (Lambert, Blinn-Phong) over a SurfaceOutput, with
// Unity's names and signatures, including their global-illumination and deferred forms. Unity's
// Lighting.cginc pulls in the whole GI stack (UnityGlobalIllumination -> UnityImageBasedLighting
// -> UnityStandardBRDF -> UnityDeprecated), so DotClamped and friends are available; so here.
#ifndef LIGHTING_INCLUDED
#define LIGHTING_INCLUDED

#include "UnityLightingCommon.cginc"
#include "UnityGBuffer.cginc"
#include "UnityGlobalIllumination.cginc"
#include "KilnClassicLighting.cginc"

struct SurfaceOutput {
    fixed3 Albedo;    // diffuse reflectance, linear
    fixed3 Normal;    // world-space unit normal
    fixed3 Emission;  // emitted colour, linear
    half Specular;    // Blinn-Phong exponent / 128, as in Unity
    fixed Gloss;      // specular intensity
    fixed Alpha;
};

#ifndef USING_DIRECTIONAL_LIGHT
#if defined(DIRECTIONAL_COOKIE) || defined(DIRECTIONAL)
#define USING_DIRECTIONAL_LIGHT
#endif
#endif

#if defined(UNITY_SHOULD_SAMPLE_SH) || defined(LIGHTMAP_ON) || defined(DYNAMICLIGHTMAP_ON)
#define UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
#endif

// Lambert (lecture "Diffuse reflection") for one light.
inline fixed4 UnityLambertLight(SurfaceOutput s, UnityLight light) {
    return fixed4(Lambert_Diffuse(s.Albedo, light.color, s.Normal, light.dir), s.Alpha);
}
// Lambert plus the indirect diffuse light.
inline fixed4 LightingLambert(SurfaceOutput s, UnityGI gi) {
    fixed4 c = UnityLambertLight(s, gi.light);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    c.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return c;
}
inline half4 LightingLambert_Deferred(SurfaceOutput s, UnityGI gi, out half4 outGBuffer0,
                                      out half4 outGBuffer1, out half4 outGBuffer2) {
    UnityStandardData data;
    data.diffuseColor = s.Albedo;
    data.occlusion = 1;
    data.specularColor = 0;
    data.smoothness = 0;
    data.normalWorld = s.Normal;
    UnityStandardDataToGbuffer(data, outGBuffer0, outGBuffer1, outGBuffer2);
    half4 emission = half4(s.Emission, 1);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    emission.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return emission;
}
inline void LightingLambert_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi) {
    gi = UnityGlobalIllumination(data, 1.0, s.Normal);
}

// Blinn-Phong (lecture "Specular reflection") for one light, with the global _SpecColor as in
// Unity.
inline fixed4 UnityBlinnPhongLight(SurfaceOutput s, half3 viewDir, UnityLight light,
                                   half3 specColor) {
    float3 h = BlinnPhong_HalfVector(SafeNormalize(light.dir), SafeNormalize(viewDir));
    float3 diffuse = Lambert_Diffuse(s.Albedo, light.color, s.Normal, light.dir);
    float3 specular =
        BlinnPhong_Specular(specColor * s.Gloss, light.color, s.Normal, h, s.Specular * 128.0);
    return fixed4(diffuse + specular, s.Alpha);
}
inline fixed4 UnityBlinnPhongLight(SurfaceOutput s, half3 viewDir, UnityLight light) {
    return UnityBlinnPhongLight(s, viewDir, light, _SpecColor.rgb);
}
inline fixed4 LightingBlinnPhong(SurfaceOutput s, half3 viewDir, UnityGI gi) {
    fixed4 c = UnityBlinnPhongLight(s, viewDir, gi.light);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    c.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return c;
}
inline half4 LightingBlinnPhong_Deferred(SurfaceOutput s, half3 viewDir, UnityGI gi,
                                         out half4 outGBuffer0, out half4 outGBuffer1,
                                         out half4 outGBuffer2) {
    UnityStandardData data;
    data.diffuseColor = s.Albedo;
    data.occlusion = 1;
    // Blinn-Phong's gloss as a specular colour and its exponent as smoothness (Unity's mapping)
    data.specularColor = _SpecColor.rgb * s.Gloss;
    data.smoothness = s.Specular;
    data.normalWorld = s.Normal;
    UnityStandardDataToGbuffer(data, outGBuffer0, outGBuffer1, outGBuffer2);
    half4 emission = half4(s.Emission, 1);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    emission.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return emission;
}
inline void LightingBlinnPhong_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi) {
    gi = UnityGlobalIllumination(data, 1.0, s.Normal);
}

#if UNITY_VERSION < 201910
// The legacy deferred (light pre-pass) path's forms, which Unity 2018 and earlier ship
// (hlsl/unity_versions.h): `light` is the accumulated light buffer, rgb the diffuse light and
// a the specular term (the lecture's sum over lights, done by the light pass).
inline fixed4 LightingLambert_PrePass(SurfaceOutput s, half4 light) {
    return fixed4(s.Albedo * light.rgb, s.Alpha);
}
inline fixed4 LightingBlinnPhong_PrePass(SurfaceOutput s, half4 light) {
    const fixed specular = light.a * s.Gloss;
    return fixed4(s.Albedo * light.rgb + light.rgb * _SpecColor.rgb * specular, s.Alpha);
}
#endif

// Legacy directional lightmaps (Unity 4's three-basis form).
#define UNITY_DIRBASIS \
    const half3x3 unity_DirBasis = half3x3(half3(0.81649658, 0.0, 0.57735027), \
                                           half3(-0.40824830, 0.70710678, 0.57735027), \
                                           half3(-0.40824830, -0.70710678, 0.57735027));
half3 DirLightmapDiffuse(in half3x3 dirBasis, fixed4 color, fixed4 scale, half3 normal,
                         bool surfFuncWritesNormal, out half3 scalePerBasisVector) {
    half3 lm = DecodeLightmap(color);
    scalePerBasisVector = DecodeLightmap(scale);
    if (surfFuncWritesNormal) {
        half3 normalInRnmBasis = saturate(mul(dirBasis, normal));
        lm *= dot(normalInRnmBasis, scalePerBasisVector);
    }
    return lm;
}

// Tessellation factors of the surface-shader tessellation stage (a struct name shaders use).
struct UnityTessellationFactors {
    float edge[3] : SV_TessFactor;
    float inside : SV_InsideTessFactor;
};

#endif  // LIGHTING_INCLUDED
