// UnityShaderVariables.cginc: the built-in values the runtime fills, with Unity's names, laid out
// per docs/binding-model.md: per-camera, per-frame, lighting, shadow, fog, probe and per-draw
// blocks (bound by name in descriptor set 0 or filled per draw), the object matrices in push
// constants. Values Kiln's runtime does not provide yet (lightmaps, shadows, reflection-probe
// boxes, light-probe proxy volumes) are declared so Unity-style code compiles; they read as 0 or
// as the default textures (docs/unity-compat.md lists which).
#ifndef UNITY_SHADER_VARIABLES_INCLUDED
#define UNITY_SHADER_VARIABLES_INCLUDED

#include "HLSLSupport.cginc"

#if defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)
#define USING_DIRECTIONAL_LIGHT
#endif

CBUFFER_START(UnityPerCamera)
    float4 _Time;               // (t/20, t, 2t, 3t), seconds since start
    float4 _SinTime;            // sin of (t/8, t/4, t/2, t)
    float4 _CosTime;            // cos of (t/8, t/4, t/2, t)
    float4 unity_DeltaTime;     // (dt, 1/dt, smoothDt, 1/smoothDt)
    float3 _WorldSpaceCameraPos;
    float4 _ProjectionParams;   // (1, near, far, 1/far)
    float4 _ScreenParams;       // (width, height, 1 + 1/width, 1 + 1/height)
    // Depth buffer value z -> linear depth, for Kiln's depth 0 at near, 1 at far:
    // x = 1 - far/near, y = far/near, z = x/far, w = y/far.
    float4 _ZBufferParams;
    float4 unity_OrthoParams;   // (width, height, unused, 1 for orthographic / 0 perspective)
CBUFFER_END

CBUFFER_START(UnityPerCameraRare)
    float4 unity_CameraWorldClipPlanes[6];
    float4x4 unity_CameraProjection;
    float4x4 unity_CameraInvProjection;
    float4x4 unity_WorldToCamera;
    float4x4 unity_CameraToWorld;
CBUFFER_END

CBUFFER_START(UnityPerFrame)
    float4x4 unity_MatrixV;
    float4x4 unity_MatrixInvV;
    float4x4 unity_MatrixVP;
    float4x4 glstate_matrix_projection;
    float4 unity_AmbientSky;    // linear RGB constant ambient colour (the lecture's ambient term)
    float4 unity_AmbientEquator;
    float4 unity_AmbientGround;
    float4 unity_IndirectSpecColor;
    float4 glstate_lightmodel_ambient;
    float4 unity_ShadowColor;
CBUFFER_END

CBUFFER_START(UnityLighting)
    // The pixel light of this pass (ForwardBase: the main directional light; ForwardAdd: one light).
    // Directional light: (unit direction towards the light, 0); other lights: (position, 1).
    float4 _WorldSpaceLightPos0;
    float4 _LightColor0;        // linear colour x intensity (docs/shader-library.md, "Light units")
    float4 kiln_SpotDirection0; // xyz: unit direction the spot light points in; w: 0
    float4 kiln_LightParams0;   // x: 1 / range^2 (0 = unlimited), y: cos outer cone, z: cos inner cone, w: 0
    float4 _LightPositionRange; // xyz: light position, w: 1 / range
    float4 _LightProjectionParams;
    float4x4 unity_WorldToLight;  // light cookie space (cookies are not implemented)

    // Up to four per-vertex point lights (ForwardBase with VERTEXLIGHT_ON), structure of arrays.
    float4 unity_4LightPosX0;   // world x of lights 0..3
    float4 unity_4LightPosY0;   // world y
    float4 unity_4LightPosZ0;   // world z
    float4 unity_4LightAtten0;  // 1 / range^2 of lights 0..3 (0 = unlimited)
    float4 unity_LightColor[8]; // colours x intensity; 0..3 are the vertex lights
    // The legacy "Vertex" pass lights, in view space (fixed-function and ShadeVertexLights).
    float4 unity_LightPosition[8];
    float4 unity_LightAtten[8];     // x: cos(spot/2), y: 1/(cos(spot/4) - cos(spot/2)), z: quadratic, w: range^2
    float4 unity_SpotDirection[8];
    float4 unity_OcclusionMaskSelector;
    float4 unity_ProbesOcclusion;
CBUFFER_END

// Unity 3's per-light colours, kept for old shaders (Kiln fills unity_LightColor[] instead).
CBUFFER_START(UnityLightingOld)
    half3 unity_LightColor0, unity_LightColor1, unity_LightColor2, unity_LightColor3;
CBUFFER_END

CBUFFER_START(UnityShadows)
    float4 unity_ShadowSplitSpheres[4];
    float4 unity_ShadowSplitSqRadii;
    float4 unity_LightShadowBias;
    float4 _LightSplitsNear;
    float4 _LightSplitsFar;
    float4x4 unity_WorldToShadow[4];
    float4 _LightShadowData;
    float4 unity_ShadowFadeCenterAndType;
CBUFFER_END

CBUFFER_START(UnityFog)
    float4 unity_FogColor;
    // x = density / sqrt(ln(2)) (Exp2), y = density / ln(2) (Exp), z = -1/(end-start), w = end/(end-start)
    float4 unity_FogParams;
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
    // Light probe proxy volumes: x = 1 when the object uses one (never in Kiln's runtime).
    float4 unity_ProbeVolumeParams;
    float4x4 unity_ProbeVolumeWorldToObject;
    float4 unity_ProbeVolumeSizeInv;
    float4 unity_ProbeVolumeMin;
CBUFFER_END

CBUFFER_START(UnityReflectionProbes)
    float4 unity_SpecCube0_BoxMax;
    float4 unity_SpecCube0_BoxMin;
    float4 unity_SpecCube0_ProbePosition;
    float4 unity_SpecCube0_HDR;
    float4 unity_SpecCube1_BoxMax;
    float4 unity_SpecCube1_BoxMin;
    float4 unity_SpecCube1_ProbePosition;
    float4 unity_SpecCube1_HDR;
CBUFFER_END

// Per draw, besides the matrices: level-of-detail fade, the sign of the object's handedness
// (w = -1 for a mirroring transform), rendering layers and lightmap scale/offset.
CBUFFER_START(UnityPerDrawRare)
    float4 unity_LODFade;
    float4 unity_WorldTransformParams;
    float4 unity_RenderingLayer;
    float4 unity_LightmapST;
    float4 unity_DynamicLightmapST;
    float4 unity_Lightmap_HDR;
    float4 unity_DynamicLightmap_HDR;
    float4 unity_MotionVectorsParams;
CBUFFER_END

// Per object: 128 bytes, the push-constant size every Vulkan device provides.
[[vk::push_constant]] cbuffer UnityPerDraw {
    float4x4 unity_ObjectToWorld;
    float4x4 unity_WorldToObject;
};

// Built-in textures: lightmaps, shadow masks, reflection probes, probe volumes.
UNITY_DECLARE_TEX2D(unity_Lightmap);
UNITY_DECLARE_TEX2D_NOSAMPLER(unity_LightmapInd);
UNITY_DECLARE_TEX2D(unity_ShadowMask);
UNITY_DECLARE_TEX2D(unity_DynamicLightmap);
UNITY_DECLARE_TEX2D_NOSAMPLER(unity_DynamicDirectionality);
UNITY_DECLARE_TEX2D_NOSAMPLER(unity_DynamicNormal);
UNITY_DECLARE_TEXCUBE(unity_SpecCube0);
UNITY_DECLARE_TEXCUBE_NOSAMPLER(unity_SpecCube1);
#if UNITY_LIGHT_PROBE_PROXY_VOLUME
UNITY_DECLARE_TEX3D_FLOAT(unity_ProbeVolumeSH);
#endif

static uint unity_StereoEyeIndex = 0;

#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_V unity_MatrixV
#define UNITY_MATRIX_I_V unity_MatrixInvV
#define UNITY_MATRIX_P glstate_matrix_projection
#define UNITY_MATRIX_VP unity_MatrixVP
#define UNITY_MATRIX_MVP mul(unity_MatrixVP, unity_ObjectToWorld)
#define UNITY_MATRIX_MV mul(unity_MatrixV, unity_ObjectToWorld)
#define UNITY_MATRIX_T_MV transpose(UNITY_MATRIX_MV)
#define UNITY_MATRIX_IT_MV transpose(mul(unity_WorldToObject, unity_MatrixInvV))
#define UNITY_LIGHTMODEL_AMBIENT (glstate_lightmodel_ambient * 2)

#endif  // UNITY_SHADER_VARIABLES_INCLUDED
