// KilnSH.cginc: ambient light from order-2 (9-coefficient) spherical harmonics.
//
// The runtime projects the environment's radiance onto the real SH basis (coefficients L_lm,
// Ramamoorthi and Hanrahan 2001, eq. 7 ordering) and packs the irradiance polynomial of their
// eq. 13, divided by pi for the library's light convention, into seven float4 per the table in
// docs/shader-library.md (runtime/reference/sh.h PackSH9 is the packing). So
//   E(n) / pi = dot(SHA, (n, 1)) + dot(SHB, n.xyzz * n.yzzx) + SHC * (n.x^2 - n.y^2).
#ifndef KILN_SH_INCLUDED
#define KILN_SH_INCLUDED

// Constant and linear bands (l = 0, 1) for one channel: dot(shA, (n, 1)).
float SH_EvalL0L1(float4 shA, float3 n) {
    return dot(shA, float4(n, 1.0));
}

// Quadratic band (l = 2) for one channel.
float SH_EvalL2(float4 shB, float shC, float3 n) {
    float4 vB = n.xyzz * n.yzzx;
    return dot(shB, vB) + shC * (n.x * n.x - n.y * n.y);
}

// Irradiance / pi for unit normal n from the packed coefficients.
float3 SH_Irradiance(float4 shAr, float4 shAg, float4 shAb, float4 shBr, float4 shBg, float4 shBb,
                     float4 shC, float3 n) {
    float3 e;
    e.r = SH_EvalL0L1(shAr, n) + SH_EvalL2(shBr, shC.r, n);
    e.g = SH_EvalL0L1(shAg, n) + SH_EvalL2(shBg, shC.g, n);
    e.b = SH_EvalL0L1(shAb, n) + SH_EvalL2(shBb, shC.b, n);
    // guard: a truncated SH series rings and can go negative opposite a bright light; irradiance
    // cannot be negative
    return max(e, 0.0);
}

#endif  // KILN_SH_INCLUDED
