// UnityStandardParticles.cginc: Unity's Standard particle shaders: the unlit vertex/fragment pair
// (vertParticleUnlit / fragParticleUnlit) and the surface functions (vert / surf) of the lit
// variant. Features follow the material keywords: blend modes (_ALPHATEST_ON, _ALPHABLEND_ON,
// _ALPHAPREMULTIPLY_ON, _ALPHAMODULATE_ON), colour modes (_COLOROVERLAY_ON, _COLORCOLOR_ON,
// _COLORADDSUBDIFF_ON), _NORMALMAP, _EMISSION, _FADING_ON (camera fade), SOFTPARTICLES_ON,
// _REQUIRE_UV2 (flipbook blending) and EFFECT_BUMP (distortion of the grab-pass texture).
#ifndef UNITY_STANDARD_PARTICLES_INCLUDED
#define UNITY_STANDARD_PARTICLES_INCLUDED

#if EFFECT_BUMP
#define _DISTORTION_ON 1
#endif

#include "HLSLSupport.cginc"
#include "UnityPBSLighting.cginc"
#include "UnityStandardParticleInstancing.cginc"
#include "KilnParticles.cginc"

struct appdata_particles {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    fixed4 color : COLOR;
#if defined(_FLIPBOOK_BLENDING)
    float4 texcoords : TEXCOORD0;  // xy: this frame, zw: next frame
    float texcoordBlend : TEXCOORD1;
#else
    float2 texcoords : TEXCOORD0;
#endif
#if defined(_NORMALMAP)
    float4 tangent : TANGENT;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// Surface-function input.
struct Input {
    float4 color : COLOR;
    float2 texcoord;
#if defined(_FLIPBOOK_BLENDING)
    float3 texcoord2AndBlend;
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
    float4 projectedPosition;  // xyw: screen position, z: eye depth
#endif
#if _DISTORTION_ON
    float4 grabPassPosition;
#endif
};

// Vertex-to-fragment data of the unlit pass.
struct VertexOutput {
    float4 vertex : SV_POSITION;
    float4 color : COLOR;
    UNITY_FOG_COORDS(0)
    float2 texcoord : TEXCOORD1;
#if defined(_FLIPBOOK_BLENDING)
    float3 texcoord2AndBlend : TEXCOORD2;
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
    float4 projectedPosition : TEXCOORD3;
#endif
#if _DISTORTION_ON
    float4 grabPassPosition : TEXCOORD4;
#endif
    UNITY_VERTEX_OUTPUT_STEREO
};

sampler2D _MainTex;
float4 _MainTex_ST;
half4 _Color;
sampler2D _BumpMap;
half _BumpScale;
sampler2D _EmissionMap;
half3 _EmissionColor;
sampler2D _MetallicGlossMap;
half _Metallic;
half _Glossiness;
UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);
float4 _SoftParticleFadeParams;  // x: near fade distance, y: 1 / fade length
float4 _CameraFadeParams;        // x: near fade distance, y: 1 / fade length
half _Cutoff;
int _DstBlend;
#if _DISTORTION_ON
UNITY_DECLARE_SCREENSPACE_TEXTURE(_GrabTexture);
half _DistortionStrengthScaled;
half _DistortionBlend;
#endif
#if defined(_COLORADDSUBDIFF_ON)
half4 _ColorAddSubDiff;
#else
#define _ColorAddSubDiff half4(0.0, 0.0, 0.0, 0.0)
#endif

// The particle's texture in both flipbook frames (Unity's name).
fixed4 readTexture(sampler2D tex, Input IN) {
#if defined(_FLIPBOOK_BLENDING)
    return ParticleFlipbookSample(tex, IN.texcoord, IN.texcoord2AndBlend);
#else
    return ParticleFlipbookSample(tex, IN.texcoord, float3(0.0, 0.0, 0.0));
#endif
}
fixed4 readTexture(sampler2D tex, VertexOutput IN) {
#if defined(_FLIPBOOK_BLENDING)
    return ParticleFlipbookSample(tex, IN.texcoord, IN.texcoord2AndBlend);
#else
    return ParticleFlipbookSample(tex, IN.texcoord, float3(0.0, 0.0, 0.0));
#endif
}

// Writes the texture coordinates of a particle vertex (the flipbook frames when streamed).
#if defined(_FLIPBOOK_BLENDING)
#define KILN_PARTICLE_TEXCOORDS(v, o) \
    o.texcoord = v.texcoords.xy;      \
    o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#else
#define KILN_PARTICLE_TEXCOORDS(v, o) o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#endif

// Screen position and eye depth for the fades; grab-pass position for distortion.
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
#define KILN_PARTICLE_FADING(v, o, clipPosition)           \
    o.projectedPosition = ComputeScreenPos(clipPosition); \
    o.projectedPosition.z = -UnityObjectToViewPos(v.vertex.xyz).z;
#else
#define KILN_PARTICLE_FADING(v, o, clipPosition)
#endif
#if _DISTORTION_ON
#define KILN_PARTICLE_DISTORTION(o, clipPosition) o.grabPassPosition = ComputeGrabScreenPos(clipPosition);
#else
#define KILN_PARTICLE_DISTORTION(o, clipPosition)
#endif

// The premultiplied mode fades the whole colour; the others fade alpha.
#if defined(_ALPHAPREMULTIPLY_ON)
#define KILN_PARTICLE_FADE(albedo, fade) albedo *= (fade)
#else
#define KILN_PARTICLE_FADE(albedo, fade) albedo.a *= (fade)
#endif

// The fades of a fragment: soft particles (needs the camera depth texture) and camera fade.
#if defined(SOFTPARTICLES_ON) && defined(_FADING_ON)
#define KILN_PARTICLE_SOFT_FADE(IN)                                                                \
    ParticleSoftFade(LinearEyeDepth(SAMPLE_DEPTH_TEXTURE_PROJ(_CameraDepthTexture,                 \
                                                              UNITY_PROJ_COORD(IN.projectedPosition))), \
                     IN.projectedPosition.z, _SoftParticleFadeParams)
#else
#define KILN_PARTICLE_SOFT_FADE(IN) 1.0
#endif
#if defined(_FADING_ON)
#define KILN_PARTICLE_CAMERA_FADE(IN) ParticleCameraFade(IN.projectedPosition.z, _CameraFadeParams)
#else
#define KILN_PARTICLE_CAMERA_FADE(IN) 1.0
#endif

// Distortion: the grab-pass image behind the particle, offset along the normal map.
#if _DISTORTION_ON
#define KILN_PARTICLE_DISTORT(IN, albedo, normal)                                           \
    {                                                                                       \
        float4 grabUV = UNITY_PROJ_COORD(IN.grabPassPosition);                             \
        grabUV.xy += normal.xy * _DistortionStrengthScaled * albedo.a;                     \
        half3 behind = UNITY_SAMPLE_SCREENSPACE_TEXTURE(_GrabTexture, grabUV.xy / grabUV.w).rgb; \
        albedo.rgb = lerp(behind, albedo.rgb, saturate(albedo.a - _DistortionBlend));      \
    }
#else
#define KILN_PARTICLE_DISTORT(IN, albedo, normal)
#endif

void vert(inout appdata_particles v, out Input o) {
    UNITY_INITIALIZE_OUTPUT(Input, o);
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    KILN_PARTICLE_TEXCOORDS(v, o)
    KILN_PARTICLE_FADING(v, o, clipPosition)
    KILN_PARTICLE_DISTORTION(o, clipPosition)
}

void surf(Input IN, inout SurfaceOutputStandard o) {
    half4 albedo = ParticleColorMode(readTexture(_MainTex, IN) * _Color, IN.color, _ColorAddSubDiff);
    float softFade = KILN_PARTICLE_SOFT_FADE(IN);
    float cameraFade = KILN_PARTICLE_CAMERA_FADE(IN);
    KILN_PARTICLE_FADE(albedo, softFade * cameraFade);
#if defined(_METALLICGLOSSMAP)
    fixed2 metallicGloss = readTexture(_MetallicGlossMap, IN).ra * fixed2(1.0, _Glossiness);
#else
    fixed2 metallicGloss = fixed2(_Metallic, _Glossiness);
#endif
#if defined(_NORMALMAP)
    float3 normal = normalize(UnpackScaleNormal(readTexture(_BumpMap, IN), _BumpScale));
    o.Normal = normal;
#else
    float3 normal = float3(0.0, 0.0, 1.0);
#endif
#if defined(_EMISSION)
    half3 emission = readTexture(_EmissionMap, IN).rgb * cameraFade * softFade;
#else
    half3 emission = 0.0;
#endif
    KILN_PARTICLE_DISTORT(IN, albedo, normal)
    o.Albedo = albedo.rgb;
    o.Emission = emission * _EmissionColor;
    o.Metallic = metallicGloss.r;
    o.Smoothness = metallicGloss.g;
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON) || defined(_ALPHAOVERLAY_ON)
    o.Alpha = albedo.a;
#else
    o.Alpha = 1.0;
#endif
#if defined(_ALPHAMODULATE_ON)
    o.Albedo = lerp(half3(1.0, 1.0, 1.0), albedo.rgb, albedo.a);
#endif
#if defined(_ALPHATEST_ON)
    clip(albedo.a - _Cutoff + 0.0001);
#endif
}

void vertParticleUnlit(appdata_particles v, out VertexOutput o) {
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    o.vertex = clipPosition;
    o.color = v.color;
    KILN_PARTICLE_TEXCOORDS(v, o)
    KILN_PARTICLE_FADING(v, o, clipPosition)
    KILN_PARTICLE_DISTORTION(o, clipPosition)
    UNITY_TRANSFER_FOG(o, o.vertex);
}

half4 fragParticleUnlit(VertexOutput IN) : SV_Target {
    UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(IN);
    half4 albedo = ParticleColorMode(readTexture(_MainTex, IN) * _Color, IN.color, _ColorAddSubDiff);
    float softFade = KILN_PARTICLE_SOFT_FADE(IN);
    float cameraFade = KILN_PARTICLE_CAMERA_FADE(IN);
    KILN_PARTICLE_FADE(albedo, softFade * cameraFade);
#if defined(_NORMALMAP)
    float3 normal = normalize(UnpackScaleNormal(readTexture(_BumpMap, IN), _BumpScale));
#else
    float3 normal = float3(0.0, 0.0, 1.0);
#endif
#if defined(_EMISSION)
    half3 emission = readTexture(_EmissionMap, IN).rgb;
#else
    half3 emission = 0.0;
#endif
    KILN_PARTICLE_DISTORT(IN, albedo, normal)

    half4 result = albedo;
#if defined(_ALPHAMODULATE_ON)
    result.rgb = lerp(half3(1.0, 1.0, 1.0), albedo.rgb, albedo.a);
#endif
    result.rgb += emission * _EmissionColor * cameraFade * softFade;
#if !defined(_ALPHABLEND_ON) && !defined(_ALPHAPREMULTIPLY_ON) && !defined(_ALPHAOVERLAY_ON)
    result.a = 1.0;
#endif
#if defined(_ALPHATEST_ON)
    clip(albedo.a - _Cutoff + 0.0001);
#endif
    // Fog towards the colour that leaves the framebuffer unchanged under the blend mode.
#if defined(_ALPHAMODULATE_ON)
    UNITY_APPLY_FOG_COLOR(IN.fogCoord, result, fixed4(1.0, 1.0, 1.0, 0.0));  // multiplicative
#elif !defined(_ALPHATEST_ON) && defined(_ALPHABLEND_ON) && !defined(_ALPHAPREMULTIPLY_ON)
    if (_DstBlend == 1) {
        UNITY_APPLY_FOG_COLOR(IN.fogCoord, result, fixed4(0.0, 0.0, 0.0, 0.0));  // additive
    } else {
        UNITY_APPLY_FOG(IN.fogCoord, result);
    }
#else
    UNITY_APPLY_FOG(IN.fogCoord, result);
#endif
    return result;
}

#endif  // UNITY_STANDARD_PARTICLES_INCLUDED
