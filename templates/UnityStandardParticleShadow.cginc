// UnityStandardParticleShadow.cginc: the ShadowCaster pass of Unity's Standard particle shaders:
// depth only, with cut-outs from the particle texture's alpha times the particle colour's alpha
// (alpha test at _Cutoff; blended modes at 0.5, or dithered with
// UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS).
#ifndef UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED
#define UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED

#include "KilnParticles.cginc"
#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityStandardParticleInstancing.cginc"

#if (defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)) && \
    defined(UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS)
#define UNITY_STANDARD_USE_DITHER_MASK 1
#endif
#if defined(_ALPHATEST_ON) || defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
#define UNITY_STANDARD_USE_SHADOW_UVS 1
#endif
#if !defined(V2F_SHADOW_CASTER_NOPOS_IS_EMPTY) || defined(UNITY_STANDARD_USE_SHADOW_UVS)
#define UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT 1
#endif

#ifdef _ALPHATEST_ON
half _Cutoff;
#endif
sampler2D _MainTex;
float4 _MainTex_ST;
#ifdef UNITY_STANDARD_USE_DITHER_MASK
sampler3D _DitherMaskLOD;
#endif
half _Metallic;
#ifdef _METALLICGLOSSMAP
sampler2D _MetallicGlossMap;
#endif

// The share of light a premultiplied particle reflects regardless of its alpha.
half MetallicSetup_ShadowGetOneMinusReflectivity(half2 uv) {
    half metallic = _Metallic;
#ifdef _METALLICGLOSSMAP
    metallic = tex2D(_MetallicGlossMap, uv).r;
#endif
    return OneMinusReflectivityFromMetallic(metallic);
}

struct VertexInput {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    fixed4 color : COLOR;
#if defined(_FLIPBOOK_BLENDING)
    float4 texcoords : TEXCOORD0;
    float texcoordBlend : TEXCOORD1;
#else
    float2 texcoords : TEXCOORD0;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
struct VertexOutputShadowCaster {
    V2F_SHADOW_CASTER_NOPOS
#ifdef UNITY_STANDARD_USE_SHADOW_UVS
    float2 texcoord : TEXCOORD1;
#ifdef _FLIPBOOK_BLENDING
    float3 texcoord2AndBlend : TEXCOORD2;
#endif
    fixed4 color : TEXCOORD3;
#endif
};
#endif

void vertParticleShadowCaster(VertexInput v,
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
                              out VertexOutputShadowCaster o,
#endif
                              out float4 opos : SV_POSITION) {
    UNITY_SETUP_INSTANCE_ID(v);
    TRANSFER_SHADOW_CASTER_NOPOS(o, opos)
#ifdef UNITY_STANDARD_USE_SHADOW_UVS
#ifdef _FLIPBOOK_BLENDING
    o.texcoord = v.texcoords.xy;
    o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#else
    o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#endif
    o.color = v.color;
#endif
}

half4 fragParticleShadowCaster(
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    VertexOutputShadowCaster i
#endif
#ifdef UNITY_STANDARD_USE_DITHER_MASK
    , UNITY_VPOS_TYPE vpos : VPOS
#endif
    ) : SV_Target {
#ifdef UNITY_STANDARD_USE_SHADOW_UVS
#ifdef _FLIPBOOK_BLENDING
    half alpha = ParticleFlipbookSample(_MainTex, i.texcoord, i.texcoord2AndBlend).a;
#else
    half alpha = ParticleFlipbookSample(_MainTex, i.texcoord, float3(0.0, 0.0, 0.0)).a;
#endif
    alpha *= i.color.a;
#ifdef _ALPHATEST_ON
    clip(alpha - _Cutoff);
#endif
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
#ifdef _ALPHAPREMULTIPLY_ON
    half premultipliedAlpha;
    PreMultiplyAlpha(half3(0.0, 0.0, 0.0), alpha,
                     MetallicSetup_ShadowGetOneMinusReflectivity(i.texcoord), premultipliedAlpha);
    alpha = premultipliedAlpha;
#endif
#ifdef UNITY_STANDARD_USE_DITHER_MASK
    // A 4x4 screen-space dither pattern per alpha level (16 levels in the 3D mask's depth).
    clip(tex3D(_DitherMaskLOD, float3(vpos.xy * 0.25, alpha * 0.9375)).a - 0.01);
#else
    clip(alpha - 0.5);
#endif
#endif
#endif  // UNITY_STANDARD_USE_SHADOW_UVS
    SHADOW_CASTER_FRAGMENT(i)
}

#endif  // UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED
