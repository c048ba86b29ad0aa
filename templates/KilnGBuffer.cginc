// KilnGBuffer.cginc: packing surface data into the deferred G-buffer and back.
//
// Layout (Unity's built-in deferred layout, as taught in the lecture):
//   RT0 (R8G8B8A8_SRGB)    diffuse colour rgb, occlusion a
//   RT1 (R8G8B8A8_SRGB)    specular colour rgb, smoothness a
//   RT2 (A2B10G10R10_UNORM) world normal * 0.5 + 0.5 rgb, a unused (1)
//   RT3 (R16G16B16A16_SFLOAT) emission + ambient rgb (HDR), a 1
#ifndef KILN_GBUFFER_INCLUDED
#define KILN_GBUFFER_INCLUDED

#include "KilnCommon.cginc"

// Unit vector [-1, 1]^3 -> [0, 1]^3 (what a UNORM target stores).
float3 GBuffer_EncodeNormal(float3 n) {
    // guard: a zero or non-unit normal is normalized safely before it is stored
    return SafeNormalize(n) * 0.5 + 0.5;
}

// [0, 1]^3 -> unit vector; a cleared texel (0) decodes to a zero normal instead of NaN.
float3 GBuffer_DecodeNormal(float3 encoded) {
    // guard: quantization makes 2e - 1 non-unit, and a cleared G-buffer texel is zero
    return SafeNormalize(encoded * 2.0 - 1.0);
}

// Emission plus ambient, clamped so the 16-bit float RT3 stays finite.
float4 GBuffer_EncodeEmission(float3 emission) {
    return float4(ClampToHalfRange(max(emission, 0.0)), 1.0);
}

#endif  // KILN_GBUFFER_INCLUDED
