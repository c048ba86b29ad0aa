// UnityBuiltin2xTreeLibrary.cginc: Unity 2's tree vertex programs with Unity's names: leaves lit
// through their directional ambient occlusion (the tangent), bark by Lambert, both by up to four
// "Vertex" pass lights (or the terrain's imposter lights with USE_CUSTOM_LIGHT_DIR).
#ifndef UNITY_BUILTIN_2X_TREE_LIBRARY_INCLUDED
#define UNITY_BUILTIN_2X_TREE_LIBRARY_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityCG.cginc"
#include "TerrainEngine.cginc"

float _Occlusion, _AO, _BaseLight;
fixed4 _Color;
#ifdef USE_CUSTOM_LIGHT_DIR
CBUFFER_START(UnityTerrainImposter)
    float3 _TerrainTreeLightDirections[4];
    float4 _TerrainTreeLightColors[4];
CBUFFER_END
#endif
CBUFFER_START(UnityPerCamera2)
    float4x4 _CameraToWorld;
CBUFFER_END
float _HalfOverCutoff;

struct v2f {
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;
    half4 color : TEXCOORD1;
    UNITY_FOG_COORDS(2)
    UNITY_VERTEX_OUTPUT_STEREO
};

// Light i's world direction, colour and attenuation at a view-space position.
void TreeLight(int i, float3 viewPos, out float3 lightDir, out float4 lightColor, out float atten) {
#ifdef USE_CUSTOM_LIGHT_DIR
    lightDir = _TerrainTreeLightDirections[i];
    lightColor = _TerrainTreeLightColors[i];
    atten = 1.0;
#else
    float3 toLight = unity_LightPosition[i].xyz - viewPos * unity_LightPosition[i].w;
    float lengthSq = dot(toLight, toLight);
    toLight.z = -toLight.z;  // view space is right-handed, the camera matrix left-handed
    lightDir = mul((float3x3)_CameraToWorld, SafeNormalize(toLight));
    atten = 1.0 / (1.0 + lengthSq * unity_LightAtten[i].z);
    lightColor = float4(unity_LightColor[i].rgb, 0);
#endif
}

v2f leaves(appdata_tree v) {
    v2f o;
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    TerrainAnimateTree(v.vertex, v.color.w);
    float3 viewPos = UnityObjectToViewPos(v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
    float4 light = UNITY_LIGHTMODEL_AMBIENT;
    for (int i = 0; i < 4; i++) {
        float3 dir;
        float4 color;
        float atten;
        TreeLight(i, viewPos, dir, color, atten);
        // the tangent holds the leaf's directional occlusion (xyz) and its ambient part (w)
        float occlusion = max(0, dot(v.tangent, float4(dir * _Occlusion, _AO))) + _BaseLight;
        light += color * (occlusion * atten);
    }
    o.color = light * _Color * _TreeInstanceColor;
    o.color.a = 0.5 * _HalfOverCutoff;
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

v2f bark(appdata_tree v) {
    v2f o;
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    TerrainAnimateTree(v.vertex, v.color.w);
    float3 viewPos = UnityObjectToViewPos(v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
    float4 light = UNITY_LIGHTMODEL_AMBIENT;
    for (int i = 0; i < 4; i++) {
        float3 dir;
        float4 color;
        float atten;
        TreeLight(i, viewPos, dir, color, atten);
        float diffuse = max(0, dot(v.normal, dir)) * (_AO * v.tangent.w + _BaseLight);
        light += color * (diffuse * atten);
    }
    light.a = 1;
    o.color = light * _Color * _TreeInstanceColor;
#ifdef WRITE_ALPHA_1
    o.color.a = 1;
#endif
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

#endif  // UNITY_BUILTIN_2X_TREE_LIBRARY_INCLUDED
