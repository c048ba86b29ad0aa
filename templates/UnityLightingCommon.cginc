// UnityLightingCommon.cginc: the light structs of the standard lighting functions and the
// global specular colour, with Unity's names. _LightColor0 and _WorldSpaceLightPos0 (w = 0 for a
// directional light, 1 for a positional one) are in UnityShaderVariables.cginc's UnityLighting
// block, which the runtime fills per light.
#ifndef UNITY_LIGHTING_COMMON_INCLUDED
#define UNITY_LIGHTING_COMMON_INCLUDED

#include "UnityShaderVariables.cginc"

// The specular colour of the classic Blinn-Phong lighting functions (a material property).
fixed4 _SpecColor;

// One direct light at the shaded point: colour (attenuation applied), unit direction towards
// the light, and n . l (deprecated in Unity: the BRDFs recompute it). The colour is 32-bit where
// Unity's is half3: a light in physical units (a 1e5 lux sun) is beyond binary16's 65504, and
// with --precision half a half3 colour would be infinite (docs/accuracy.md, "fp16").
struct UnityLight {
    float3 color;
    half3 dir;
    half ndotl;
};

// Indirect light at the shaded point: diffuse irradiance / pi and prefiltered specular radiance.
struct UnityIndirect {
    half3 diffuse;
    half3 specular;
};

struct UnityGI {
    UnityLight light;
    UnityIndirect indirect;
};

// What the global-illumination functions read (UnityGlobalIllumination.cginc).
struct UnityGIInput {
    UnityLight light;  // the pixel light
    float3 worldPos;
    half3 worldViewDir;
    half atten;
    half3 ambient;
    float4 lightmapUV;  // xy: static lightmap, zw: dynamic lightmap
#if defined(UNITY_SPECCUBE_BLENDING) || defined(UNITY_SPECCUBE_BOX_PROJECTION) || \
    defined(UNITY_ENABLE_REFLECTION_BUFFERS)
    float4 boxMin[2];
#endif
#ifdef UNITY_SPECCUBE_BOX_PROJECTION
    float4 boxMax[2];
    float4 probePosition[2];
#endif
    float4 probeHDR[2];  // decode instructions of the reflection probes
};

#endif  // UNITY_LIGHTING_COMMON_INCLUDED
