// UnityGBuffer.cginc: the deferred G-buffer layout (KilnGBuffer.cginc) with Unity's names.
#ifndef UNITY_GBUFFER_INCLUDED
#define UNITY_GBUFFER_INCLUDED

#include "KilnGBuffer.cginc"
#include "UnityShaderVariables.cginc"

struct UnityStandardData {
    half3 diffuseColor;
    half occlusion;
    half3 specularColor;
    half smoothness;
    float3 normalWorld;  // unit world-space normal
};

// Surface data -> RT0, RT1, RT2 (RT3, emission + ambient, is written by the pass itself;
// GBuffer_EncodeEmission clamps it for the 16-bit float target).
void UnityStandardDataToGbuffer(UnityStandardData data, out half4 outGBuffer0,
                                out half4 outGBuffer1, out half4 outGBuffer2) {
    outGBuffer0 = half4(saturate(data.diffuseColor), saturate(data.occlusion));
    outGBuffer1 = half4(saturate(data.specularColor), saturate(data.smoothness));
#if defined(_GBUFFER_NORMALS_OCT)
    outGBuffer2 = half4(GBuffer_EncodeNormalOct(data.normalWorld), 0.0, 1.0);
#else
    outGBuffer2 = half4(GBuffer_EncodeNormal(data.normalWorld), 1.0);
#endif
}

// RT0, RT1, RT2 -> surface data (the lighting pass of the deferred path).
UnityStandardData UnityStandardDataFromGbuffer(half4 inGBuffer0, half4 inGBuffer1,
                                               half4 inGBuffer2) {
    UnityStandardData data;
    data.diffuseColor = inGBuffer0.rgb;
    data.occlusion = inGBuffer0.a;
    data.specularColor = inGBuffer1.rgb;
    data.smoothness = inGBuffer1.a;
#if defined(_GBUFFER_NORMALS_OCT)
    data.normalWorld = GBuffer_DecodeNormalOct(inGBuffer2.rg);
#else
    data.normalWorld = GBuffer_DecodeNormal(inGBuffer2.rgb);
#endif
    return data;
}

// World position of a G-buffer texel from its screen UV (top-left origin) and device depth
// (0..1): clip space (y up, as the renderer's flipped viewport has it) back through the inverse
// projection and the inverse view matrix.
float3 GBuffer_WorldPosition(float2 uv, float depth) {
    float4 clip = float4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0);
    float4 view = mul(unity_CameraInvProjection, clip);
    // guard: w = 0 only for a point at infinity, which the depth buffer's clear value is not
    view.xyz /= abs(view.w) < 1e-30 ? 1e-30 : view.w;
    return mul(unity_MatrixInvV, float4(view.xyz, 1.0)).xyz;
}

// Decals and other blended G-buffer writes: premultiply by the blend weight.
void UnityStandardDataApplyWeightToGbuffer(inout half4 inOutGBuffer0, inout half4 inOutGBuffer1,
                                           inout half4 inOutGBuffer2, half alpha) {
    inOutGBuffer0.rgb *= alpha;
    inOutGBuffer1 *= alpha;
    inOutGBuffer2 *= alpha;
}

#endif  // UNITY_GBUFFER_INCLUDED
