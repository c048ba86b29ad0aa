// HLSLSupport.cginc: the spellings Unity-style shader code expects from its compiler.
// (fixed/fixedN are defined by Kiln's prelude; see docs/variants.md.)
#ifndef HLSL_SUPPORT_INCLUDED
#define HLSL_SUPPORT_INCLUDED

#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };
#define UNITY_INITIALIZE_OUTPUT(type, name) name = (type)0;
#define UNITY_BRANCH [branch]
#define UNITY_FLATTEN [flatten]
#define UNITY_UNROLL [unroll]
#define UNITY_LOOP [loop]

#endif  // HLSL_SUPPORT_INCLUDED
