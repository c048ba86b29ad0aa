// UnityShaderUtilities.cginc: included in front of every CGPROGRAM (as Unity does), so
// UnityObjectToClipPos is available without UnityCG.cginc.
#ifndef UNITY_SHADER_UTILITIES_INCLUDED
#define UNITY_SHADER_UTILITIES_INCLUDED

#include "UnityShaderVariables.cginc"

// Kiln renders no omni-directional stereo captures (STEREO_CUBEMAP_RENDER_ON): the ODS
// transform is the ordinary one.
inline float4 UnityObjectToClipPosODS(float3 inPos) {
    return mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, float4(inPos, 1.0)));
}

// Object space -> homogeneous clip space: P * V * M * p, with w = 1 forced on the input.
inline float4 UnityObjectToClipPos(in float3 pos) {
    return mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, float4(pos, 1.0)));
}
// The float4 overload ignores w (Unity's, which avoids the truncation warning).
inline float4 UnityObjectToClipPos(float4 pos) {
    return UnityObjectToClipPos(pos.xyz);
}

#endif  // UNITY_SHADER_UTILITIES_INCLUDED
