// AutoLight.cginc: light attenuation for the pass's pixel light, chosen by the light-type
// keyword of `#pragma multi_compile DIRECTIONAL POINT SPOT` (or multi_compile_fwdadd):
//   DIRECTIONAL (or no keyword)  1
//   POINT                        inverse square x smooth range window (KilnAttenuation.cginc)
//   SPOT                         the same x the spot cone
// from _WorldSpaceLightPos0, kiln_SpotDirection0 and kiln_LightParams0. Kiln has no light
// cookies: POINT_COOKIE and DIRECTIONAL_COOKIE behave as POINT and DIRECTIONAL. Shadows are not
// implemented yet: the shadow macros are empty and SHADOW_ATTENUATION is 1.
#ifndef AUTOLIGHT_INCLUDED
#define AUTOLIGHT_INCLUDED

#include "UnityCG.cginc"
#include "KilnAttenuation.cginc"

#define SHADOW_COORDS(idx1)
#define UNITY_SHADOW_COORDS(idx1)
#define TRANSFER_SHADOW(a)
#define UNITY_TRANSFER_SHADOW(a, coord)
#define SHADOW_ATTENUATION(a) 1.0
#define UNITY_SHADOW_ATTENUATION(a, worldPos) 1.0
#define LIGHTING_COORDS(idx1, idx2)
#define UNITY_LIGHTING_COORDS(idx1, idx2)
#define TRANSFER_VERTEX_TO_FRAGMENT(a)
#define UNITY_TRANSFER_LIGHTING(a, coord)

// Attenuation of the pass's pixel light at a world position, by light type.
float UnityLightAttenuation(float3 worldPos) {
#if defined(POINT) || defined(SPOT) || defined(POINT_COOKIE)
    float3 toLight = _WorldSpaceLightPos0.xyz - worldPos;
    float distanceSq = dot(toLight, toLight);
    float atten = Attenuation_Distance(distanceSq, kiln_LightParams0.x);
#if defined(SPOT)
    atten *= Attenuation_SpotCone(SafeNormalize(toLight), kiln_SpotDirection0.xyz,
                                  kiln_LightParams0.y, kiln_LightParams0.z);
#endif
    return atten;
#else
    return 1.0;
#endif
}

// Declares `float destName` = the light's attenuation at worldPos times the shadow term.
// worldPos may be a float3 or a float4 (the lecture passes its float4 world position).
#define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) \
    float destName = UnityLightAttenuation((worldPos).xyz) * SHADOW_ATTENUATION(input)

#endif  // AUTOLIGHT_INCLUDED
