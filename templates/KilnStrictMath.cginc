// KilnStrictMath.cginc: what SPIR-V leaves undefined, made NaN (kiln stability --source).
//
// GLSL.std.450 Pow is undefined for x < 0 and for x = 0 with y <= 0, Normalize of the zero
// vector divides 0 by 0 (and of a vector within rounding of zero returns noise), and FClamp of
// a NaN may return either operand: one driver shows black where another shows NaN. With
// KILN_STRICT_POW and / or KILN_STRICT_NORMALIZE defined (-D), HLSLSupport.cginc includes this
// file before any other code; the named intrinsic returns NaN on those inputs, and saturate and
// pow pass a NaN on, so a render shows every pixel whose value depends on an undefined
// operation, on every driver. Not for shipping builds.
#ifndef KILN_STRICT_MATH_INCLUDED
#define KILN_STRICT_MATH_INCLUDED

float KilnStrictNaN() {
    return asfloat(0x7fc00000u);
}

// NaN by its bits: a compiler that assumes no NaN (fast math) may fold isnan(x) to false.
bool KilnStrictIsNaN(float x) {
    return (asuint(x) & 0x7fffffffu) > 0x7f800000u;
}

// saturate that keeps NaN (FClamp's result for NaN is undefined; llvmpipe returns 0).
float KilnStrictSaturate(float x) {
    return KilnStrictIsNaN(x) ? x : saturate(x);
}
float2 KilnStrictSaturate(float2 x) {
    return float2(KilnStrictSaturate(x.x), KilnStrictSaturate(x.y));
}
float3 KilnStrictSaturate(float3 x) {
    return float3(KilnStrictSaturate(x.x), KilnStrictSaturate(x.y), KilnStrictSaturate(x.z));
}
float4 KilnStrictSaturate(float4 x) {
    return float4(KilnStrictSaturate(x.xyz), KilnStrictSaturate(x.w));
}
#define saturate KilnStrictSaturate

// pow that keeps NaN (llvmpipe's exp2(y log2 x) turns a NaN base into a finite value) and, with
// KILN_STRICT_POW, is NaN where GLSL.std.450 Pow is undefined.
float KilnStrictPow(float x, float y) {
    bool nan = KilnStrictIsNaN(x) || KilnStrictIsNaN(y);
#if defined(KILN_STRICT_POW)
    nan = nan || x < 0.0 || (x == 0.0 && y <= 0.0);
#endif
    return nan ? KilnStrictNaN() : pow(x, y);
}
float2 KilnStrictPow(float2 x, float2 y) {
    return float2(KilnStrictPow(x.x, y.x), KilnStrictPow(x.y, y.y));
}
float3 KilnStrictPow(float3 x, float3 y) {
    return float3(KilnStrictPow(x.xy, y.xy), KilnStrictPow(x.z, y.z));
}
float4 KilnStrictPow(float4 x, float4 y) {
    return float4(KilnStrictPow(x.xyz, y.xyz), KilnStrictPow(x.w, y.w));
}
#define pow KilnStrictPow

#if defined(KILN_STRICT_NORMALIZE)
// A vector this short (as KILN_MIN_LENGTH_SQ, where SafeNormalize returns 0) is the zero vector
// plus rounding: normalize returns a direction made of rounding noise, or NaN when it is exactly
// zero (the half vector of l = -v one ULP away from exact). Both count as undefined here.
#define KILN_STRICT_MIN_LENGTH_SQ 1e-12
float2 KilnStrictNormalize(float2 v) {
    return dot(v, v) > KILN_STRICT_MIN_LENGTH_SQ ? normalize(v) : KilnStrictNaN().xx;
}
float3 KilnStrictNormalize(float3 v) {
    return dot(v, v) > KILN_STRICT_MIN_LENGTH_SQ ? normalize(v) : KilnStrictNaN().xxx;
}
float4 KilnStrictNormalize(float4 v) {
    return dot(v, v) > KILN_STRICT_MIN_LENGTH_SQ ? normalize(v) : KilnStrictNaN().xxxx;
}
#define normalize KilnStrictNormalize
#endif

#endif  // KILN_STRICT_MATH_INCLUDED
