// UnityLightingCommon.cginc: the light built-ins (_LightColor0, _WorldSpaceLightPos0), declared
// in UnityShaderVariables.cginc's UnityLighting block.
#ifndef UNITY_LIGHTING_COMMON_INCLUDED
#define UNITY_LIGHTING_COMMON_INCLUDED

#include "UnityShaderVariables.cginc"

#endif  // UNITY_LIGHTING_COMMON_INCLUDED
