// AutoLight.cginc: attenuation and shadows of the pass's pixel light, with Unity's macro names.
// The light type comes from the keyword of `#pragma multi_compile DIRECTIONAL POINT SPOT` (or the
// multi_compile_fwdadd shortcuts); none means directional.
//   DIRECTIONAL            1
//   POINT                  inverse square x smooth range window (KilnAttenuation.cginc)
//   SPOT                   the same x the spot cone
// from _WorldSpaceLightPos0, kiln_SpotDirection0 and kiln_LightParams0: Kiln's physical light
// units instead of Unity's attenuation textures (docs/shader-library.md). Kiln has no light
// cookies: POINT_COOKIE and DIRECTIONAL_COOKIE behave as POINT and DIRECTIONAL. Shadows: the
// SHADOWS_* variants sample the maps the runtime renders from ShadowCaster passes
// (UnityShadowLibrary.cginc; SHADOWS_SCREEN: the screen-space shadow texture of the pass's
// directional light); every other variant is unshadowed (attenuation 1). UNITY_LIGHT_ATTENUATION
// needs only the world position: with input 0 (no shadow coordinates interpolated) it projects
// the position itself.
#ifndef AUTOLIGHT_INCLUDED
#define AUTOLIGHT_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityShadowLibrary.cginc"
#include "KilnAttenuation.cginc"

#if !defined(POINT) && !defined(SPOT) && !defined(DIRECTIONAL) && !defined(POINT_COOKIE) && \
    !defined(DIRECTIONAL_COOKIE)
#define DIRECTIONAL 1
#endif

// ---- shadows ----
#if defined(SHADOWS_SCREEN)
UNITY_DECLARE_SCREENSPACE_SHADOWMAP(_ShadowMapTexture);
// The screen-space shadow texture, read at the pixel's projected screen position.
inline fixed unitySampleShadow(unityShadowCoord4 shadowCoord) {
    return UNITY_SAMPLE_SCREEN_SHADOW(_ShadowMapTexture, shadowCoord);
}
#define SHADOW_COORDS(idx1) unityShadowCoord4 _ShadowCoord : TEXCOORD##idx1;
#define TRANSFER_SHADOW(a) a._ShadowCoord = ComputeScreenPos(a.pos);
#define TRANSFER_SHADOW_WPOS(a, wpos) a._ShadowCoord = ComputeScreenPos(a.pos);
#define SHADOW_ATTENUATION(a) unitySampleShadow(a._ShadowCoord)
#elif defined(SHADOWS_DEPTH) && defined(SPOT)
#define SHADOW_COORDS(idx1) unityShadowCoord4 _ShadowCoord : TEXCOORD##idx1;
#define TRANSFER_SHADOW(a) \
    a._ShadowCoord = mul(unity_WorldToShadow[0], mul(unity_ObjectToWorld, v.vertex));
#define TRANSFER_SHADOW_WPOS(a, wpos) \
    a._ShadowCoord = mul(unity_WorldToShadow[0], float4((wpos).xyz, 1.0));
#define SHADOW_ATTENUATION(a) UnitySampleShadowmap(a._ShadowCoord)
#elif defined(SHADOWS_CUBE)
#define SHADOW_COORDS(idx1) unityShadowCoord3 _ShadowCoord : TEXCOORD##idx1;
#define TRANSFER_SHADOW(a) \
    a._ShadowCoord.xyz = mul(unity_ObjectToWorld, v.vertex).xyz - _LightPositionRange.xyz;
#define TRANSFER_SHADOW_WPOS(a, wpos) a._ShadowCoord.xyz = (wpos).xyz - _LightPositionRange.xyz;
#define SHADOW_ATTENUATION(a) UnitySampleShadowmap(a._ShadowCoord)
#else
#define SHADOW_COORDS(idx1)
#define TRANSFER_SHADOW(a)
#define TRANSFER_SHADOW_WPOS(a, wpos)
#define SHADOW_ATTENUATION(a) 1.0
#endif
#define READ_SHADOW_COORDS(a) 0
#define UNITY_READ_SHADOW_COORDS(input) 0
#define UNITY_SHADOW_W(_w) _w

// The real-time shadow of the pass's light at a world position: the screen-space shadow at the
// position's pixel (SHADOWS_SCREEN), the spot light's depth map (SHADOWS_DEPTH) or the point
// light's depth cube (SHADOWS_CUBE); 1 without a shadow variant.
half UnityRealtimeShadowAt(float3 worldPos) {
#if defined(SHADOWS_SCREEN)
    return unitySampleShadow(ComputeScreenPos(mul(UNITY_MATRIX_VP, float4(worldPos, 1.0))));
#elif defined(SHADOWS_DEPTH) && defined(SPOT)
    return UnitySampleShadowmap(mul(unity_WorldToShadow[0], float4(worldPos, 1.0)));
#elif defined(SHADOWS_CUBE)
    return UnitySampleShadowmap(worldPos - _LightPositionRange.xyz);
#else
    return 1.0;
#endif
}

// The fade of real-time shadows with distance from the camera (_LightShadowData.zw).
half UnityShadowFadeAt(float3 worldPos) {
    float zDist = dot(_WorldSpaceCameraPos - worldPos, UNITY_MATRIX_V[2].xyz);
    return UnityComputeShadowFade(UnityComputeShadowFadeDistance(worldPos, zDist));
}

// Unity's forward-pass shadow with the real-time / baked blend: SHADOWS_SCREEN reads the screen
// position the vertex stage interpolated, the others the world position.
half UnityComputeForwardShadows(float2 lightmapUV, float3 worldPos, float4 screenPos) {
    half baked = UnitySampleBakedOcclusion(lightmapUV, worldPos);
#if defined(SHADOWS_SCREEN)
    half realtime = unitySampleShadow(screenPos);
#else
    half realtime = UnityRealtimeShadowAt(worldPos);
#endif
    return UnityMixRealtimeAndBakedShadows(realtime, baked, UnityShadowFadeAt(worldPos));
}

// The same from the world position alone (UNITY_SHADOW_ATTENUATION's, Kiln's).
half UnityShadowAttenuationAt(float3 worldPos) {
    return UnityMixRealtimeAndBakedShadows(UnityRealtimeShadowAt(worldPos),
                                           UnitySampleBakedOcclusion(0, worldPos),
                                           UnityShadowFadeAt(worldPos));
}

#define UNITY_SHADOW_COORDS(idx1) SHADOW_COORDS(idx1)
#define UNITY_TRANSFER_SHADOW(a, coord) TRANSFER_SHADOW(a)
#define UNITY_SHADOW_ATTENUATION(a, worldPos) UnityShadowAttenuationAt((worldPos).xyz)

// ---- light attenuation ----
// Attenuation of the pass's pixel light at a world position, by light type.
float UnityLightAttenuation(float3 worldPos) {
#if defined(POINT) || defined(SPOT) || defined(POINT_COOKIE)
    float3 toLight = _WorldSpaceLightPos0.xyz - worldPos;
    float distanceSq = dot(toLight, toLight);
    float atten = Attenuation_Distance(distanceSq, kiln_LightParams0.x);
#if defined(SPOT)
    atten *= Attenuation_SpotCone(SafeNormalize(toLight), kiln_SpotDirection0.xyz,
                                  kiln_LightParams0.y, kiln_LightParams0.z);
#endif
    return atten;
#else
    return 1.0;
#endif
}

// Unity's cookie and falloff textures for spot lights (Kiln binds white: no cookie).
sampler2D_float _LightTexture0;
sampler2D_float _LightTextureB0;
inline fixed UnitySpotCookie(unityShadowCoord4 lightCoord) {
    // guard: w = 0 behind the spot's plane
    return tex2D(_LightTexture0, lightCoord.xy / max(abs(lightCoord.w), 1e-7) + 0.5).w;
}
inline fixed UnitySpotAttenuate(unityShadowCoord3 lightCoord) {
    return tex2D(_LightTextureB0, dot(lightCoord, lightCoord).xx).r;
}

// Interpolated light coordinates: Kiln interpolates the world position, from which
// LIGHT_ATTENUATION computes the physical falloff.
#if defined(POINT) || defined(SPOT) || defined(POINT_COOKIE) || defined(DIRECTIONAL_COOKIE)
#define DECLARE_LIGHT_COORDS(idx) float3 _LightCoord : TEXCOORD##idx;
#define COMPUTE_LIGHT_COORDS(a) a._LightCoord = mul(unity_ObjectToWorld, v.vertex).xyz;
#define LIGHT_ATTENUATION(a) (UnityLightAttenuation(a._LightCoord) * SHADOW_ATTENUATION(a))
#else
#define DECLARE_LIGHT_COORDS(idx)
#define COMPUTE_LIGHT_COORDS(a)
#define LIGHT_ATTENUATION(a) SHADOW_ATTENUATION(a)
#endif
#define DECLARE_LIGHT_COORD(input, worldPos) float3 lightCoord = (worldPos).xyz

#define LIGHTING_COORDS(idx1, idx2) DECLARE_LIGHT_COORDS(idx1) SHADOW_COORDS(idx2)
#define TRANSFER_VERTEX_TO_FRAGMENT(a) COMPUTE_LIGHT_COORDS(a) TRANSFER_SHADOW(a)
#define UNITY_LIGHTING_COORDS(idx1, idx2) DECLARE_LIGHT_COORDS(idx1) UNITY_SHADOW_COORDS(idx2)
#define UNITY_TRANSFER_LIGHTING(a, coord) COMPUTE_LIGHT_COORDS(a) UNITY_TRANSFER_SHADOW(a, coord)

// Declares `float destName` = the light's attenuation at worldPos times the shadow term.
// worldPos may be a float3 or a float4 (the lecture passes its float4 world position). Ends in
// `;` as Unity's does, so code that writes the macro without one (which Unity accepts) compiles.
#define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) \
    float destName = UnityLightAttenuation((worldPos).xyz) * UNITY_SHADOW_ATTENUATION(input, worldPos);

#endif  // AUTOLIGHT_INCLUDED
