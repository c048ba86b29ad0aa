// HLSLSupport.cginc: the spellings Unity-style shader code expects from its compiler.
// (fixed/fixedN are defined by Kiln's prelude; see docs/variants.md. half is 32-bit: glslang
// maps HLSL half to float unless 16-bit types are enabled, which Kiln does not do.)
#ifndef HLSL_SUPPORT_INCLUDED
#define HLSL_SUPPORT_INCLUDED

#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };
#define UNITY_INITIALIZE_OUTPUT(type, name) name = (type)0;
#define UNITY_BRANCH [branch]
#define UNITY_FLATTEN [flatten]
#define UNITY_UNROLL [unroll]
#define UNITY_LOOP [loop]

// Separate texture and sampler objects (DX11 style): texture NAME with sampler samplerNAME.
#define UNITY_DECLARE_TEX2D(tex) Texture2D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER(tex) Texture2D tex
#define UNITY_DECLARE_TEXCUBE(tex) TextureCube tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEXCUBE_NOSAMPLER(tex) TextureCube tex
#define UNITY_SAMPLE_TEX2D(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEX2D_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEX2D_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEXCUBE(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEXCUBE_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)

#endif  // HLSL_SUPPORT_INCLUDED
