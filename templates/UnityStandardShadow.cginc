// UnityStandardShadow.cginc: the Standard shader's ShadowCaster pass with Unity's names: depth
// only, with alpha-tested (and, with UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS, dithered
// transparent) cut-outs from the albedo's alpha.
#ifndef UNITY_STANDARD_SHADOW_INCLUDED
#define UNITY_STANDARD_SHADOW_INCLUDED

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityLightingCommon.cginc"  // _SpecColor

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

half4 _Color;
half _Cutoff;
sampler2D _MainTex;
float4 _MainTex_ST;
#ifdef UNITY_STANDARD_USE_DITHER_MASK
sampler3D _DitherMaskLOD;
#endif
half _Metallic;
#ifdef _SPECGLOSSMAP
sampler2D _SpecGlossMap;
#endif
#ifdef _METALLICGLOSSMAP
sampler2D _MetallicGlossMap;
#endif
#if defined(UNITY_STANDARD_USE_SHADOW_UVS) && defined(_PARALLAXMAP)
sampler2D _ParallaxMap;
half _Parallax;
#endif

// The share of light a premultiplied surface reflects regardless of alpha, per workflow.
half MetallicSetup_ShadowGetOneMinusReflectivity(half2 uv) {
    half metallic = _Metallic;
#ifdef _METALLICGLOSSMAP
    metallic = tex2D(_MetallicGlossMap, uv).r;
#endif
    return OneMinusReflectivityFromMetallic(metallic);
}
half RoughnessSetup_ShadowGetOneMinusReflectivity(half2 uv) {
    return MetallicSetup_ShadowGetOneMinusReflectivity(uv);
}
half SpecularSetup_ShadowGetOneMinusReflectivity(half2 uv) {
    half3 specColor = _SpecColor.rgb;
#ifdef _SPECGLOSSMAP
    specColor = tex2D(_SpecGlossMap, uv).rgb;
#endif
    return 1.0 - SpecularStrength(specColor);
}
#ifndef UNITY_SETUP_BRDF_INPUT
#define UNITY_SETUP_BRDF_INPUT MetallicSetup
#endif
#define SHADOW_JOIN2(a, b) a##b
#define SHADOW_JOIN(a, b) SHADOW_JOIN2(a, b)
#define SHADOW_ONEMINUSREFLECTIVITY SHADOW_JOIN(UNITY_SETUP_BRDF_INPUT, _ShadowGetOneMinusReflectivity)

struct VertexInput {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float2 uv0 : TEXCOORD0;
#if defined(UNITY_STANDARD_USE_SHADOW_UVS) && defined(_PARALLAXMAP)
    half4 tangent : TANGENT;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
struct VertexOutputShadowCaster {
    V2F_SHADOW_CASTER_NOPOS
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    float2 tex : TEXCOORD1;
#if defined(_PARALLAXMAP)
    half3 viewDirForParallax : TEXCOORD2;
#endif
#endif
};
#endif

// The clip position is a separate output so the struct can be empty (opaque casters).
void vertShadowCaster(VertexInput v, out float4 opos : SV_POSITION
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
                      , out VertexOutputShadowCaster o
#endif
) {
    UNITY_SETUP_INSTANCE_ID(v);
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    UNITY_INITIALIZE_OUTPUT(VertexOutputShadowCaster, o);
#endif
    TRANSFER_SHADOW_CASTER_NOPOS(o, opos)
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    o.tex = TRANSFORM_TEX(v.uv0, _MainTex);
#ifdef _PARALLAXMAP
    TANGENT_SPACE_ROTATION;
    o.viewDirForParallax = mul(rotation, ObjSpaceViewDir(v.vertex));
#endif
#endif
}

half4 fragShadowCaster(UNITY_POSITION(vpos)
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
                       , VertexOutputShadowCaster i
#endif
                       ) : SV_Target {
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    float2 uv = i.tex;
#if defined(_PARALLAXMAP) && (SHADER_TARGET >= 30)
    half h = tex2D(_ParallaxMap, uv).g;
    uv += ParallaxOffset1Step(h, _Parallax, SafeNormalize(i.viewDirForParallax));
#endif
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    half alpha = _Color.a;
#else
    half alpha = tex2D(_MainTex, uv).a * _Color.a;
#endif
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
#endif
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
#if defined(_ALPHAPREMULTIPLY_ON)
    half oneMinusReflectivity = SHADOW_ONEMINUSREFLECTIVITY(uv);
    alpha = 1 - oneMinusReflectivity + alpha * oneMinusReflectivity;
#endif
#if defined(UNITY_STANDARD_USE_DITHER_MASK)
    // 4x4 dither pattern per 16 alpha levels
    half alphaRef = tex3D(_DitherMaskLOD, float3(vpos.xy * 0.25, alpha * 0.9375)).a;
    clip(alphaRef - 0.01);
#else
    clip(alpha - _Cutoff);
#endif
#endif
#endif
    SHADOW_CASTER_FRAGMENT(i)
}

#endif  // UNITY_STANDARD_SHADOW_INCLUDED
