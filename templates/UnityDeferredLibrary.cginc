// UnityDeferredLibrary.cginc: the deferred light pass helpers with Unity's names: the light
// volume's vertex program, the world position from the depth buffer, and the light's direction,
// attenuation and shadow at a pixel. Attenuation is Kiln's physical falloff (KilnAttenuation:
// inverse square with the range window, the glTF spot cone) from _LightPos / _LightDir and
// kiln_LightParams0, instead of Unity's attenuation textures (docs/unity-compat.md).
#ifndef UNITY_DEFERRED_LIBRARY_INCLUDED
#define UNITY_DEFERRED_LIBRARY_INCLUDED

#include "UnityCG.cginc"
#include "KilnAttenuation.cginc"

struct unity_v2f_deferred {
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;
    float3 ray : TEXCOORD1;  // view-space ray to the far plane
};

float _LightAsQuad;  // 1 for a full-screen quad (directional lights), 0 for a light volume

unity_v2f_deferred vert_deferred(float4 vertex : POSITION, float3 normal : NORMAL) {
    unity_v2f_deferred o;
    o.pos = UnityObjectToClipPos(vertex);
    o.uv = ComputeScreenPos(o.pos);
    // A light volume: the ray through its vertex; a full-screen quad carries the ray to a
    // near-plane corner in its normal.
    o.ray = lerp(UnityObjectToViewPos(vertex) * float3(-1, -1, 1), normal, _LightAsQuad);
    return o;
}

UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);
float4 _LightDir;    // xyz: the direction the directional light shines in
float4 _LightPos;    // xyz: position; w: 1 / range^2
float4 _LightColor;  // linear colour x intensity
float4 unity_LightmapFade;
sampler2D_float _LightTextureB0;
#if defined(POINT_COOKIE)
samplerCUBE_float _LightTexture0;
#else
sampler2D_float _LightTexture0;
#endif
#if defined(SHADOWS_SCREEN)
sampler2D _ShadowMapTexture;
#endif
#if defined(SHADOWS_SHADOWMASK)
sampler2D _CameraGBufferTexture4;
#endif

#include "UnityShadowLibrary.cginc"

// Baked occlusion from the G-buffer's shadow-mask target.
half UnityDeferredSampleShadowMask(float2 uv) {
#if defined(SHADOWS_SHADOWMASK)
    return saturate(dot(tex2D(_CameraGBufferTexture4, uv), unity_OcclusionMaskSelector));
#else
    return 1.0;
#endif
}

// The light's real-time shadow: screen-space for directional lights, the shadow map for spot
// lights (vec = world position), the depth cube for point lights (vec = position - light).
half UnityDeferredSampleRealtimeShadow(half fade, float3 vec, float2 uv) {
    half shadow = 1.0;
#if (defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)) && defined(SHADOWS_SCREEN)
    shadow = tex2D(_ShadowMapTexture, uv).r;
#endif
#if defined(SPOT) && defined(SHADOWS_DEPTH)
    shadow = UnitySampleShadowmap(mul(unity_WorldToShadow[0], float4(vec, 1)));
#endif
#if (defined(POINT) || defined(POINT_COOKIE)) && defined(SHADOWS_CUBE)
    shadow = UnitySampleShadowmap(vec);
#endif
    return shadow;
}

half UnityDeferredComputeShadow(float3 vec, float fadeDist, float2 uv) {
    half fade = UnityComputeShadowFade(fadeDist);
    return UnityMixRealtimeAndBakedShadows(UnityDeferredSampleRealtimeShadow(fade, vec, uv),
                                           UnityDeferredSampleShadowMask(uv), fade);
}

// World position, screen UV, unit direction to the light, attenuation (with shadow) and the
// shadow-fade distance of the pixel a light volume covers.
void UnityDeferredCalculateLightParams(unity_v2f_deferred i, out float3 outWorldPos,
                                       out float2 outUV, out half3 outLightDir,
                                       out float outAtten, out float outFadeDist) {
    // guard: a ray parallel to the far plane (z = 0) cannot reach it
    i.ray = i.ray * (_ProjectionParams.z / (abs(i.ray.z) < 1e-7 ? 1e-7 : i.ray.z));
    float2 uv = i.uv.xy / i.uv.w;
    float depth = Linear01Depth(SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, uv));
    float4 vpos = float4(i.ray * depth, 1);
    float3 wpos = mul(unity_CameraToWorld, vpos).xyz;
    float fadeDist = UnityComputeShadowFadeDistance(wpos, vpos.z);
    half3 lightDir = 0;
    float atten = 0;
#if defined(SPOT) || defined(POINT) || defined(POINT_COOKIE)
    float3 toLight = _LightPos.xyz - wpos;
    lightDir = SafeNormalize(toLight);
    atten = Attenuation_Distance(dot(toLight, toLight), kiln_LightParams0.x);
#if defined(SPOT)
    atten *= Attenuation_SpotCone(lightDir, kiln_SpotDirection0.xyz, kiln_LightParams0.y,
                                  kiln_LightParams0.z);
    atten *= UnityDeferredComputeShadow(wpos, fadeDist, uv);
#else
    atten *= UnityDeferredComputeShadow(-toLight, fadeDist, uv);
#endif
#elif defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)
    lightDir = -_LightDir.xyz;
    atten = UnityDeferredComputeShadow(wpos, fadeDist, uv);
#endif
    outWorldPos = wpos;
    outUV = uv;
    outLightDir = lightDir;
    outAtten = atten;
    outFadeDist = fadeDist;
}

#endif  // UNITY_DEFERRED_LIBRARY_INCLUDED
