// UnityStandardParticleInstancing.cginc: the hooks Unity's particle shaders call for GPU-instanced
// mesh particles (`#pragma instancing_options procedural:vertInstancingSetup`). Kiln draws
// particles non-instanced (its UnityInstancing never defines UNITY_PROCEDURAL_INSTANCING_ENABLED,
// so UNITY_PARTICLE_INSTANCING_ENABLED stays undefined): each particle's transform, colour and
// flipbook UVs arrive through the ordinary per-draw constants and vertex streams, and the hooks
// leave their arguments as the vertex provides them.
#ifndef UNITY_STANDARD_PARTICLE_INSTANCING_INCLUDED
#define UNITY_STANDARD_PARTICLE_INSTANCING_INCLUDED

// Per-instance transform: none, unity_ObjectToWorld already holds the particle's.
void vertInstancingSetup() {}

// Per-instance tint: none, the vertex colour is the particle colour.
void vertInstancingColor(inout fixed4 color) {}

// Flipbook frame UVs: the vertex stream already carries them (no blending between frames).
void vertInstancingUVs(in float2 uv, out float2 texcoord, out float3 texcoord2AndBlend) {
    texcoord = uv;
    texcoord2AndBlend = float3(uv, 0.0);
}
void vertInstancingUVs(in float2 uv, out float2 texcoord) {
    texcoord = uv;
}

#endif  // UNITY_STANDARD_PARTICLE_INSTANCING_INCLUDED
