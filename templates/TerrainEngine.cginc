// TerrainEngine.cginc: helpers of Unity's terrain and tree shaders with Unity's names: grass
// waving and billboards, tree bending and squashing, tree billboards, and the vegetation
// animation of Sousa 2007 (GPU Gems 3, chapter 16, "Vegetation Procedural Animation and Shading
// in Crysis": main bending along the wind plus detail bending of branches and leaves). Kiln's
// runtime has no terrain engine: the UnityTerrain values are whatever a material sets.
#ifndef TERRAIN_ENGINE_INCLUDED
#define TERRAIN_ENGINE_INCLUDED

#include "UnityCG.cginc"

CBUFFER_START(UnityTerrain)
    // grass
    fixed4 _WavingTint;
    float4 _WaveAndDistance;  // wind speed, wave size, wind amount, max squared distance
    float4 _CameraPosition;   // xyz: camera position, w: 1 / max squared distance
    float3 _CameraRight, _CameraUp;
    // trees
    fixed4 _TreeInstanceColor;
    float4 _TreeInstanceScale;
    float4x4 _TerrainEngineBendTree;
    float4 _SquashPlaneNormal;
    float _SquashAmount;
    // billboards
    float3 _TreeBillboardCameraRight;
    float4 _TreeBillboardCameraUp;     // w: how far billboards move towards the camera
    float4 _TreeBillboardCameraFront;
    float4 _TreeBillboardCameraPos;    // w: the billboard angle factor
    float4 _TreeBillboardDistances;    // x: max distance squared
CBUFFER_END

float4 _Wind;  // xyz: wind direction x strength; w: the wind's overall weight

struct appdata_tree {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;  // directional ambient occlusion
    float3 normal : NORMAL;
    fixed4 color : COLOR;      // w: bend factor
    float4 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_tree_billboard {
    float4 vertex : POSITION;
    fixed4 color : COLOR;
    float4 texcoord : TEXCOORD0;
    float2 texcoord1 : TEXCOORD1;  // billboard extrusion
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// Sine and cosine of four phases given in [0, 1] of a wave period (angle 2 pi val - pi).
void FastSinCos(float4 val, out float4 s, out float4 c) {
    float4 angle = val * (2.0 * KILN_PI) - KILN_PI;
    s = sin(angle);
    c = cos(angle);
}

// Grass blades sway with four travelling waves; the colour brightens with the sway and fades
// out towards the grass distance.
fixed4 TerrainWaveGrass(inout float4 vertex, float waveAmount, fixed4 color) {
    const float4 waveX = float4(0.012, 0.02, 0.06, 0.024);
    const float4 waveZ = float4(0.006, 0.02, 0.02, 0.05);
    const float4 speed = float4(1.2, 2.0, 1.6, 4.8);
    float4 phase = frac((vertex.x * waveX + vertex.z * waveZ) * _WaveAndDistance.y +
                        _WaveAndDistance.x * speed);
    float4 s, c;
    FastSinCos(phase, s, c);
    s = s * s;
    s = s * s;  // sharp crests
    float lighting = dot(s, normalize(float4(1, 1, 0.4, 0.2))) * 0.7;
    s *= waveAmount;
    float2 move = float2(dot(s, float4(0.024, 0.04, -0.12, 0.096)),
                         dot(s, float4(0.006, 0.02, -0.02, 0.1)));
    vertex.xz -= move * _WaveAndDistance.z;
    fixed3 waveColor = lerp(fixed3(0.5, 0.5, 0.5), _WavingTint.rgb, lighting);
    float3 offset = vertex.xyz - _CameraPosition.xyz;
    color.a = saturate(2 * (_WaveAndDistance.w - dot(offset, offset)) * _CameraPosition.w);
    return fixed4(2 * waveColor * color.rgb, color.a);
}

// A grass billboard: extruded along the camera's right and up within the grass distance.
void TerrainBillboardGrass(inout float4 pos, float2 offset) {
    float3 grassPos = pos.xyz - _CameraPosition.xyz;
    if (dot(grassPos, grassPos) > _WaveAndDistance.w)
        offset = 0.0;
    pos.xyz += offset.x * _CameraRight.xyz + offset.y * _CameraUp.xyz;
}
void WavingGrassVert(inout appdata_full v) {
    v.color = TerrainWaveGrass(v.vertex, v.color.a * _WaveAndDistance.z, v.color);
}
void WavingGrassBillboardVert(inout appdata_full v) {
    TerrainBillboardGrass(v.vertex, v.tangent.xy);
    v.color = TerrainWaveGrass(v.vertex, v.tangent.y, v.color);
}

// Projects towards the squash plane by 1 - _SquashAmount (trees being squashed by terrain edits).
inline float4 Squash(in float4 pos) {
    float3 n = _SquashPlaneNormal.xyz;
    float3 projected = pos.xyz - (dot(n, pos.xyz) + _SquashPlaneNormal.w) * n;
    return float4(lerp(projected, pos.xyz, _SquashAmount), 1);
}
void TerrainAnimateTree(inout float4 pos, float alpha) {
    pos.xyz *= _TreeInstanceScale.xyz;
    float3 bent = mul(_TerrainEngineBendTree, float4(pos.xyz, 0.0)).xyz;
    pos.xyz = lerp(pos.xyz, bent, alpha);
    pos = Squash(pos);
}

// A tree billboard: extruded towards the camera within the billboard distance.
void TerrainBillboardTree(inout float4 pos, float2 offset, float offsetz) {
    float3 treePos = pos.xyz - _TreeBillboardCameraPos.xyz;
    if (dot(treePos, treePos) > _TreeBillboardDistances.x)
        offset.xy = offsetz = 0.0;
    pos.xyz += _TreeBillboardCameraRight.xyz * offset.x;
    pos.xyz += _TreeBillboardCameraUp.xyz * lerp(offset.y, offsetz, _TreeBillboardCameraPos.w);
    pos.xyz += _TreeBillboardCameraFront.xyz * abs(offset.x) * _TreeBillboardCameraUp.w;
}

// Leaf cards flagged as billboards (tangent.w = 0) turn to face the camera through `mat`.
inline void ExpandBillboard(in float4x4 mat, inout float4 pos, inout float3 normal,
                            inout float4 tangent) {
    float isBillboard = 1.0f - abs(tangent.w);
    float3 facingNormal = SafeNormalize(mul(float4(normal, 0), mat).xyz);
    float3 facingTangent = SafeNormalize(mul(float4(tangent.xyz, 0.0f), mat).xyz);
    pos += mul(float4(normal.xy, 0, 0), mat) * isBillboard;
    normal = lerp(normal, facingNormal, isBillboard);
    tangent = lerp(tangent, float4(facingTangent, -1.0f), isBillboard);
}

// Smoothed triangle waves (Sousa 2007, section 16.2.3): a cheap, continuous sine substitute.
float4 SmoothCurve(float4 x) {
    return x * x * (3.0 - 2.0 * x);
}
float4 TriangleWave(float4 x) {
    return abs(frac(x + 0.5) * 2.0 - 1.0);
}
float4 SmoothTriangleWave(float4 x) {
    return SmoothCurve(TriangleWave(x));
}

// Main and detail bending (Sousa 2007, section 16.2): animParams = (branch phase, edge flutter,
// primary bend, secondary bend). Each object's phase comes from its world position.
inline float4 AnimateVertex(float4 pos, float3 normal, float4 animParams) {
    const float detailAmp = 0.1;
    const float branchAmp = 0.3;
    float3 objectPos = float3(unity_ObjectToWorld[0].w, unity_ObjectToWorld[1].w,
                              unity_ObjectToWorld[2].w);
    float objectPhase = dot(objectPos, float3(1, 1, 1));
    float branchPhase = objectPhase + animParams.x;
    float vertexPhase = dot(pos.xyz, animParams.y + branchPhase);
    float2 wavesIn = _Time.yy + float2(vertexPhase, branchPhase);
    float4 waves = frac(wavesIn.xxyy * float4(1.975, 0.793, 0.375, 0.193)) * 2.0 - 1.0;
    waves = SmoothTriangleWave(waves);
    float2 wavesSum = waves.xz + waves.yw;
    float3 bend = animParams.y * detailAmp * normal.xyz;
    bend.y = animParams.w * branchAmp;
    pos.xyz += ((wavesSum.xyx * bend) + (_Wind.xyz * wavesSum.y * animParams.w)) * _Wind.w;
    pos.xyz += animParams.z * _Wind.xyz;  // main bending
    return pos;
}

#endif  // TERRAIN_ENGINE_INCLUDED
