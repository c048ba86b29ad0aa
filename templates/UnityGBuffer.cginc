// UnityGBuffer.cginc: the deferred G-buffer layout (KilnGBuffer.cginc) with Unity's names.
#ifndef UNITY_GBUFFER_INCLUDED
#define UNITY_GBUFFER_INCLUDED

#include "KilnGBuffer.cginc"

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
    outGBuffer2 = half4(GBuffer_EncodeNormal(data.normalWorld), 1.0);
}

// RT0, RT1, RT2 -> surface data (the lighting pass of the deferred path).
UnityStandardData UnityStandardDataFromGbuffer(half4 inGBuffer0, half4 inGBuffer1,
                                               half4 inGBuffer2) {
    UnityStandardData data;
    data.diffuseColor = inGBuffer0.rgb;
    data.occlusion = inGBuffer0.a;
    data.specularColor = inGBuffer1.rgb;
    data.smoothness = inGBuffer1.a;
    data.normalWorld = GBuffer_DecodeNormal(inGBuffer2.rgb);
    return data;
}

// Decals and other blended G-buffer writes: premultiply by the blend weight.
void UnityStandardDataApplyWeightToGbuffer(inout half4 inOutGBuffer0, inout half4 inOutGBuffer1,
                                           inout half4 inOutGBuffer2, half alpha) {
    inOutGBuffer0.rgb *= alpha;
    inOutGBuffer1 *= alpha;
    inOutGBuffer2 *= alpha;
}

#endif  // UNITY_GBUFFER_INCLUDED
