// HLSLSupport.cginc: the spellings Unity-style shader code expects from its compiler, for Kiln's
// target (Vulkan through glslang, desktop precision). Unity includes this file in front of every
// CGPROGRAM; so does Kiln (docs/unity-compat.md). Names follow Unity's HLSLSupport.cginc.
#ifndef HLSL_SUPPORT_INCLUDED
#define HLSL_SUPPORT_INCLUDED

// kiln stability --strict: undefined operations as NaN, before any other code (KilnStrictMath)
#if defined(KILN_STRICT_POW) || defined(KILN_STRICT_NORMALIZE)
#include "KilnStrictMath.cginc"
#endif

#define UNITY_COMPILER_HLSL
#define UNITY_COMPILER_HLSLCC

// ---- precision (kiln compile --precision, docs/unity-compat.md) ----
// full (the default): desktop Vulkan as Unity defines it there, fixed and half are 32-bit.
// relaxed and half: fixed and half are min16float, RelaxedPrecision in SPIR-V, as Unity's Vulkan
// back end emits them for mobile; with half, that arithmetic is then binary16 on the device.
// glslang has no min16float matrices, so half and fixed matrices stay 32-bit.
#if defined(KILN_PRECISION_RELAXED)
#define fixed min16float
#define fixed2 min16float2
#define fixed3 min16float3
#define fixed4 min16float4
#define half min16float
#define half2 min16float2
#define half3 min16float3
#define half4 min16float4
#else
#define fixed float
#define fixed2 float2
#define fixed3 float3
#define fixed4 float4
#define half float
#define half2 float2
#define half3 float3
#define half4 float4
#endif
#define fixed4x4 float4x4
#define fixed3x3 float3x3
#define fixed2x2 float2x2
#define half2x2 float2x2
#define half3x3 float3x3
#define half4x4 float4x4

// ---- capabilities of the target ----
#define UNITY_SUPPORT_DEPTH_FETCH 1
#define UNITY_ALLOWED_MRT_COUNT 8
#if SHADER_TARGET >= 30
#define UNITY_FAST_COHERENT_DYNAMIC_BRANCHING 1
#endif
#define UNITY_SM40_PLUS_PLATFORM (!(SHADER_TARGET < 30))
#define UNITY_CAN_COMPILE_TESSELLATION 1
#define SHADOWS_NATIVE
#define UNITY_SEPARATE_TEXTURE_SAMPLER
// Kiln's runtime renders with depth 0 at the near plane (no reversed Z) and flips y through the
// viewport, so clip space is OpenGL-like with z in [0, 1]: UNITY_REVERSED_Z and
// UNITY_UV_STARTS_AT_TOP stay undefined (docs/unity-compat.md).
#define UNITY_NEAR_CLIP_VALUE (0.0)

// ---- cbuffers: real uniform blocks (Kiln binds them by name, docs/binding-model.md) ----
#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };
#define GLOBAL_CBUFFER_START(name) CBUFFER_START(name)
#define GLOBAL_CBUFFER_END CBUFFER_END
#define CBUFFER_START_WITH_BINDING(name, set, binding) CBUFFER_START(name)
#define DECL_WITH_BINDING(type, name, set, binding) type name
#define SAMPLER_UNIFORM
#define UNITY_REQUIRE_ADVANCED_BLEND(mode)

// ---- semantics and attributes ----
#define UNITY_POSITION(pos) float4 pos : SV_POSITION
#define UNITY_VPOS_TYPE float4
#define WPOS VPOS
#define UNITY_INITIALIZE_OUTPUT(type, name) name = (type)0;
#define UNITY_BRANCH [branch]
#define UNITY_FLATTEN [flatten]
#define UNITY_UNROLL [unroll]
#define UNITY_LOOP [loop]
#define UNITY_FASTOPT
#define UNITY_PROJ_COORD(a) a
#define UNITY_ATTEN_CHANNEL r
#define UNITY_ALPHA_CHANNEL a
#define UNITY_SAMPLE_1CHANNEL(x, y) tex2D(x, y).a
#define UNITY_domain domain
#define UNITY_partitioning partitioning
#define UNITY_outputtopology outputtopology
#define UNITY_patchconstantfunc patchconstantfunc
#define UNITY_outputcontrolpoints outputcontrolpoints

// ---- legacy sampler spellings ----
#define samplerRECT sampler2D
#define texRECT tex2D
#define texRECTlod tex2Dlod
#define texRECTbias tex2Dbias
#define texRECTproj tex2Dproj
#define SampleCubeReflection(env, dir, lod) UNITY_SAMPLE_TEXCUBE_LOD(env, dir, lod)

// ---- depth textures: the depth is in the red channel ----
#define UNITY_DECLARE_DEPTH_TEXTURE_MS(tex) Texture2DMS<float> tex;
#define UNITY_DECLARE_DEPTH_TEXTURE(tex) sampler2D_float tex
#define SAMPLE_DEPTH_TEXTURE(sampler, uv) (tex2D(sampler, uv).r)
#define SAMPLE_DEPTH_TEXTURE_PROJ(sampler, uv) (tex2Dproj(sampler, uv).r)
#define SAMPLE_DEPTH_TEXTURE_LOD(sampler, uv) (tex2Dlod(sampler, uv).r)
#define SAMPLE_RAW_DEPTH_TEXTURE(sampler, uv) (tex2D(sampler, uv))
#define SAMPLE_RAW_DEPTH_TEXTURE_PROJ(sampler, uv) (tex2Dproj(sampler, uv))
#define SAMPLE_RAW_DEPTH_TEXTURE_LOD(sampler, uv) (tex2Dlod(sampler, uv))
#define SAMPLE_DEPTH_CUBE_TEXTURE(sampler, uv) (texCUBE(sampler, uv).r)
#define UNITY_SAMPLE_DEPTH(value) (value).r

// ---- shadow maps: comparison samplers ----
#define UNITY_DECLARE_SHADOWMAP(tex) Texture2D tex; SamplerComparisonState sampler##tex
#define UNITY_DECLARE_TEXCUBE_SHADOWMAP(tex) TextureCube tex; SamplerComparisonState sampler##tex
#define UNITY_SAMPLE_SHADOW(tex, coord) tex.SampleCmpLevelZero(sampler##tex, (coord).xy, (coord).z)
#define UNITY_SAMPLE_SHADOW_PROJ(tex, coord) \
    tex.SampleCmpLevelZero(sampler##tex, (coord).xy / (coord).w, (coord).z / (coord).w)
#define UNITY_SAMPLE_TEXCUBE_SHADOW(tex, coord) tex.SampleCmp(sampler##tex, (coord).xyz, (coord).w)

// ---- separate textures and samplers (DX11 style): texture NAME, sampler samplerNAME ----
#define UNITY_DECLARE_TEX2D(tex) Texture2D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER(tex) Texture2D tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_INT(tex) Texture2D<int4> tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_UINT(tex) Texture2D<uint4> tex
#define UNITY_DECLARE_TEX2D_HALF(tex) Texture2D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2D_FLOAT(tex) Texture2D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_HALF(tex) Texture2D tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_FLOAT(tex) Texture2D tex
#define UNITY_SAMPLE_TEX2D(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEX2D_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEX2D_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEX2D_SAMPLER_LOD(tex, samplertex, coord, lod) \
    tex.SampleLevel(sampler##samplertex, coord, lod)

#define UNITY_DECLARE_TEXCUBE(tex) TextureCube tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEXCUBE_NOSAMPLER(tex) TextureCube tex
#define UNITY_ARGS_TEXCUBE(tex) TextureCube tex, SamplerState sampler##tex
#define UNITY_PASS_TEXCUBE(tex) tex, sampler##tex
#define UNITY_PASS_TEXCUBE_SAMPLER(tex, samplertex) tex, sampler##samplertex
#define UNITY_PASS_TEXCUBE_SAMPLER_LOD(tex, samplertex, lod) tex, sampler##samplertex, lod
#define UNITY_ARGS_TEXCUBE_NOSAMPLER(tex) TextureCube tex
#define UNITY_PASS_TEXCUBE_NOSAMPLER(tex) tex
#define UNITY_SAMPLE_TEXCUBE(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEXCUBE_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEXCUBE_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEXCUBE_SAMPLER_LOD(tex, samplertex, coord, lod) \
    tex.SampleLevel(sampler##samplertex, coord, lod)

#define UNITY_DECLARE_TEX3D(tex) Texture3D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX3D_NOSAMPLER(tex) Texture3D tex
#define UNITY_DECLARE_TEX3D_FLOAT(tex) Texture3D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX3D_HALF(tex) Texture3D tex; SamplerState sampler##tex
#define UNITY_SAMPLE_TEX3D(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEX3D_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEX3D_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEX3D_SAMPLER_LOD(tex, samplertex, coord, lod) \
    tex.SampleLevel(sampler##samplertex, coord, lod)

#define UNITY_DECLARE_TEX2DARRAY_MS(tex) Texture2DMSArray<float> tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2DARRAY_MS_NOSAMPLER(tex) Texture2DArray<float> tex
#define UNITY_DECLARE_TEX2DARRAY(tex) Texture2DArray tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2DARRAY_NOSAMPLER(tex) Texture2DArray tex
#define UNITY_ARGS_TEX2DARRAY(tex) Texture2DArray tex, SamplerState sampler##tex
#define UNITY_PASS_TEX2DARRAY(tex) tex, sampler##tex
#define UNITY_ARGS_TEX2DARRAY_NOSAMPLER(tex) Texture2DArray tex
#define UNITY_PASS_TEX2DARRAY_NOSAMPLER(tex) tex
#define UNITY_SAMPLE_TEX2DARRAY(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEX2DARRAY_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEX2DARRAY_SAMPLER(tex, samplertex, coord) \
    tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEX2DARRAY_SAMPLER_LOD(tex, samplertex, coord, lod) \
    tex.SampleLevel(sampler##samplertex, coord, lod)

#define UNITY_DECLARE_TEXCUBEARRAY(tex) TextureCubeArray tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEXCUBEARRAY_NOSAMPLER(tex) TextureCubeArray tex
#define UNITY_ARGS_TEXCUBEARRAY(tex) TextureCubeArray tex, SamplerState sampler##tex
#define UNITY_PASS_TEXCUBEARRAY(tex) tex, sampler##tex
#define UNITY_ARGS_TEXCUBEARRAY_NOSAMPLER(tex) TextureCubeArray tex
#define UNITY_PASS_TEXCUBEARRAY_NOSAMPLER(tex) tex
#define UNITY_SAMPLE_TEXCUBEARRAY(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEXCUBEARRAY_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEXCUBEARRAY_SAMPLER(tex, samplertex, coord) \
    tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEXCUBEARRAY_SAMPLER_LOD(tex, samplertex, coord, lod) \
    tex.SampleLevel(sampler##samplertex, coord, lod)

// ---- screen-space textures (no stereo: plain 2D textures) ----
#define UNITY_DECLARE_SCREENSPACE_SHADOWMAP(tex) sampler2D tex
#define UNITY_SAMPLE_SCREEN_SHADOW(tex, uv) tex2Dproj(tex, UNITY_PROJ_COORD(uv)).r
#define UNITY_DECLARE_SCREENSPACE_TEXTURE(tex) sampler2D tex
#define UNITY_SAMPLE_SCREENSPACE_TEXTURE(tex, uv) tex2D(tex, uv)

// ---- framebuffer input: read as ordinary textures at the pixel position ----
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_FLOAT(idx) Texture2D<float4> _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_HALF(idx) Texture2D<float4> _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_INT(idx) Texture2D<int4> _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_UINT(idx) Texture2D<uint4> _UnityFBInput##idx
#define UNITY_READ_FRAMEBUFFER_INPUT(idx, v2fname) _UnityFBInput##idx.Load(uint3((v2fname).xy, 0))

// ---- display orientation (none on desktop) ----
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_0 0
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_90 1
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_180 2
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_270 3
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_0

#endif  // HLSL_SUPPORT_INCLUDED
