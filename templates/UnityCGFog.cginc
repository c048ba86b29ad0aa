// UnityCGFog.cginc (part of UnityCG.cginc): fog with Unity's macro names. multi_compile_fog
// selects FOG_LINEAR, FOG_EXP or FOG_EXP2 (KilnFog.cginc has the factors); the vertex stage
// passes the clip-space depth, the fragment stage computes the factor (shader model 3.0 and up)
// or the vertex stage does (below 3.0), and the colour is blended towards unity_FogColor, or
// towards black in additive passes. Also Unity's tangent-frame packing helpers and the LOD
// cross-fade macros (Kiln has no LOD cross-fade: they do nothing).
#ifndef UNITY_CG_FOG_INCLUDED
#define UNITY_CG_FOG_INCLUDED

// Fog makes no sense in G-buffer and shadow passes: treated as off there.
#if defined(UNITY_PASS_DEFERRED) || defined(UNITY_PASS_SHADOWCASTER)
#undef FOG_LINEAR
#undef FOG_EXP
#undef FOG_EXP2
#endif

// Kiln's clip-space z runs from 0 at the near plane to (about) the far distance: already a
// distance.
#define UNITY_Z_0_FAR_FROM_CLIPSPACE(coord) (coord)

#if defined(FOG_LINEAR)
#define KILN_FOG_FACTOR(z) Fog_Linear(z, unity_FogParams)
#elif defined(FOG_EXP)
#define KILN_FOG_FACTOR(z) Fog_Exp(z, unity_FogParams)
#elif defined(FOG_EXP2)
#define KILN_FOG_FACTOR(z) Fog_Exp2(z, unity_FogParams)
#else
#define KILN_FOG_FACTOR(z) 0.0
#endif
#define UNITY_CALC_FOG_FACTOR_RAW(coord) float unityFogFactor = KILN_FOG_FACTOR(coord)
#define UNITY_CALC_FOG_FACTOR(coord) UNITY_CALC_FOG_FACTOR_RAW(UNITY_Z_0_FAR_FROM_CLIPSPACE(coord))
#define UNITY_FOG_COORDS_PACKED(idx, vectype) vectype fogCoord : TEXCOORD##idx;
#define UNITY_FOG_LERP_COLOR(col, fogCol, fogFac) \
    col.rgb = lerp((fogCol).rgb, (col).rgb, saturate(fogFac))

#if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
#define UNITY_FOG_COORDS(idx) UNITY_FOG_COORDS_PACKED(idx, float1)
#if SHADER_TARGET < 30
// The factor per vertex.
#define UNITY_TRANSFER_FOG(o, outpos) \
    UNITY_CALC_FOG_FACTOR((outpos).z); o.fogCoord.x = unityFogFactor
#define UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(o, outpos) \
    UNITY_CALC_FOG_FACTOR((outpos).z); o.tSpace1.y = tangentSign; o.tSpace2.y = unityFogFactor
#define UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS(o, outpos) \
    UNITY_CALC_FOG_FACTOR((outpos).z); o.worldPos.w = unityFogFactor
#define UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, outpos) \
    UNITY_CALC_FOG_FACTOR((outpos).z); o.eyeVec.w = unityFogFactor
#define UNITY_APPLY_FOG_COLOR(coord, col, fogCol) UNITY_FOG_LERP_COLOR(col, fogCol, (coord).x)
#else
// The distance per vertex, the factor per pixel.
#define UNITY_TRANSFER_FOG(o, outpos) o.fogCoord.x = (outpos).z
#define UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(o, outpos) o.tSpace2.y = (outpos).z
#define UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS(o, outpos) o.worldPos.w = (outpos).z
#define UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, outpos) o.eyeVec.w = (outpos).z
#define UNITY_APPLY_FOG_COLOR(coord, col, fogCol) \
    UNITY_CALC_FOG_FACTOR((coord).x); UNITY_FOG_LERP_COLOR(col, fogCol, unityFogFactor)
#endif
#define UNITY_EXTRACT_FOG(name) float _unity_fogCoord = name.fogCoord
#define UNITY_EXTRACT_FOG_FROM_TSPACE(name) float _unity_fogCoord = name.tSpace2.y
#define UNITY_EXTRACT_FOG_FROM_WORLD_POS(name) float _unity_fogCoord = name.worldPos.w
#define UNITY_EXTRACT_FOG_FROM_EYE_VEC(name) float _unity_fogCoord = name.eyeVec.w
#else
#define UNITY_FOG_COORDS(idx)
#define UNITY_TRANSFER_FOG(o, outpos)
#define UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(o, outpos)
#define UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS(o, outpos)
#define UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, outpos)
#define UNITY_APPLY_FOG_COLOR(coord, col, fogCol)
#define UNITY_EXTRACT_FOG(name)
#define UNITY_EXTRACT_FOG_FROM_TSPACE(name)
#define UNITY_EXTRACT_FOG_FROM_WORLD_POS(name)
#define UNITY_EXTRACT_FOG_FROM_EYE_VEC(name)
#endif

#ifdef UNITY_PASS_FORWARDADD
#define UNITY_APPLY_FOG(coord, col) UNITY_APPLY_FOG_COLOR(coord, col, fixed4(0, 0, 0, 0))
#else
#define UNITY_APPLY_FOG(coord, col) UNITY_APPLY_FOG_COLOR(coord, col, unity_FogColor)
#endif

// Tangent frames packed as three rows tSpace0..2 (x: tangent, y: binormal, z: normal), with the
// binormal sign or the fog coordinate in tSpace1.y / tSpace2.y.
#define UNITY_EXTRACT_TBN_0(name) fixed3 _unity_tbn_0 = name.tSpace0.xyz
#define UNITY_EXTRACT_TBN_1(name) fixed3 _unity_tbn_1 = name.tSpace1.xyz
#define UNITY_EXTRACT_TBN_2(name) fixed3 _unity_tbn_2 = name.tSpace2.xyz
#define UNITY_EXTRACT_TBN(name) \
    UNITY_EXTRACT_TBN_0(name); UNITY_EXTRACT_TBN_1(name); UNITY_EXTRACT_TBN_2(name)
#define UNITY_EXTRACT_TBN_T(name) \
    fixed3 _unity_tangent = fixed3(name.tSpace0.x, name.tSpace1.x, name.tSpace2.x)
#define UNITY_EXTRACT_TBN_N(name) \
    fixed3 _unity_normal = fixed3(name.tSpace0.z, name.tSpace1.z, name.tSpace2.z)
#define UNITY_EXTRACT_TBN_B(name) fixed3 _unity_binormal = cross(_unity_normal, _unity_tangent)
#define UNITY_CORRECT_TBN_B_SIGN(name) _unity_binormal *= name.tSpace1.y;
#define UNITY_RECONSTRUCT_TBN_0 \
    fixed3 _unity_tbn_0 = fixed3(_unity_tangent.x, _unity_binormal.x, _unity_normal.x)
#define UNITY_RECONSTRUCT_TBN_1 \
    fixed3 _unity_tbn_1 = fixed3(_unity_tangent.y, _unity_binormal.y, _unity_normal.y)
#define UNITY_RECONSTRUCT_TBN_2 \
    fixed3 _unity_tbn_2 = fixed3(_unity_tangent.z, _unity_binormal.z, _unity_normal.z)
#if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
#define UNITY_RECONSTRUCT_TBN(name)                                                     \
    UNITY_EXTRACT_TBN_T(name); UNITY_EXTRACT_TBN_N(name); UNITY_EXTRACT_TBN_B(name);  \
    UNITY_CORRECT_TBN_B_SIGN(name); UNITY_RECONSTRUCT_TBN_0; UNITY_RECONSTRUCT_TBN_1; \
    UNITY_RECONSTRUCT_TBN_2
#else
#define UNITY_RECONSTRUCT_TBN(name) UNITY_EXTRACT_TBN(name)
#endif

#define UNITY_DITHER_CROSSFADE_COORDS
#define UNITY_DITHER_CROSSFADE_COORDS_IDX(idx)
#define UNITY_TRANSFER_DITHER_CROSSFADE(o, v)
#define UNITY_TRANSFER_DITHER_CROSSFADE_HPOS(o, hpos)

// LOD cross-fade (Unity's LOD_FADE_CROSSFADE keyword, a LOD Group's "Cross Fade" mode): the
// pixel is kept or clipped by comparing the fade amount unity_LODFade.x with a 4x4 dither mask
// tiled over the screen (`vpos`: the pixel position, VPOS), as UnityCG.cginc does; a negative
// fade is the incoming LOD, whose mask is inverted. unity_DitherMask is an engine texture (Kiln's
// runtime draws no LOD groups, so it never asks for the keyword).
#ifdef LOD_FADE_CROSSFADE
#define UNITY_APPLY_DITHER_CROSSFADE(vpos) UnityApplyDitherCrossFade(vpos)
sampler2D unity_DitherMask;
void UnityApplyDitherCrossFade(float2 vpos) {
    vpos /= 4;  // the dither mask texture is 4x4
    float mask = tex2D(unity_DitherMask, vpos).a;
    float sgn = unity_LODFade.x > 0 ? 1.0f : -1.0f;
    clip(unity_LODFade.x - mask * sgn);
}
#else
#define UNITY_APPLY_DITHER_CROSSFADE(vpos)
#endif

#endif  // UNITY_CG_FOG_INCLUDED
