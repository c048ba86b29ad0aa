// UnityShaderVariables.cginc: the built-in values the runtime fills, laid out per
// docs/binding-model.md: per-camera, per-frame and per-light blocks in descriptor set 0 (bound
// by name), per-object matrices in push constants.
#ifndef UNITY_SHADER_VARIABLES_INCLUDED
#define UNITY_SHADER_VARIABLES_INCLUDED

#include "HLSLSupport.cginc"

CBUFFER_START(UnityPerCamera)
    float4 _Time;               // (t/20, t, 2t, 3t), seconds since start
    float4 _SinTime;            // sin of (t/8, t/4, t/2, t)
    float4 _CosTime;            // cos of (t/8, t/4, t/2, t)
    float4 unity_DeltaTime;     // (dt, 1/dt, smoothDt, 1/smoothDt)
    float3 _WorldSpaceCameraPos;
    float4 _ProjectionParams;   // (1, near, far, 1/far)
    float4 _ScreenParams;       // (width, height, 1 + 1/width, 1 + 1/height)
CBUFFER_END

CBUFFER_START(UnityPerFrame)
    float4x4 unity_MatrixV;
    float4x4 unity_MatrixVP;
    float4x4 glstate_matrix_projection;
    float4 unity_AmbientSky;    // linear RGB ambient colour
CBUFFER_END

CBUFFER_START(UnityLighting)
    // Directional light: (direction towards the light, 0); other lights: (position, 1).
    float4 _WorldSpaceLightPos0;
    float4 _LightColor0;        // linear colour x intensity
CBUFFER_END

// Per object: 128 bytes, the push-constant size every Vulkan device provides.
[[vk::push_constant]] cbuffer UnityPerDraw {
    float4x4 unity_ObjectToWorld;
    float4x4 unity_WorldToObject;
};

#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_V unity_MatrixV
#define UNITY_MATRIX_P glstate_matrix_projection
#define UNITY_MATRIX_VP unity_MatrixVP
#define UNITY_MATRIX_MVP mul(unity_MatrixVP, unity_ObjectToWorld)

#endif  // UNITY_SHADER_VARIABLES_INCLUDED
