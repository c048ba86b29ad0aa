// MaterialCommon.cginc: the vertex stage and per-light set-up shared by Kiln's shipped forward
// materials. Lighting itself comes from templates/ (UnityPBSLighting, AutoLight, ...).
#ifndef KILN_MATERIAL_COMMON_INCLUDED
#define KILN_MATERIAL_COMMON_INCLUDED

#include "UnityPBSLighting.cginc"
#include "AutoLight.cginc"

struct VertexData {
    float4 position : POSITION;
    float3 normal : NORMAL;
    float2 uv : TEXCOORD0;
};

struct Interpolators {
    float4 position : SV_POSITION;
    float2 uv : TEXCOORD0;        // untransformed; fragment programs apply their texture's _ST
    float3 normal : TEXCOORD1;    // world space, not renormalized after interpolation
    float3 worldPos : TEXCOORD2;
};

Interpolators ForwardVertex(VertexData v) {
    Interpolators i;
    i.position = UnityObjectToClipPos(v.position);
    i.worldPos = mul(unity_ObjectToWorld, float4(v.position.xyz, 1.0)).xyz;
    i.normal = UnityObjectToWorldNormal(v.normal);
    i.uv = v.uv;
    return i;
}

// The pass's pixel light at the fragment: unit direction, colour times attenuation
// (DIRECTIONAL / POINT / SPOT by keyword, AutoLight.cginc) and the clamped cosine.
UnityLight PixelLight(float3 worldPos, float3 normal) {
    UnityLight light;
    light.dir = SafeNormalize(UnityWorldSpaceLightDir(worldPos));
    UNITY_LIGHT_ATTENUATION(attenuation, 0, worldPos);
    light.color = _LightColor0.rgb * attenuation;
    light.ndotl = DotClamped(normal, light.dir);
    return light;
}

// Unit view direction from the fragment to the camera.
float3 ViewDirection(float3 worldPos) {
    return SafeNormalize(UnityWorldSpaceViewDir(worldPos));
}

#endif  // KILN_MATERIAL_COMMON_INCLUDED
