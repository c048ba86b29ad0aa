// UnityStandardConfig.cginc: the Standard shader's configuration switches, with Unity's names
// and desktop defaults.
#ifndef UNITY_STANDARD_CONFIG_INCLUDED
#define UNITY_STANDARD_CONFIG_INCLUDED

// The simple (per-vertex tangent space) forward variant: off on desktop shader model 3.0+.
#ifndef UNITY_STANDARD_SIMPLE
#define UNITY_STANDARD_SIMPLE 0
#endif

// Energy conservation between diffuse and specular, by the specular colour's maximum.
#ifndef UNITY_CONSERVE_ENERGY
#define UNITY_CONSERVE_ENERGY 1
#endif
#ifndef UNITY_CONSERVE_ENERGY_MONOCHROME
#define UNITY_CONSERVE_ENERGY_MONOCHROME 1
#endif

// GGX distribution (Kiln's BRDF is always GGX; the switch is kept for code that tests it).
#ifndef UNITY_BRDF_GGX
#define UNITY_BRDF_GGX 1
#endif

// Roughness to cubemap mip: perceptualRoughness (1.7 - 0.7 perceptualRoughness) x steps.
#ifndef UNITY_SPECCUBE_LOD_STEPS
#define UNITY_SPECCUBE_LOD_STEPS (6)
#endif

// Orthonormalize the interpolated tangent frame per pixel.
#ifndef UNITY_TANGENT_ORTHONORMALIZE
#define UNITY_TANGENT_ORTHONORMALIZE 0
#endif

// Ambient SH evaluated per pixel (1) or its L2 band per vertex (0).
#ifndef UNITY_SAMPLE_FULL_SH_PER_PIXEL
#define UNITY_SAMPLE_FULL_SH_PER_PIXEL 0
#endif

// Whether the fragment stage needs the world position (box projection, blending, shadows).
#if defined(UNITY_SPECCUBE_BOX_PROJECTION) || defined(UNITY_LIGHT_PROBE_PROXY_VOLUME) || \
    defined(SHADOWS_SCREEN) || defined(SHADOWS_SHADOWMASK) || defined(LIGHTMAP_SHADOW_MIXING)
#define UNITY_REQUIRE_FRAG_WORLDPOS 1
#else
#define UNITY_REQUIRE_FRAG_WORLDPOS 0
#endif
// The world position rides in the tangent frame's w components (saves an interpolator).
#ifndef UNITY_PACK_WORLDPOS_WITH_TANGENT
#define UNITY_PACK_WORLDPOS_WITH_TANGENT 1
#endif

#endif  // UNITY_STANDARD_CONFIG_INCLUDED
