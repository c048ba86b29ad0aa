// TerrainSplatmapCommon.cginc: Unity's terrain splat mapping. A control texture holds four
// blend weights per texel; each weight selects one of four splat layers (albedo, and with
// _NORMALMAP a tangent-space normal). Terrain meshes are drawn non-instanced in Kiln (Kiln's
// UnityInstancing never defines UNITY_INSTANCING_ENABLED), so the vertex position and normal come
// from the mesh rather than from the heightmap. Include after UnityCG.cginc; surface-style users
// (SplatmapFinalColor / SplatmapFinalGBuffer) also need Lighting.cginc and UnityGBuffer.cginc.
#ifndef TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED
#define TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED

// _NORMALMAP and the older _TERRAIN_NORMAL_MAP are synonyms.
#if defined(_NORMALMAP) && !defined(_TERRAIN_NORMAL_MAP)
#define _TERRAIN_NORMAL_MAP
#elif !defined(_NORMALMAP) && defined(_TERRAIN_NORMAL_MAP)
#define _NORMALMAP
#endif

struct Input {
    float4 tc;  // xy: terrain UV (0..1 over the tile)
#ifndef TERRAIN_BASE_PASS
    UNITY_FOG_COORDS(0)
#endif
};

sampler2D _Control;
float4 _Control_ST;
float4 _Control_TexelSize;
sampler2D _Splat0, _Splat1, _Splat2, _Splat3;
float4 _Splat0_ST, _Splat1_ST, _Splat2_ST, _Splat3_ST;

UNITY_INSTANCING_BUFFER_START(Terrain)
UNITY_DEFINE_INSTANCED_PROP(float4, _TerrainPatchInstanceData)  // xBase, yBase, skipScale
UNITY_INSTANCING_BUFFER_END(Terrain)

#ifdef _NORMALMAP
sampler2D _Normal0, _Normal1, _Normal2, _Normal3;
float _NormalScale0, _NormalScale1, _NormalScale2, _NormalScale3;
#endif

#ifdef _ALPHATEST_ON
sampler2D _TerrainHolesTexture;

// Discards terrain holes. Compressed hole masks store "0" as a small positive value, hence the
// threshold rather than a comparison with zero.
void ClipHoles(float2 uv) {
    clip(tex2D(_TerrainHolesTexture, uv).r < 0.0005 ? -1.0 : 1.0);
}
#endif

#if defined(TERRAIN_BASE_PASS) && defined(UNITY_PASS_META)
float4 _MainTex_ST;  // the meta pass bakes albedo with the base map's tiling
#endif

void SplatmapVert(inout appdata_full v, out Input data) {
    UNITY_INITIALIZE_OUTPUT(Input, data);
    // Terrain UV runs along +x and +z; the tangent follows x, and the bitangent sign makes the
    // frame right-handed with the up normal.
    v.tangent.xyz = cross(v.normal, float3(0.0, 0.0, 1.0));
    v.tangent.w = -1.0;
    data.tc.xy = v.texcoord.xy;
#ifdef TERRAIN_BASE_PASS
#ifdef UNITY_PASS_META
    data.tc.xy = TRANSFORM_TEX(v.texcoord.xy, _MainTex);
#endif
#else
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    UNITY_TRANSFER_FOG(data, clipPosition);
#endif
}

#ifndef TERRAIN_BASE_PASS

// Splat-layer UVs centred on control texels: the tile edges land on texel centres.
float2 TerrainControlUV(float2 uv) {
    return (uv * (_Control_TexelSize.zw - 1.0) + 0.5) * _Control_TexelSize.xy;
}

// Mixes the four layers by the control weights. The weights are normalised for lighting
// (the final-colour functions multiply the total weight back in, so add passes sum correctly).
#ifdef TERRAIN_STANDARD_SHADER
void SplatmapMix(Input IN, half4 defaultAlpha, out half4 splat_control, out half weight,
                 out fixed4 mixedDiffuse, inout fixed3 mixedNormal)
#else
void SplatmapMix(Input IN, out half4 splat_control, out half weight, out fixed4 mixedDiffuse,
                 inout fixed3 mixedNormal)
#endif
{
#ifdef _ALPHATEST_ON
    ClipHoles(IN.tc.xy);
#endif
    splat_control = tex2D(_Control, TerrainControlUV(IN.tc.xy));
    weight = dot(splat_control, half4(1.0, 1.0, 1.0, 1.0));
#if !defined(SHADER_API_MOBILE) && defined(TERRAIN_SPLAT_ADDPASS)
    clip(weight == 0.0 ? -1.0 : 1.0);
#endif
    splat_control /= weight + 1e-3;

    float2 uv0 = TRANSFORM_TEX(IN.tc.xy, _Splat0);
    float2 uv1 = TRANSFORM_TEX(IN.tc.xy, _Splat1);
    float2 uv2 = TRANSFORM_TEX(IN.tc.xy, _Splat2);
    float2 uv3 = TRANSFORM_TEX(IN.tc.xy, _Splat3);
#ifdef TERRAIN_STANDARD_SHADER
    half4 alpha = defaultAlpha;  // per-layer smoothness replaces the layer's alpha
#else
    half4 alpha = half4(1.0, 1.0, 1.0, 1.0);
#endif
    half4 keepAlpha = half4(1.0, 1.0, 1.0, 0.0);
    mixedDiffuse = splat_control.r * tex2D(_Splat0, uv0) * (keepAlpha + half4(0, 0, 0, alpha.r)) +
                   splat_control.g * tex2D(_Splat1, uv1) * (keepAlpha + half4(0, 0, 0, alpha.g)) +
                   splat_control.b * tex2D(_Splat2, uv2) * (keepAlpha + half4(0, 0, 0, alpha.b)) +
                   splat_control.a * tex2D(_Splat3, uv3) * (keepAlpha + half4(0, 0, 0, alpha.a));
#ifdef _NORMALMAP
    mixedNormal = UnpackNormalWithScale(tex2D(_Normal0, uv0), _NormalScale0) * splat_control.r +
                  UnpackNormalWithScale(tex2D(_Normal1, uv1), _NormalScale1) * splat_control.g +
                  UnpackNormalWithScale(tex2D(_Normal2, uv2), _NormalScale2) * splat_control.b +
                  UnpackNormalWithScale(tex2D(_Normal3, uv3), _NormalScale3) * splat_control.a;
    mixedNormal.z += 1e-5;  // opposing layers cancelling to zero would make normalize() NaN
#endif
}

#ifndef TERRAIN_SURFACE_OUTPUT
#define TERRAIN_SURFACE_OUTPUT SurfaceOutput
#endif

// Restores the layer weight (carried in Alpha) and applies fog; add passes fog towards black
// so the blended sum fogs once.
void SplatmapFinalColor(Input IN, TERRAIN_SURFACE_OUTPUT o, inout fixed4 color) {
    color *= o.Alpha;
#ifdef TERRAIN_SPLAT_ADDPASS
    UNITY_APPLY_FOG_COLOR(IN.fogCoord, color, fixed4(0.0, 0.0, 0.0, 0.0));
#else
    UNITY_APPLY_FOG(IN.fogCoord, color);
#endif
}

void SplatmapFinalGBuffer(Input IN, TERRAIN_SURFACE_OUTPUT o, inout half4 outGBuffer0,
                          inout half4 outGBuffer1, inout half4 outGBuffer2, inout half4 emission) {
    UnityStandardDataApplyWeightToGbuffer(outGBuffer0, outGBuffer1, outGBuffer2, o.Alpha);
    emission *= o.Alpha;
}

#endif  // TERRAIN_BASE_PASS

#endif  // TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED
