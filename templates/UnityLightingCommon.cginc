// UnityLightingCommon.cginc: the light built-ins (_LightColor0, _WorldSpaceLightPos0 with w = 0
// for a directional light and 1 for a positional one, declared in UnityShaderVariables.cginc's
// UnityLighting block) and the light structs of the standard lighting functions.
#ifndef UNITY_LIGHTING_COMMON_INCLUDED
#define UNITY_LIGHTING_COMMON_INCLUDED

#include "UnityShaderVariables.cginc"

// One direct light at the shaded point: colour (attenuation applied), unit direction towards
// the light, and the clamped cosine n . l (kept for Unity compatibility; the BRDF recomputes it).
struct UnityLight {
    float3 color;
    float3 dir;
    float ndotl;
};

// Indirect light at the shaded point: diffuse irradiance / pi and prefiltered specular radiance.
struct UnityIndirect {
    float3 diffuse;
    float3 specular;
};

struct UnityGI {
    UnityLight light;
    UnityIndirect indirect;
};

#endif  // UNITY_LIGHTING_COMMON_INCLUDED
