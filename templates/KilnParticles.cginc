// KilnParticles.cginc: terms shared by the Unity-named particle files (UnityStandardParticles,
// UnityStandardParticleShadow, UnityStandardParticleEditor): flipbook frame blending, the
// particle colour modes and the soft-particle / camera fades.
#ifndef KILN_PARTICLES_INCLUDED
#define KILN_PARTICLES_INCLUDED

// _REQUIRE_UV2: the particle system streams a second flipbook frame and the blend between them.
#if _REQUIRE_UV2
#define _FLIPBOOK_BLENDING 1
#endif

// One texture read of a particle, blended between two flipbook frames when they are streamed:
// uv2AndBlend.xy is the next frame's UV, .z the blend factor.
fixed4 ParticleFlipbookSample(sampler2D tex, float2 uv, float3 uv2AndBlend) {
    fixed4 color = tex2D(tex, uv);
#ifdef _FLIPBOOK_BLENDING
    color = lerp(color, tex2D(tex, uv2AndBlend.xy), uv2AndBlend.z);
#endif
    return color;
}

// RGB <-> HSV, hue in [0, 1) (Smith 1978, "Color gamut transform pairs"), branch-free form;
// the epsilon keeps black and greys finite.
half3 RGBtoHSV(half3 rgb) {
    half4 k = half4(0.0, -1.0 / 3.0, 2.0 / 3.0, -1.0);
    half4 p = lerp(half4(rgb.bg, k.wz), half4(rgb.gb, k.xy), step(rgb.b, rgb.g));
    half4 q = lerp(half4(p.xyw, rgb.r), half4(rgb.r, p.yzx), step(p.x, rgb.r));
    half chroma = q.x - min(q.w, q.y);
    half epsilon = 1e-4;
    return half3(abs(q.z + (q.w - q.y) / (6.0 * chroma + epsilon)), chroma / (q.x + epsilon), q.x);
}
half3 HSVtoRGB(half3 hsv) {
    half3 rgb = saturate(abs(frac(hsv.xxx + half3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0);
    return hsv.z * lerp(half3(1.0, 1.0, 1.0), rgb, hsv.y);
}

// The particle colour (vertex colour) applied to the albedo by the material's colour mode:
// multiply (default), overlay, colour (hue and saturation of the particle, value of the albedo)
// or additive/subtractive/difference (addSubDiff.x: +1 add, -1 subtract; .y: 1 absolute value).
half4 ParticleColorMode(half4 albedo, half4 particleColor, half4 addSubDiff) {
#if defined(_COLOROVERLAY_ON)
    half3 screen = 1.0 - 2.0 * (1.0 - albedo.rgb) * (1.0 - particleColor.rgb);
    half3 multiply = 2.0 * albedo.rgb * particleColor.rgb;
    return half4(lerp(screen, multiply, step(albedo.rgb, 0.5)), albedo.a * particleColor.a);
#elif defined(_COLORCOLOR_ON)
    half3 hsv = half3(RGBtoHSV(particleColor.rgb).xy, RGBtoHSV(albedo.rgb).z);
    return half4(HSVtoRGB(hsv), albedo.a * particleColor.a);
#elif defined(_COLORADDSUBDIFF_ON)
    half3 rgb = albedo.rgb + particleColor.rgb * addSubDiff.x;
    return half4(lerp(rgb, abs(rgb), addSubDiff.y), albedo.a * particleColor.a);
#else
    return albedo * particleColor;
#endif
}

// Soft particles: fade where the particle nears the opaque scene behind it. fadeParams.x is
// the near fade distance, .y the reciprocal of the fade length (0 and 0: no fade).
float ParticleSoftFade(float sceneEyeDepth, float particleEyeDepth, float4 fadeParams) {
    if (fadeParams.x <= 0.0 && fadeParams.y <= 0.0) {
        return 1.0;
    }
    return saturate(fadeParams.y * ((sceneEyeDepth - fadeParams.x) - particleEyeDepth));
}

// Camera fade: transparent between the near distance and near + 1 / fadeParams.y.
float ParticleCameraFade(float particleEyeDepth, float4 fadeParams) {
    return saturate((particleEyeDepth - fadeParams.x) * fadeParams.y);
}

#endif  // KILN_PARTICLES_INCLUDED
