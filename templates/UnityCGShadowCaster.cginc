// UnityCGShadowCaster.cginc (part of UnityCG.cginc): the ShadowCaster pass helpers with Unity's
// names. unity_LightShadowBias: x = depth bias in clip space, y = 1 to clamp to the near plane
// (directional lights), z = normal bias. Kiln stores point-light shadows in depth cube maps
// (SHADOWS_CUBE_IN_DEPTH_TEX), so every light type renders depth only. Shadows are not rendered
// by Kiln's runtime yet; these compile ShadowCaster passes correctly for when they are.
#ifndef UNITY_CG_SHADOW_CASTER_INCLUDED
#define UNITY_CG_SHADOW_CASTER_INCLUDED

#define SHADOWS_CUBE_IN_DEPTH_TEX

// Distance to a point light in [0, 1] (of its range), packed for an RGBA8 cube if needed.
float4 UnityEncodeCubeShadowDepth(float z) {
    return z;
}
float UnityDecodeCubeShadowDepth(float4 vals) {
    return vals.r;
}

// Clip-space position of a shadow caster, moved against its normal by the normal bias: the
// offset grows with the sine of the angle between the normal and the light (slope-scaled).
float4 UnityClipSpaceShadowCasterPos(float4 vertex, float3 normal) {
    float4 wPos = mul(unity_ObjectToWorld, vertex);
    if (unity_LightShadowBias.z != 0.0) {
        float3 wNormal = UnityObjectToWorldNormal(normal);
        float3 wLight = SafeNormalize(UnityWorldSpaceLightDir(wPos.xyz));
        float cosine = dot(wNormal, wLight);
        // guard: rounding can push cosine^2 above 1
        float sine = sqrt(saturate(1.0 - cosine * cosine));
        wPos.xyz -= wNormal * (unity_LightShadowBias.z * sine);
    }
    return mul(UNITY_MATRIX_VP, wPos);
}
float4 UnityClipSpaceShadowCasterPos(float3 vertex, float3 normal) {
    return UnityClipSpaceShadowCasterPos(float4(vertex, 1.0), normal);
}

// The constant depth bias, and the clamp of casters behind the near plane onto it (pancaking).
float4 UnityApplyLinearShadowBias(float4 clipPos) {
#if !defined(SHADOWS_CUBE)
    // guard: w = 0 (a vertex in the camera plane) makes the ratio 0/0; saturate maps NaN to 0
    clipPos.z += saturate(unity_LightShadowBias.x / clipPos.w);
#endif
    float nearPlane = clipPos.w * UNITY_NEAR_CLIP_VALUE;
    clipPos.z = lerp(clipPos.z, max(clipPos.z, nearPlane), unity_LightShadowBias.y);
    return clipPos;
}

#define V2F_SHADOW_CASTER_NOPOS
#define V2F_SHADOW_CASTER_NOPOS_IS_EMPTY
#define TRANSFER_SHADOW_CASTER_NOPOS_LEGACY(o, opos) \
    opos = UnityObjectToClipPos(v.vertex.xyz);      \
    opos = UnityApplyLinearShadowBias(opos);
#define TRANSFER_SHADOW_CASTER_NOPOS(o, opos)                    \
    opos = UnityClipSpaceShadowCasterPos(v.vertex, v.normal); \
    opos = UnityApplyLinearShadowBias(opos);
#define SHADOW_CASTER_FRAGMENT(i) return 0;
#define V2F_SHADOW_CASTER V2F_SHADOW_CASTER_NOPOS UNITY_POSITION(pos)
#define TRANSFER_SHADOW_CASTER_NORMALOFFSET(o) TRANSFER_SHADOW_CASTER_NOPOS(o, o.pos)
#define TRANSFER_SHADOW_CASTER(o) TRANSFER_SHADOW_CASTER_NOPOS_LEGACY(o, o.pos)

// Legacy screen-space shadow collector pass (Unity 4): world position and view depth.
#define V2F_SHADOW_COLLECTOR \
    float4 pos : SV_POSITION; float3 _ShadowCoord0 : TEXCOORD0; float3 _ShadowCoord1 : TEXCOORD1; \
    float3 _ShadowCoord2 : TEXCOORD2; float3 _ShadowCoord3 : TEXCOORD3; float4 _WorldPosViewZ : TEXCOORD4
#define TRANSFER_SHADOW_COLLECTOR(o)                                 \
    o.pos = UnityObjectToClipPos(v.vertex);                          \
    float4 wpos = mul(unity_ObjectToWorld, v.vertex);                \
    o._WorldPosViewZ.xyz = wpos.xyz;                                 \
    o._WorldPosViewZ.w = -UnityObjectToViewPos(v.vertex).z;          \
    o._ShadowCoord0 = mul(unity_WorldToShadow[0], wpos).xyz;         \
    o._ShadowCoord1 = mul(unity_WorldToShadow[1], wpos).xyz;         \
    o._ShadowCoord2 = mul(unity_WorldToShadow[2], wpos).xyz;         \
    o._ShadowCoord3 = mul(unity_WorldToShadow[3], wpos).xyz;
#define SHADOW_COLLECTOR_FRAGMENT(i) return float4(1.0, 1.0, 1.0, 1.0);
#define COMPUTE_SHADOW_COLLECTOR_SHADOW(i, weights, shadowFade) 1.0
#define SAMPLE_SHADOW_COLLECTOR_SHADOW(coord) 1.0

#define UNITY_OPAQUE_ALPHA(outputAlpha) outputAlpha = 1.0

#endif  // UNITY_CG_SHADOW_CASTER_INCLUDED
