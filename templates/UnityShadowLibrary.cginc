// UnityShadowLibrary.cginc: shadow-map sampling and the real-time / baked shadow blend, with
// Unity's names. Kiln's runtime renders the maps from the objects' ShadowCaster passes
// (docs/runtime.md, "Shadows"): _ShadowMapTexture is a depth map sampled with a comparison
// sampler (spot lights, SHADOWS_DEPTH) or a depth cube (point lights, SHADOWS_CUBE, stored as
// depth: SHADOWS_CUBE_IN_DEPTH_TEX); the comparison sampler filters bilinearly (2x2 PCF) and
// SHADOWS_SOFT adds a wider filter. Baked occlusion (shadow masks) reads unity_ShadowMask, a
// default white texture.
#ifndef UNITY_BUILTIN_SHADOW_LIBRARY_INCLUDED
#define UNITY_BUILTIN_SHADOW_LIBRARY_INCLUDED

#include "UnityCG.cginc"

#define unityShadowCoord float
#define unityShadowCoord2 float2
#define unityShadowCoord3 float3
#define unityShadowCoord4 float4
#define unityShadowCoord4x4 float4x4

// Real-time shadows of the main light are blended with baked occlusion inside the GI function
// when the lightmap or shadow mask already carries them (Unity's convention).
#if defined(SHADOWS_SCREEN) && defined(LIGHTMAP_ON)
#define HANDLE_SHADOWS_BLENDING_IN_GI 1
#endif

// ---- spot light shadows: a depth map compared at (u, v, depth) ----
#if defined(SHADOWS_DEPTH) && defined(SPOT)
#if !defined(SHADOWMAPSAMPLER_DEFINED)
UNITY_DECLARE_SHADOWMAP(_ShadowMapTexture);
#define SHADOWMAPSAMPLER_DEFINED
#endif
float4 _ShadowMapTexture_TexelSize;
#define SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED
#endif

// Percentage-closer filtering over an N x N texel footprint (uniform weights of bilinear
// comparison taps). Without a spot shadow map (no SHADOWS_DEPTH variant) there is nothing to
// filter: 1.
#if defined(SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED)
half UnitySampleShadowmap_PCFNxN(float4 coord, int n) {
    // guard: w = 0 only for a receiver in the light's plane, outside its frustum
    float3 c = coord.xyz / max(abs(coord.w), 1e-7);
    half sum = 0.0;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            float2 offset = (float2(x, y) - (n - 1) * 0.5) * _ShadowMapTexture_TexelSize.xy;
            sum += UNITY_SAMPLE_SHADOW(_ShadowMapTexture, float3(c.xy + offset, c.z));
        }
    }
    return lerp(_LightShadowData.r, 1.0, sum / (n * n));
}
#else
half UnitySampleShadowmap_PCFNxN(float4 coord, int n) {
    return 1.0;
}
#endif

#if defined(SHADOWS_DEPTH) && defined(SPOT)
// 1 where lit, _LightShadowData.r (the shadow strength's complement) where fully shadowed;
// SHADOWS_SOFT: a 3 x 3 texel filter (Unity's PCF3x3).
inline fixed UnitySampleShadowmap(float4 shadowCoord) {
#if defined(SHADOWS_SOFT)
    return UnitySampleShadowmap_PCFNxN(shadowCoord, 3);
#else
    // guard: w = 0 only for a receiver in the light's plane, outside its frustum
    float3 coord = shadowCoord.xyz / max(abs(shadowCoord.w), 1e-7);
    half shadow = UNITY_SAMPLE_SHADOW(_ShadowMapTexture, coord);
    return lerp(_LightShadowData.r, 1.0, shadow);
#endif
}
#endif

// ---- point light shadows: a depth cube compared at the receiver's projected depth ----
#if defined(SHADOWS_CUBE)
#if !defined(SHADOWMAPSAMPLER_DEFINED)
UNITY_DECLARE_TEXCUBE_SHADOWMAP(_ShadowMapTexture);
#define SHADOWMAPSAMPLER_DEFINED
#endif
float4 _ShadowMapTexture_TexelSize;  // of a face
// The depth the cube face that `dir` looks through stores for the point `vec` (Unity's
// SHADOWS_CUBE_IN_DEPTH_TEX): the point's distance along that face's axis, less the bias
// (_LightProjectionParams.z, world units) and `extraBias`, projected as z = -x + y / d
// (x = -f/(f-n), y = -f n/(f-n): depth 0 at the near plane, 1 at far).
float UnityCubeShadowDepthAlong(float3 vec, float3 dir, float extraBias) {
    float3 a = abs(dir);
    float3 v = abs(vec);
    float axisDistance = a.x >= a.y && a.x >= a.z ? v.x : (a.y >= a.z ? v.y : v.z);
    // guard: a receiver at the light's position
    axisDistance = max(0.00001, axisDistance - _LightProjectionParams.z - extraBias);
    axisDistance *= _LightProjectionParams.w;
    return -_LightProjectionParams.x + _LightProjectionParams.y / axisDistance;
}
float UnityCubeShadowDepth(float3 vec) {
    return UnityCubeShadowDepthAlong(vec, vec, 0.0);
}
// vec: surface position minus the light's (_LightPositionRange.xyz). SHADOWS_SOFT: four taps
// on the diagonals, as Unity's, about a face texel and a half from the centre (a face spans 2 at
// distance 1: a texel is 2 / size there); each compares the point's depth on the face its tap
// reads, so taps across a face edge agree with their neighbours, biased further by twice the
// taps' offset: a tap reads the receiver up to that far away, nearer the light on a slope.
inline half UnitySampleShadowmap(float3 vec) {
#if defined(SHADOWS_SOFT)
    float z = length(vec) * 2.0 * _ShadowMapTexture_TexelSize.x;
    float3 o[4] = {float3(z, z, z), float3(-z, -z, z), float3(-z, z, -z), float3(z, -z, -z)};
    half shadow = 0.0;
    for (int k = 0; k < 4; ++k) {
        float3 dir = vec + o[k];
        float depth = UnityCubeShadowDepthAlong(vec, dir, 3.5 * z);  // 2 |o[k]|
        shadow += 0.25 * UNITY_SAMPLE_TEXCUBE_SHADOW(_ShadowMapTexture, float4(dir, depth));
    }
#else
    half shadow =
        UNITY_SAMPLE_TEXCUBE_SHADOW(_ShadowMapTexture, float4(vec, UnityCubeShadowDepth(vec)));
#endif
    return lerp(_LightShadowData.r, 1.0, shadow);
}
#endif

half UnitySampleShadowmap_PCF3x3(float4 coord, float3 receiverPlaneDepthBias) {
    return UnitySampleShadowmap_PCFNxN(coord, 3);
}
half UnitySampleShadowmap_PCF5x5(float4 coord, float3 receiverPlaneDepthBias) {
    return UnitySampleShadowmap_PCFNxN(coord, 5);
}
half UnitySampleShadowmap_PCF7x7(float4 coord, float3 receiverPlaneDepthBias) {
    return UnitySampleShadowmap_PCFNxN(coord, 7);
}
#define UnitySampleShadowmap_PCF3x3Tent UnitySampleShadowmap_PCF3x3
#define UnitySampleShadowmap_PCF3x3Gaussian UnitySampleShadowmap_PCF3x3
#define UnitySampleShadowmap_PCF3x3NoHardwareSupport UnitySampleShadowmap_PCF3x3
#define UnitySampleShadowmap_PCF5x5Tent UnitySampleShadowmap_PCF5x5
#define UnitySampleShadowmap_PCF5x5Gaussian UnitySampleShadowmap_PCF5x5
#define UnitySampleShadowmap_PCF7x7Tent UnitySampleShadowmap_PCF7x7

// Receiver-plane depth bias (Isidoro 2006): the depth slope of the receiver in shadow-map UV
// space, from screen-space derivatives. Kiln's PCF does not use it; returned for compatibility.
float2 UnityGetReceiverPlaneDepthBias(float3 shadowCoord, float biasMultiply) {
    float3 dx = ddx(shadowCoord);
    float3 dy = ddy(shadowCoord);
    float det = dx.x * dy.y - dx.y * dy.x;
    // guard: a receiver seen edge-on has a singular UV Jacobian
    if (abs(det) < 1e-12)
        return float2(0.0, 0.0);
    float2 bias = float2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
    return bias * biasMultiply;
}
float3 UnityCombineShadowcoordComponents(float2 baseUV, float2 deltaUV, float depth,
                                         float3 receiverPlaneDepthBias) {
    float3 uv = float3(baseUV + deltaUV, depth + receiverPlaneDepthBias.z);
    uv.z += dot(deltaUV, receiverPlaneDepthBias.xy);
    return uv;
}

// ---- fading real-time shadows out with distance, into baked occlusion ----
// Distance used for the fade: along the view axis, or from the fade sphere's centre (w = 1).
float UnityComputeShadowFadeDistance(float3 wpos, float z) {
    float sphereDist = distance(wpos, unity_ShadowFadeCenterAndType.xyz);
    return lerp(z, sphereDist, unity_ShadowFadeCenterAndType.w);
}
// 0 inside the shadow distance, rising to 1 at its end (_LightShadowData.zw = scale, offset).
half UnityComputeShadowFade(float fadeDist) {
    return saturate(fadeDist * _LightShadowData.z + _LightShadowData.w);
}

// Baked occlusion of the light from the shadow mask (or light probes without a lightmap).
fixed4 UnityGetRawBakedOcclusions(float2 lightmapUV, float3 worldPos) {
#if defined(SHADOWS_SHADOWMASK)
#if defined(LIGHTMAP_ON)
    return UNITY_SAMPLE_TEX2D(unity_ShadowMask, lightmapUV.xy);
#else
    return unity_ProbesOcclusion;
#endif
#else
    return fixed4(1, 1, 1, 1);
#endif
}
fixed UnitySampleBakedOcclusion(float2 lightmapUV, float3 worldPos) {
#if defined(SHADOWS_SHADOWMASK)
    return saturate(dot(UnityGetRawBakedOcclusions(lightmapUV, worldPos),
                        unity_OcclusionMaskSelector));
#else
    return 1.0;
#endif
}
#if UNITY_LIGHT_PROBE_PROXY_VOLUME
// Occlusion from a light probe proxy volume's fourth slice.
half4 LPPV_SampleProbeOcclusion(float3 worldPos) {
    const float transformToLocal = unity_ProbeVolumeParams.y;
    const float texelSizeX = unity_ProbeVolumeParams.z;
    float3 position = (transformToLocal == 1.0f)
                          ? mul(unity_ProbeVolumeWorldToObject, float4(worldPos, 1.0)).xyz
                          : worldPos;
    float3 coord = (position - unity_ProbeVolumeMin.xyz) * unity_ProbeVolumeSizeInv.xyz;
    coord.x = clamp(coord.x * 0.25f, 0.5f * texelSizeX, 0.25f - 0.5f * texelSizeX) + 0.75f;
    return UNITY_SAMPLE_TEX3D_SAMPLER(unity_ProbeVolumeSH, unity_ProbeVolumeSH, coord);
}
#endif
// Real-time and baked shadows combined: the darker of the two, the real-time one faded out.
half UnityMixRealtimeAndBakedShadows(half realtimeShadowAttenuation, half bakedShadowAttenuation,
                                     half fade) {
#if defined(LIGHTMAP_SHADOW_MIXING) || defined(SHADOWS_SHADOWMASK)
    return min(lerp(realtimeShadowAttenuation, 1.0, fade), bakedShadowAttenuation);
#else
    return lerp(realtimeShadowAttenuation, 1.0, fade);
#endif
}

#endif  // UNITY_BUILTIN_SHADOW_LIBRARY_INCLUDED
