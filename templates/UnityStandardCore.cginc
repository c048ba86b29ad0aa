// UnityStandardCore.cginc: the Standard shader's forward (base and additive) and deferred
// programs with Unity's names, over Kiln's BRDF (UnityStandardBRDF.cginc) and global
// illumination (UnityGlobalIllumination.cginc). The BRDF input comes from the workflow function
// UNITY_SETUP_BRDF_INPUT names: MetallicSetup (the default), SpecularSetup or RoughnessSetup.
#ifndef UNITY_STANDARD_CORE_INCLUDED
#define UNITY_STANDARD_CORE_INCLUDED

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardInput.cginc"
#include "UnityPBSLighting.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityGBuffer.cginc"
#include "UnityStandardBRDF.cginc"
#include "AutoLight.cginc"

// ---- per-pixel frame ----
half3 NormalizePerVertexNormal(float3 n) {
#if (SHADER_TARGET < 30) || UNITY_STANDARD_SIMPLE
    return SafeNormalize(n);
#else
    return n;  // normalized per pixel
#endif
}
float3 NormalizePerPixelNormal(float3 n) {
#if (SHADER_TARGET < 30) || UNITY_STANDARD_SIMPLE
    return n;
#else
    return SafeNormalize(n);
#endif
}

// World normal: from the normal map through the interpolated tangent frame (rows tangent,
// binormal, normal), or the interpolated normal.
float3 PerPixelWorldNormal(float4 i_tex, float4 tangentToWorld[3]) {
#ifdef _NORMALMAP
    half3 tangent = tangentToWorld[0].xyz;
    half3 binormal = tangentToWorld[1].xyz;
    half3 normal = tangentToWorld[2].xyz;
#if UNITY_TANGENT_ORTHONORMALIZE
    normal = NormalizePerPixelNormal(normal);
    tangent = SafeNormalize(tangent - normal * dot(tangent, normal));
    half3 newBinormal = cross(normal, tangent);
    binormal = newBinormal * sign(dot(newBinormal, binormal));
#endif
    half3 normalTangent = NormalInTangentSpace(i_tex);
    return NormalizePerPixelNormal(tangent * normalTangent.x + binormal * normalTangent.y +
                                   normal * normalTangent.z);
#else
    return SafeNormalize(tangentToWorld[2].xyz);
#endif
}

#ifdef _PARALLAXMAP
#define IN_VIEWDIR4PARALLAX(i) \
    NormalizePerPixelNormal(half3(i.tangentToWorldAndPackedData[0].w, \
                                  i.tangentToWorldAndPackedData[1].w, \
                                  i.tangentToWorldAndPackedData[2].w))
#define IN_VIEWDIR4PARALLAX_FWDADD(i) NormalizePerPixelNormal(i.viewDirForParallax.xyz)
#else
#define IN_VIEWDIR4PARALLAX(i) half3(0, 0, 0)
#define IN_VIEWDIR4PARALLAX_FWDADD(i) half3(0, 0, 0)
#endif

#if UNITY_REQUIRE_FRAG_WORLDPOS
#if UNITY_PACK_WORLDPOS_WITH_TANGENT
#define IN_WORLDPOS(i) \
    half3(i.tangentToWorldAndPackedData[0].w, i.tangentToWorldAndPackedData[1].w, \
          i.tangentToWorldAndPackedData[2].w)
#else
#define IN_WORLDPOS(i) i.posWorld
#endif
#else
#define IN_WORLDPOS(i) half3(0, 0, 0)
#endif
#define IN_WORLDPOS_FWDADD(i) i.posWorld
#define IN_LIGHTDIR_FWDADD(i) \
    half3(i.tangentToWorldAndLightDir[0].w, i.tangentToWorldAndLightDir[1].w, \
          i.tangentToWorldAndLightDir[2].w)

#define FRAGMENT_SETUP(x) \
    FragmentCommonData x = FragmentSetup(i.tex, i.eyeVec.xyz, IN_VIEWDIR4PARALLAX(i), \
                                         i.tangentToWorldAndPackedData, IN_WORLDPOS(i));
#define FRAGMENT_SETUP_FWDADD(x) \
    FragmentCommonData x = FragmentSetup(i.tex, i.eyeVec.xyz, IN_VIEWDIR4PARALLAX_FWDADD(i), \
                                         i.tangentToWorldAndLightDir, IN_WORLDPOS_FWDADD(i));

// ---- lights ----
UnityLight MainLight() {
    UnityLight l;
    l.color = _LightColor0.rgb;
    l.dir = _WorldSpaceLightPos0.xyz;
    l.ndotl = 0;
    return l;
}
UnityLight AdditiveLight(half3 lightDir, half atten) {
    UnityLight l;
    l.color = _LightColor0.rgb * atten;
    l.dir = NormalizePerPixelNormal(lightDir);
    l.ndotl = 0;
    return l;
}
UnityLight DummyLight() {
    UnityLight l;
    l.color = 0;
    l.dir = half3(0, 1, 0);
    l.ndotl = 0;
    return l;
}
UnityIndirect ZeroIndirect() {
    UnityIndirect ind;
    ind.diffuse = 0;
    ind.specular = 0;
    return ind;
}

// ---- the surface at a pixel ----
struct FragmentCommonData {
    half3 diffColor, specColor;
    // Diffuse weight and perceptual smoothness; the BRDFs derive roughness from smoothness.
    half oneMinusReflectivity, smoothness;
    float3 normalWorld;
    float3 eyeVec;  // camera to surface, normalized
    half alpha;
    float3 posWorld;
#if UNITY_STANDARD_SIMPLE
    half3 reflUVW;
    half3 tangentSpaceNormal;
#endif
};

#ifndef UNITY_SETUP_BRDF_INPUT
#define UNITY_SETUP_BRDF_INPUT MetallicSetup
#endif

// Specular workflow: specular colour and smoothness from SpecularGloss, energy-conserving
// diffuse.
inline FragmentCommonData SpecularSetup(float4 i_tex) {
    half4 specGloss = SpecularGloss(i_tex.xy);
    FragmentCommonData o = (FragmentCommonData)0;
    o.diffColor = EnergyConservationBetweenDiffuseAndSpecular(Albedo(i_tex), specGloss.rgb,
                                                              o.oneMinusReflectivity);
    o.specColor = specGloss.rgb;
    o.smoothness = specGloss.a;
    return o;
}
// Metallic workflow with a roughness map (Autodesk Interactive).
inline FragmentCommonData RoughnessSetup(float4 i_tex) {
    half2 metallicGloss = MetallicRough(i_tex.xy);
    FragmentCommonData o = (FragmentCommonData)0;
    o.diffColor = DiffuseAndSpecularFromMetallic(Albedo(i_tex), metallicGloss.x, o.specColor,
                                                 o.oneMinusReflectivity);
    o.smoothness = metallicGloss.y;
    return o;
}
// Metallic workflow (Standard.shader).
inline FragmentCommonData MetallicSetup(float4 i_tex) {
    half2 metallicGloss = MetallicGloss(i_tex.xy);
    FragmentCommonData o = (FragmentCommonData)0;
    o.diffColor = DiffuseAndSpecularFromMetallic(Albedo(i_tex), metallicGloss.x, o.specColor,
                                                 o.oneMinusReflectivity);
    o.smoothness = metallicGloss.y;
    return o;
}

// Parallax, alpha test, the workflow's BRDF input, the world normal and premultiplied alpha.
inline FragmentCommonData FragmentSetup(inout float4 i_tex, float3 i_eyeVec,
                                        half3 i_viewDirForParallax, float4 tangentToWorld[3],
                                        float3 i_posWorld) {
    i_tex = Parallax(i_tex, i_viewDirForParallax);
    half alpha = Alpha(i_tex.xy);
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
#endif
    FragmentCommonData o = UNITY_SETUP_BRDF_INPUT(i_tex);
    o.normalWorld = PerPixelWorldNormal(i_tex, tangentToWorld);
    o.eyeVec = NormalizePerPixelNormal(i_eyeVec);
    o.posWorld = i_posWorld;
    o.diffColor = PreMultiplyAlpha(o.diffColor, alpha, o.oneMinusReflectivity, o.alpha);
    return o;
}

// The GI input of the pixel light and the probes, and the GI it yields.
inline UnityGI FragmentGI(FragmentCommonData s, half occlusion, half4 i_ambientOrLightmapUV,
                          half atten, UnityLight light, bool reflections) {
    UnityGIInput d;
    d.light = light;
    d.worldPos = s.posWorld;
    d.worldViewDir = -s.eyeVec;
    d.atten = atten;
#if defined(LIGHTMAP_ON) || defined(DYNAMICLIGHTMAP_ON)
    d.ambient = 0;
    d.lightmapUV = i_ambientOrLightmapUV;
#else
    d.ambient = i_ambientOrLightmapUV.rgb;
    d.lightmapUV = 0;
#endif
    d.probeHDR[0] = unity_SpecCube0_HDR;
    d.probeHDR[1] = unity_SpecCube1_HDR;
#if defined(UNITY_SPECCUBE_BLENDING) || defined(UNITY_SPECCUBE_BOX_PROJECTION)
    d.boxMin[0] = unity_SpecCube0_BoxMin;  // w: the blend weight of the first probe
#endif
#ifdef UNITY_SPECCUBE_BOX_PROJECTION
    d.boxMax[0] = unity_SpecCube0_BoxMax;
    d.probePosition[0] = unity_SpecCube0_ProbePosition;
    d.boxMax[1] = unity_SpecCube1_BoxMax;
    d.boxMin[1] = unity_SpecCube1_BoxMin;
    d.probePosition[1] = unity_SpecCube1_ProbePosition;
#endif
    if (reflections) {
        Unity_GlossyEnvironmentData g =
            UnityGlossyEnvironmentSetup(s.smoothness, -s.eyeVec, s.normalWorld, s.specColor);
#if UNITY_STANDARD_SIMPLE
        g.reflUVW = s.reflUVW;
#endif
        return UnityGlobalIllumination(d, occlusion, s.normalWorld, g);
    }
    return UnityGlobalIllumination(d, occlusion, s.normalWorld);
}
inline UnityGI FragmentGI(FragmentCommonData s, half occlusion, half4 i_ambientOrLightmapUV,
                          half atten, UnityLight light) {
    return FragmentGI(s, occlusion, i_ambientOrLightmapUV, atten, light, true);
}

// Alpha out of the forward passes: only blended modes keep it.
half4 OutputForward(half4 output, half alphaFromSurface) {
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
    output.a = alphaFromSurface;
#else
    UNITY_OPAQUE_ALPHA(output.a);
#endif
    return output;
}

// Vertex part of the indirect light: lightmap UVs, or vertex lights plus the SH L2 band.
inline half4 VertexGIForward(VertexInput v, float3 posWorld, half3 normalWorld) {
    half4 ambientOrLightmapUV = 0;
#ifdef LIGHTMAP_ON
    ambientOrLightmapUV.xy = v.uv1.xy * unity_LightmapST.xy + unity_LightmapST.zw;
#elif UNITY_SHOULD_SAMPLE_SH
#ifdef VERTEXLIGHT_ON
    ambientOrLightmapUV.rgb = Shade4PointLights(
        unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0, unity_LightColor[0].rgb,
        unity_LightColor[1].rgb, unity_LightColor[2].rgb, unity_LightColor[3].rgb,
        unity_4LightAtten0, posWorld, normalWorld);
#endif
    ambientOrLightmapUV.rgb = ShadeSHPerVertex(normalWorld, ambientOrLightmapUV.rgb);
#endif
#ifdef DYNAMICLIGHTMAP_ON
    ambientOrLightmapUV.zw = v.uv2.xy * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;
#endif
    return ambientOrLightmapUV;
}

// The tangent frame rows (or the normal alone) into three interpolators' xyz.
void WriteTangentFrame(VertexInput v, float3 normalWorld, out float4 rows[3]) {
    rows[0] = 0;
    rows[1] = 0;
    rows[2] = 0;
#ifdef _TANGENT_TO_WORLD
    float3x3 frame = CreateTangentToWorldPerVertex(normalWorld, UnityObjectToWorldDir(v.tangent.xyz),
                                                   v.tangent.w);
    rows[0].xyz = frame[0];
    rows[1].xyz = frame[1];
    rows[2].xyz = frame[2];
#else
    rows[2].xyz = normalWorld;
#endif
}

#include "UnityStandardCorePasses.cginc"

#endif  // UNITY_STANDARD_CORE_INCLUDED
