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
    float4 unity_AmbientSky;    // linear RGB constant ambient colour (the lecture's ambient term)
CBUFFER_END

CBUFFER_START(UnityLighting)
    // The pixel light of this pass (ForwardBase: the main directional light; ForwardAdd: one light).
    // Directional light: (unit direction towards the light, 0); other lights: (position, 1).
    float4 _WorldSpaceLightPos0;
    float4 _LightColor0;        // linear colour x intensity (docs/shader-library.md, "Light units")
    float4 kiln_SpotDirection0; // xyz: unit direction the spot light points in; w: 0
    float4 kiln_LightParams0;   // x: 1 / range^2 (0 = unlimited), y: cos outer cone, z: cos inner cone, w: 0

    // Up to four per-vertex point lights (ForwardBase with VERTEXLIGHT_ON), structure of arrays.
    float4 unity_4LightPosX0;   // world x of lights 0..3
    float4 unity_4LightPosY0;   // world y
    float4 unity_4LightPosZ0;   // world z
    float4 unity_4LightAtten0;  // 1 / range^2 of lights 0..3 (0 = unlimited)
    float4 unity_LightColor[8]; // colours x intensity; 0..3 are the vertex lights
CBUFFER_END

// Ambient light as order-2 spherical harmonics (KilnSH.cginc has the packing), per frame.
CBUFFER_START(UnityProbes)
    float4 unity_SHAr;
    float4 unity_SHAg;
    float4 unity_SHAb;
    float4 unity_SHBr;
    float4 unity_SHBg;
    float4 unity_SHBb;
    float4 unity_SHC;
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
