#line 1 "main.hlsl"
#pragma multi_compile KILN_FUZZ_K1 KILN_FUZZ_K2
#include "UnityCG.cginc"
#include "Lighting.cginc"

float4 f(float3 n) : SV_Target { return float4(UnityObjectToWorldNormal(n) * UNITY_PI, 1); }
#if KILN_FUZZ_K1
float k;
#endif
