// UnityPBSLighting.cginc: the physically based lighting entry point of the lecture.
#ifndef UNITY_PBS_LIGHTING_INCLUDED
#define UNITY_PBS_LIGHTING_INCLUDED

#include "UnityShaderVariables.cginc"
#include "UnityStandardBRDF.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityLightingCommon.cginc"

// UNITY_BRDF_PBS(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
//                light, indirect) -> float4 linear colour (docs/shader-library.md).
#define UNITY_BRDF_PBS BRDF1_Unity_PBS

#endif  // UNITY_PBS_LIGHTING_INCLUDED
