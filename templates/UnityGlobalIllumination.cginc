// UnityGlobalIllumination.cginc: indirect light for the Standard lighting functions, with Unity's
// names: ambient SH (LIGHTPROBE_SH), baked and real-time lightmaps (LIGHTMAP_ON,
// DYNAMICLIGHTMAP_ON, DIRLIGHTMAP_COMBINED), the subtractive shadow mix and reflection probes
// (box projection, blending). Kiln's runtime fills the SH and binds a default probe; lightmaps
// are sampled when their keywords are on (docs/unity-compat.md).
#ifndef UNITY_GLOBAL_ILLUMINATION_INCLUDED
#define UNITY_GLOBAL_ILLUMINATION_INCLUDED

#include "UnityImageBasedLighting.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityShadowLibrary.cginc"

inline void ResetUnityLight(out UnityLight outLight) {
    outLight.color = half3(0, 0, 0);
    outLight.dir = half3(0, 1, 0);  // any unit vector
    outLight.ndotl = 0;
}
inline void ResetUnityGI(out UnityGI outGI) {
    ResetUnityLight(outGI.light);
    outGI.indirect.diffuse = 0;
    outGI.indirect.specular = 0;
}

// A directional realtime lightmap's specular light: the dominant direction as a light.
inline half3 DecodeDirectionalSpecularLightmap(half3 color, half4 dirTex, half3 normalWorld,
                                               bool isRealtimeLightmap, fixed4 realtimeNormalTex,
                                               out UnityLight o_light) {
    o_light.color = color;
    o_light.dir = SafeNormalize(dirTex.xyz * 2 - 1);
    o_light.ndotl = 0;
    // the direction's length says how directional the light is: keep that share as a light
    half directionality = max(0.001, length(dirTex.xyz * 2 - 1));
    o_light.color *= directionality;
    return color * (1 - directionality);
}

// Subtractive mixing: the main light's estimated contribution, darkened by its real-time
// shadow, is taken out of the baked lightmap (never below the shadow colour).
inline half3 SubtractMainLightWithRealtimeAttenuationFromLightmap(half3 lightmap, half attenuation,
                                                                  half4 bakedColorTex,
                                                                  half3 normalWorld) {
    half3 shadowColor = unity_ShadowColor.rgb;
    half shadowStrength = _LightShadowData.x;
    half ndotl = saturate(dot(normalWorld, _WorldSpaceLightPos0.xyz));
    half3 lightInShadow = ndotl * (1 - attenuation) * _LightColor0.rgb;
    half3 shadowed = max(lightmap - lightInShadow, shadowColor);
    shadowed = lerp(shadowed, lightmap, shadowStrength);
    return min(lightmap, shadowed);
}

// Diffuse indirect light and the attenuated pixel light.
inline UnityGI UnityGI_Base(UnityGIInput data, half occlusion, half3 normalWorld) {
    UnityGI gi;
    ResetUnityGI(gi);
#if defined(HANDLE_SHADOWS_BLENDING_IN_GI)
    half bakedAtten = UnitySampleBakedOcclusion(data.lightmapUV.xy, data.worldPos);
    float zDist = dot(_WorldSpaceCameraPos - data.worldPos, UNITY_MATRIX_V[2].xyz);
    half fade = UnityComputeShadowFade(UnityComputeShadowFadeDistance(data.worldPos, zDist));
    data.atten = UnityMixRealtimeAndBakedShadows(data.atten, bakedAtten, fade);
#endif
    gi.light = data.light;
    gi.light.color *= data.atten;
#if UNITY_SHOULD_SAMPLE_SH
    gi.indirect.diffuse = ShadeSHPerPixel(normalWorld, data.ambient, data.worldPos);
#endif
#if defined(LIGHTMAP_ON)
    half4 bakedTex = UNITY_SAMPLE_TEX2D(unity_Lightmap, data.lightmapUV.xy);
    half3 baked = DecodeLightmap(bakedTex);
#ifdef DIRLIGHTMAP_COMBINED
    fixed4 bakedDir =
        UNITY_SAMPLE_TEX2D_SAMPLER(unity_LightmapInd, unity_Lightmap, data.lightmapUV.xy);
    gi.indirect.diffuse += DecodeDirectionalLightmap(baked, bakedDir, normalWorld);
#else
    gi.indirect.diffuse += baked;
#endif
#if defined(LIGHTMAP_SHADOW_MIXING) && !defined(SHADOWS_SHADOWMASK) && defined(SHADOWS_SCREEN)
    ResetUnityLight(gi.light);
    gi.indirect.diffuse = SubtractMainLightWithRealtimeAttenuationFromLightmap(
        gi.indirect.diffuse, data.atten, bakedTex, normalWorld);
#endif
#endif
#ifdef DYNAMICLIGHTMAP_ON
    half3 realtime =
        DecodeRealtimeLightmap(UNITY_SAMPLE_TEX2D(unity_DynamicLightmap, data.lightmapUV.zw));
#ifdef DIRLIGHTMAP_COMBINED
    half4 realtimeDir = UNITY_SAMPLE_TEX2D_SAMPLER(unity_DynamicDirectionality,
                                                   unity_DynamicLightmap, data.lightmapUV.zw);
    gi.indirect.diffuse += DecodeDirectionalLightmap(realtime, realtimeDir, normalWorld);
#else
    gi.indirect.diffuse += realtime;
#endif
#endif
    gi.indirect.diffuse *= occlusion;
    return gi;
}

// Specular indirect light from the reflection probe(s), box-projected and blended.
inline half3 UnityGI_IndirectSpecular(UnityGIInput data, half occlusion,
                                      Unity_GlossyEnvironmentData glossIn) {
    half3 specular;
#ifdef UNITY_SPECCUBE_BOX_PROJECTION
    half3 reflected = glossIn.reflUVW;
    glossIn.reflUVW = BoxProjectedCubemapDirection(reflected, data.worldPos, data.probePosition[0],
                                                   data.boxMin[0], data.boxMax[0]);
#endif
#ifdef _GLOSSYREFLECTIONS_OFF
    specular = unity_IndirectSpecColor.rgb;
#else
    half3 env0 = Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(unity_SpecCube0), data.probeHDR[0],
                                         glossIn);
    specular = env0;
#ifdef UNITY_SPECCUBE_BLENDING
    // boxMin[0].w: the weight of the first probe (1 = no blend)
    float weight0 = data.boxMin[0].w;
    UNITY_BRANCH
    if (weight0 < 0.99999) {
#ifdef UNITY_SPECCUBE_BOX_PROJECTION
        glossIn.reflUVW = BoxProjectedCubemapDirection(reflected, data.worldPos,
                                                       data.probePosition[1], data.boxMin[1],
                                                       data.boxMax[1]);
#endif
        half3 env1 = Unity_GlossyEnvironment(
            UNITY_PASS_TEXCUBE_SAMPLER(unity_SpecCube1, unity_SpecCube0), data.probeHDR[1],
            glossIn);
        specular = lerp(env1, env0, weight0);
    }
#endif
#endif
    return specular * occlusion;
}
inline half3 UnityGI_IndirectSpecular(UnityGIInput data, half occlusion, half3 normalWorld,
                                      Unity_GlossyEnvironmentData glossIn) {
    return UnityGI_IndirectSpecular(data, occlusion, glossIn);
}

inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half3 normalWorld) {
    return UnityGI_Base(data, occlusion, normalWorld);
}
inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half3 normalWorld,
                                       Unity_GlossyEnvironmentData glossIn) {
    UnityGI gi = UnityGI_Base(data, occlusion, normalWorld);
    gi.indirect.specular = UnityGI_IndirectSpecular(data, occlusion, glossIn);
    return gi;
}
inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half smoothness,
                                       half3 normalWorld, bool reflections) {
    if (reflections) {
        Unity_GlossyEnvironmentData g =
            UnityGlossyEnvironmentSetup(smoothness, data.worldViewDir, normalWorld, float3(0, 0, 0));
        return UnityGlobalIllumination(data, occlusion, normalWorld, g);
    }
    return UnityGlobalIllumination(data, occlusion, normalWorld);
}
inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half smoothness,
                                       half3 normalWorld) {
    // Deferred reflections come from the reflection buffers, not from the G-buffer pass.
#if defined(UNITY_PASS_DEFERRED) && UNITY_ENABLE_REFLECTION_BUFFERS
    return UnityGlobalIllumination(data, occlusion, smoothness, normalWorld, false);
#else
    return UnityGlobalIllumination(data, occlusion, smoothness, normalWorld, true);
#endif
}

#endif  // UNITY_GLOBAL_ILLUMINATION_INCLUDED
