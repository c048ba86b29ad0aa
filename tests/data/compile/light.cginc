#ifndef LIGHT_CGINC
#define LIGHT_CGINC
float4 _LightColor0;
float4 _WorldSpaceLightPos0;
float3 LightDir(float3 worldPos) {
#if defined(POINT) || defined(SPOT)
    return normalize(_WorldSpaceLightPos0.xyz - worldPos);
#else
    return _WorldSpaceLightPos0.xyz;
#endif
}
#endif
