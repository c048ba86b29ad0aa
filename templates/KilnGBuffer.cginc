// KilnGBuffer.cginc: packing surface data into the deferred G-buffer and back.
//
// Layout (Unity's built-in deferred layout, as taught in the lecture):
//   RT0 (R8G8B8A8_SRGB)    diffuse colour rgb, occlusion a
//   RT1 (R8G8B8A8_SRGB)    specular colour rgb, smoothness a
//   RT2 (A2B10G10R10_UNORM) world normal * 0.5 + 0.5 rgb, a unused (1); with the keyword
//                          _GBUFFER_NORMALS_OCT (URP's name) the octahedral encoding in rg
//                          (the renderer's G-buffer settings choose the format and encoding)
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

// Octahedral encoding of a unit vector (Cigolle et al. 2014, "A Survey of Efficient
// Representations for Independent Unit Vectors", JCGT 3(2), section 3.3): project onto the
// octahedron |x| + |y| + |z| = 1, fold the lower half over the diagonals, store in [0, 1]^2.
float2 GBuffer_OctWrap(float2 v) {
    return (1.0 - abs(v.yx)) * float2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

float2 GBuffer_EncodeNormalOct(float3 n) {
    // guard: SafeNormalize maps a zero normal to zero, whose L1 norm would divide by zero
    n = SafeNormalize(n);
    n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-7);
    float2 p = n.z >= 0.0 ? n.xy : GBuffer_OctWrap(n.xy);
    return p * 0.5 + 0.5;
}

float3 GBuffer_DecodeNormalOct(float2 encoded) {
    float2 f = encoded * 2.0 - 1.0;
    float3 n = float3(f.x, f.y, 1.0 - abs(f.x) - abs(f.y));
    float t = saturate(-n.z);
    n.xy += float2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
    // guard: a cleared texel (0, 0) decodes to a corner, still unit after normalizing
    return SafeNormalize(n);
}

// Emission plus ambient, clamped so the 16-bit float RT3 stays finite.
float4 GBuffer_EncodeEmission(float3 emission) {
    return float4(ClampToHalfRange(max(emission, 0.0)), 1.0);
}

#endif  // KILN_GBUFFER_INCLUDED
