// KilnCommon.cginc: constants and guarded math shared by the whole library.
//
// Domain: every function here returns a finite value for every finite input. The guards are
// the numerical contract of docs/shader-library.md ("Numerical guards"); the CPU reference
// (runtime/reference) applies the same guards and is tested on an adversarial grid.
#ifndef KILN_COMMON_INCLUDED
#define KILN_COMMON_INCLUDED

#define KILN_PI 3.14159265358979323846
#define KILN_INV_PI 0.31830988618379067154
// Largest finite IEEE 754 binary16 value: HDR results are clamped to it before they reach a
// 16-bit float render target, where anything larger becomes +Inf.
#define KILN_HALF_MAX 65504.0
// Smallest normal binary16 value (2^-14): 1 / KILN_HALF_MIN is finite in binary16, and unlike a
// subnormal it is not flushed to 0.
#define KILN_HALF_MIN 6.103515625e-5
// Squared length below which a vector counts as zero for normalization.
#define KILN_MIN_LENGTH_SQ 1e-12

// v / |v|, or the zero vector when |v| is (almost) zero.
float3 SafeNormalize(float3 v) {
    float len2 = dot(v, v);
    // guard: normalize(0) is 0/0 = NaN (e.g. the half vector of a light exactly opposite the view)
    return len2 > KILN_MIN_LENGTH_SQ ? v * rsqrt(len2) : float3(0.0, 0.0, 0.0);
}

// x^y for x >= 0 and y >= 0 with the limits pow(0, 0) = 1 and pow(0, y > 0) = 0.
float SafePow(float x, float y) {
    // guard: SPIR-V's Pow is undefined for x < 0 and for x = 0 with y <= 0 (e.g. the Blinn-Phong
    // exponent _Smoothness * 100 at smoothness 0); max(x, 1e-30) keeps it defined, and the select
    // gives the exact 0 for x <= 0 < y (1e-30^y is near 1 for tiny y; kiln stability)
    float p = pow(max(x, 1e-30), max(y, 0.0));
    return x <= 0.0 && y > 0.0 ? 0.0 : p;
}

// x^5 by multiplication (Schlick's approximation needs it); no pow, so no undefined cases.
float Pow5(float x) {
    float x2 = x * x;
    return x2 * x2 * x;
}

// Clamps an HDR colour to the binary16 range.
float3 ClampToHalfRange(float3 c) {
    // guard: intensities above 65504 overflow to +Inf in a 16-bit float target
    return min(c, KILN_HALF_MAX);
}
float4 ClampToHalfRange(float4 c) {
    return float4(ClampToHalfRange(c.rgb), min(c.a, KILN_HALF_MAX));
}

#endif  // KILN_COMMON_INCLUDED
