// UnityStandardBRDF.cginc: BRDF helpers.
#ifndef UNITY_STANDARD_BRDF_INCLUDED
#define UNITY_STANDARD_BRDF_INCLUDED

#include "UnityCG.cginc"
#include "UnityLightingCommon.cginc"

// max(0, a . b): the clamped cosine of Lambert's law.
float DotClamped(float3 a, float3 b) {
    return saturate(dot(a, b));
}

#endif  // UNITY_STANDARD_BRDF_INCLUDED
