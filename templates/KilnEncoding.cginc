// KilnEncoding.cginc: packings of values into texels and back: RGBM and double-LDR colour,
// HDR cubemap decoding, floats in RGBA8 / RG8, view normals in two channels (stereographic
// projection), and depth-buffer linearization.
#ifndef KILN_ENCODING_INCLUDED
#define KILN_ENCODING_INCLUDED

#include "KilnCommon.cginc"

// RGBM: rgb * (range * a^exponent). Unity's decode instructions carry range in x and the
// exponent in y (y = 1 in linear colour space); w = 1 means alpha is used at all.
float3 Decode_RGBM(float4 data, float4 instructions) {
    float alpha = instructions.w * (data.a - 1.0) + 1.0;  // w = 0: alpha ignored (treated as 1)
    // guard: pow of a negative alpha (filtered texels are in [0, 1], but stay safe)
    return (instructions.x * pow(max(alpha, 0.0), instructions.y)) * data.rgb;
}

// Double LDR: rgb * 2 (4.59 in linear space, passed as `scale`).
float3 Decode_DoubleLDR(float4 data, float scale) {
    return scale * data.rgb;
}

// RGBM encode with a given range: the smallest multiplier m in (0, 1] with rgb / (m range) <= 1.
float4 Encode_RGBM(float3 rgb, float range) {
    float m = max(max(rgb.r, rgb.g), max(rgb.b, 1e-6)) / range;
    m = ceil(saturate(m) * 255.0) / 255.0;
    // guard: m >= 1/255 after the ceil unless rgb is 0, where any rgb/m is 0
    return float4(rgb / (max(m, 1.0 / 255.0) * range), m);
}

// A float in [0, 1) packed into 8-bit channels (and back).
float4 Encode_FloatRGBA(float v) {
    float4 enc = float4(1.0, 255.0, 65025.0, 16581375.0) * v;
    enc = frac(enc);
    enc -= enc.yzww * float4(1.0 / 255.0, 1.0 / 255.0, 1.0 / 255.0, 0.0);
    return enc;
}
float Decode_FloatRGBA(float4 enc) {
    return dot(enc, float4(1.0, 1.0 / 255.0, 1.0 / 65025.0, 1.0 / 16581375.0));
}
float2 Encode_FloatRG(float v) {
    float2 enc = frac(float2(1.0, 255.0) * v);
    enc.x -= enc.y * (1.0 / 255.0);
    return enc;
}
float Decode_FloatRG(float2 enc) {
    return dot(enc, float2(1.0, 1.0 / 255.0));
}

// A unit view-space normal facing the camera in two channels: stereographic projection from
// (0, 0, -1), scaled by 1.7777 to use [0, 1] well (Pranckevicius, "Compact Normal Storage").
#define KILN_STEREO_SCALE 1.7777
float2 Encode_ViewNormalStereo(float3 n) {
    // guard: n.z = -1 (a normal facing away) would divide by zero
    float2 enc = n.xy / max(n.z + 1.0, 1e-5);
    enc /= KILN_STEREO_SCALE;
    return enc * 0.5 + 0.5;
}
float3 Decode_ViewNormalStereo(float2 enc) {
    float3 nn = float3(enc * (2.0 * KILN_STEREO_SCALE) - KILN_STEREO_SCALE, 1.0);
    float g = 2.0 / dot(nn, nn);
    return float3(g * nn.xy, g - 1.0);
}

// Depth-buffer value -> linear depth, with zbuffer = _ZBufferParams (x = 1 - far/near,
// y = far/near, z = x / far, w = y / far for a buffer holding 0 at near, 1 at far).
float Depth_Linear01(float z, float4 zbuffer) {
    // guard: z * x + y reaches 0 only outside [0, 1]
    return 1.0 / max(zbuffer.x * z + zbuffer.y, 1e-7);
}
float Depth_LinearEye(float z, float4 zbuffer) {
    return 1.0 / max(zbuffer.z * z + zbuffer.w, 1e-7);
}

#endif  // KILN_ENCODING_INCLUDED
