// UnityCG.cginc: space transforms and small helpers with Unity's names.
#ifndef UNITY_CG_INCLUDED
#define UNITY_CG_INCLUDED

#include "UnityShaderVariables.cginc"

// Object space -> homogeneous clip space: P * V * M * p, with w = 1 forced on the input.
float4 UnityObjectToClipPos(float3 pos) {
    return mul(unity_MatrixVP, mul(unity_ObjectToWorld, float4(pos, 1.0)));
}
float4 UnityObjectToClipPos(float4 pos) {
    return UnityObjectToClipPos(pos.xyz);
}

// Normals transform with the inverse transpose of M: n_world = n * M^-1 (row vector), normalized.
// A zero normal stays zero instead of becoming NaN (normalize(0) is undefined).
float3 UnityObjectToWorldNormal(float3 norm) {
    float3 n = mul(norm, (float3x3)unity_WorldToObject);
    float len2 = dot(n, n);
    return len2 > 0.0 ? n * rsqrt(len2) : n;  // guard: zero-length normal
}

float3 UnityObjectToWorldDir(float3 dir) {
    return normalize(mul((float3x3)unity_ObjectToWorld, dir));
}

// Unnormalized direction from a world position to the camera.
float3 UnityWorldSpaceViewDir(float3 worldPos) {
    return _WorldSpaceCameraPos.xyz - worldPos;
}

// Unnormalized direction to the light: the direction itself (w = 0) or position - p (w = 1).
float3 UnityWorldSpaceLightDir(float3 worldPos) {
    return _WorldSpaceLightPos0.xyz - worldPos * _WorldSpaceLightPos0.w;
}

// Texture tiling and offset from the material's <name>_ST vector.
#define TRANSFORM_TEX(tex, name) ((tex).xy * name##_ST.xy + name##_ST.zw)

#endif  // UNITY_CG_INCLUDED
