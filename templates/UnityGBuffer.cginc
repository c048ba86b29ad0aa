// UnityGBuffer.cginc: the deferred G-buffer layout (KilnGBuffer.cginc) with Unity's names.
#ifndef UNITY_GBUFFER_INCLUDED
#define UNITY_GBUFFER_INCLUDED

#include "KilnGBuffer.cginc"

struct UnityStandardData {
    float3 diffuseColor;
    float occlusion;
    float3 specularColor;
    float smoothness;
    float3 normalWorld;  // unit world-space normal
};

// Surface data -> RT0, RT1, RT2 (RT3, emission + ambient, is written by the pass itself;
// GBuffer_EncodeEmission clamps it for the 16-bit float target).
void UnityStandardDataToGbuffer(UnityStandardData data, out float4 outGBuffer0,
                                out float4 outGBuffer1, out float4 outGBuffer2) {
    outGBuffer0 = float4(saturate(data.diffuseColor), saturate(data.occlusion));
    outGBuffer1 = float4(saturate(data.specularColor), saturate(data.smoothness));
    outGBuffer2 = float4(GBuffer_EncodeNormal(data.normalWorld), 1.0);
}

// RT0, RT1, RT2 -> surface data (the lighting pass of the deferred path).
UnityStandardData UnityStandardDataFromGbuffer(float4 inGBuffer0, float4 inGBuffer1,
                                               float4 inGBuffer2) {
    UnityStandardData data;
    data.diffuseColor = inGBuffer0.rgb;
    data.occlusion = inGBuffer0.a;
    data.specularColor = inGBuffer1.rgb;
    data.smoothness = inGBuffer1.a;
    data.normalWorld = GBuffer_DecodeNormal(inGBuffer2.rgb);
    return data;
}

#endif  // UNITY_GBUFFER_INCLUDED
