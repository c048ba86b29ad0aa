// KilnFog.cginc: distance fog factors (1 = no fog, 0 = fully fogged), the three modes of the
// OpenGL fixed-function fog that Unity's FOG_LINEAR / FOG_EXP / FOG_EXP2 keywords select
// (OpenGL 2.1 specification, section 3.10, eqs. 3.24-3.26). `params` is unity_FogParams:
// x = density / sqrt(ln 2), y = density / ln 2, z = -1 / (end - start), w = end / (end - start).
#ifndef KILN_FOG_INCLUDED
#define KILN_FOG_INCLUDED

// Linear: (end - z) / (end - start), clamped.
float Fog_Linear(float z, float4 params) {
    return saturate(z * params.z + params.w);
}

// Exponential: exp(-density z) = exp2(-(density / ln 2) z).
float Fog_Exp(float z, float4 params) {
    // guard: a negative distance (behind the near plane) would give a factor above 1
    return saturate(exp2(-params.y * max(z, 0.0)));
}

// Squared exponential: exp(-(density z)^2) = exp2(-((density / sqrt(ln 2)) z)^2).
float Fog_Exp2(float z, float4 params) {
    float d = params.x * max(z, 0.0);
    return saturate(exp2(-d * d));
}

#endif  // KILN_FOG_INCLUDED
