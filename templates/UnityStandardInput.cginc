// UnityStandardInput.cginc: the Standard shader's material inputs with Unity's names: the
// properties of Standard.shader and StandardSpecular.shader, the vertex input, and one function
// per input that applies the map keywords (_NORMALMAP, _METALLICGLOSSMAP, _SPECGLOSSMAP,
// _EMISSION, _DETAIL_*, _PARALLAXMAP, _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A).
#ifndef UNITY_STANDARD_INPUT_INCLUDED
#define UNITY_STANDARD_INPUT_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityPBSLighting.cginc"
#include "UnityStandardUtils.cginc"

// A tangent frame is needed for normal maps, parallax and directional lightmaps.
#if defined(_NORMALMAP) || defined(DIRLIGHTMAP_COMBINED) || defined(_PARALLAXMAP)
#define _TANGENT_TO_WORLD 1
#endif
#if defined(_DETAIL_MULX2) || defined(_DETAIL_MUL) || defined(_DETAIL_ADD) || defined(_DETAIL_LERP)
#define _DETAIL 1
#endif

half4 _Color;
half _Cutoff;
sampler2D _MainTex;
float4 _MainTex_ST;
sampler2D _DetailAlbedoMap;
float4 _DetailAlbedoMap_ST;
sampler2D _BumpMap;
half _BumpScale;
sampler2D _DetailMask;
sampler2D _DetailNormalMap;
half _DetailNormalMapScale;
sampler2D _SpecGlossMap;
sampler2D _MetallicGlossMap;
half _Metallic;
float _Glossiness;
float _GlossMapScale;
sampler2D _OcclusionMap;
half _OcclusionStrength;
sampler2D _ParallaxMap;
half _Parallax;
half _UVSec;
half4 _EmissionColor;
sampler2D _EmissionMap;

struct VertexInput {
    float4 vertex : POSITION;
    half3 normal : NORMAL;
    float2 uv0 : TEXCOORD0;
    float2 uv1 : TEXCOORD1;
#if defined(DYNAMICLIGHTMAP_ON) || defined(UNITY_PASS_META)
    float2 uv2 : TEXCOORD2;
#endif
#ifdef _TANGENT_TO_WORLD
    half4 tangent : TANGENT;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// xy: the main UV (always UV0), zw: the detail UV (UV0 or UV1 by _UVSec).
float4 TexCoords(VertexInput v) {
    float2 detailSource = _UVSec == 0 ? v.uv0 : v.uv1;
    return float4(TRANSFORM_TEX(v.uv0, _MainTex), TRANSFORM_TEX(detailSource, _DetailAlbedoMap));
}

half DetailMask(float2 uv) {
    return tex2D(_DetailMask, uv).a;
}

// Base colour, with the detail albedo blended in by the detail mode.
half3 Albedo(float4 texcoords) {
    half3 albedo = _Color.rgb * tex2D(_MainTex, texcoords.xy).rgb;
#if _DETAIL
    half mask = SHADER_TARGET < 30 ? 1.0 : DetailMask(texcoords.xy);
    half3 detail = tex2D(_DetailAlbedoMap, texcoords.zw).rgb;
#if _DETAIL_MULX2
    albedo *= LerpWhiteTo(detail * unity_ColorSpaceDouble.rgb, mask);
#elif _DETAIL_MUL
    albedo *= LerpWhiteTo(detail, mask);
#elif _DETAIL_ADD
    albedo += detail * mask;
#elif _DETAIL_LERP
    albedo = lerp(albedo, detail, mask);
#endif
#endif
    return albedo;
}

// Alpha: the albedo texture's, unless its alpha holds the smoothness.
half Alpha(float2 uv) {
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    return _Color.a;
#else
    return tex2D(_MainTex, uv).a * _Color.a;
#endif
}

// Ambient occlusion from the map's green channel, scaled towards 1 by the strength.
half Occlusion(float2 uv) {
    half occlusion = tex2D(_OcclusionMap, uv).g;
#if SHADER_TARGET < 30
    return occlusion;
#else
    return LerpOneTo(occlusion, _OcclusionStrength);
#endif
}

// Specular workflow: rgb specular colour, a smoothness.
half4 SpecularGloss(float2 uv) {
    half4 sg;
#ifdef _SPECGLOSSMAP
    sg = tex2D(_SpecGlossMap, uv);
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    sg.a = tex2D(_MainTex, uv).a;
#endif
    sg.a *= _GlossMapScale;
#else
    sg.rgb = _SpecColor.rgb;
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    sg.a = tex2D(_MainTex, uv).a * _GlossMapScale;
#else
    sg.a = _Glossiness;
#endif
#endif
    return sg;
}

// Metallic workflow: x metallic, y smoothness.
half2 MetallicGloss(float2 uv) {
    half2 mg;
#ifdef _METALLICGLOSSMAP
    half4 map = tex2D(_MetallicGlossMap, uv);
    mg.x = map.r;
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    mg.y = tex2D(_MainTex, uv).a;
#else
    mg.y = map.a;
#endif
    mg.y *= _GlossMapScale;
#else
    mg.x = _Metallic;
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    mg.y = tex2D(_MainTex, uv).a * _GlossMapScale;
#else
    mg.y = _Glossiness;
#endif
#endif
    return mg;
}

// Roughness workflow (Autodesk Interactive): x metallic, y smoothness = 1 - roughness map.
half2 MetallicRough(float2 uv) {
    half2 mg;
#ifdef _METALLICGLOSSMAP
    mg.x = tex2D(_MetallicGlossMap, uv).r;
#else
    mg.x = _Metallic;
#endif
#ifdef _SPECGLOSSMAP
    mg.y = 1.0 - tex2D(_SpecGlossMap, uv).r;
#else
    mg.y = 1.0 - _Glossiness;
#endif
    return mg;
}

half3 Emission(float2 uv) {
#ifdef _EMISSION
    return tex2D(_EmissionMap, uv).rgb * _EmissionColor.rgb;
#else
    return 0;
#endif
}

#ifdef _NORMALMAP
// Tangent-space normal from the normal map, with the detail normal map blended in.
half3 NormalInTangentSpace(float4 texcoords) {
    half3 n = UnpackScaleNormal(tex2D(_BumpMap, texcoords.xy), _BumpScale);
#if _DETAIL && defined(UNITY_ENABLE_DETAIL_NORMALMAP)
    half mask = DetailMask(texcoords.xy);
    half3 detail = UnpackScaleNormal(tex2D(_DetailNormalMap, texcoords.zw), _DetailNormalMapScale);
#if _DETAIL_LERP
    n = lerp(n, detail, mask);
#else
    n = lerp(n, BlendNormals(n, detail), mask);
#endif
#endif
    return n;
}
#endif

// Parallax mapping: both UV sets shifted by one parallax step from the height map's green.
float4 Parallax(float4 texcoords, half3 viewDir) {
#if !defined(_PARALLAXMAP) || (SHADER_TARGET < 30)
    return texcoords;
#else
    half h = tex2D(_ParallaxMap, texcoords.xy).g;
    float2 offset = ParallaxOffset1Step(h, _Parallax, viewDir);
    return float4(texcoords.xy + offset, texcoords.zw + offset);
#endif
}

#endif  // UNITY_STANDARD_INPUT_INCLUDED
