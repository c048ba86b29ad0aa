// Lecture 06 (Light): the shared include file of the multiple-lights section, in its final form
// (directional, point and spot lights, attenuation through UNITY_LIGHT_ATTENUATION).
#if !defined(LIGHTSHADER_INCLUDED)
#define LIGHTSHADER_INCLUDED

#include "UnityPBSLighting.cginc"
#include "AutoLight.cginc"

float4 _Color;
float _Smoothness;
float4 _SpecularColor;
sampler2D _MainTex;
float4 _MainTex_ST;

struct VertexData {
    float4 position : POSITION;
    float3 normal : NORMAL;
    float2 uv : TEXCOORD0;
};

struct VertexToFragment {
    float4 position : SV_POSITION;
    float2 uv : TEXCOORD0;
    float3 normal : NORMAL;
    float4 worldpos : TEXCOORD1;
};

VertexToFragment MyVertexProgram(VertexData vert) {
    VertexToFragment v2f;
    v2f.position = UnityObjectToClipPos(vert.position);
    v2f.worldpos = mul(unity_ObjectToWorld, vert.position);
    v2f.normal = UnityObjectToWorldNormal(vert.normal);
    v2f.uv = TRANSFORM_TEX(vert.uv, _MainTex);
    return v2f;
}

UnityLight CreateLight(VertexToFragment v2f) {
    UnityLight light;
    #if defined(POINT) || defined(SPOT)
        light.dir = normalize(_WorldSpaceLightPos0.xyz - v2f.worldpos);
    #else
        light.dir = _WorldSpaceLightPos0.xyz;
    #endif
    UNITY_LIGHT_ATTENUATION(attenuation, 0, v2f.worldpos);
    light.color = _LightColor0.rgb * attenuation;
    light.ndotl = DotClamped(normalize(v2f.normal), light.dir);
    return light;
}

float4 MyFragmentProgram(VertexToFragment v2f) : SV_TARGET {
    float3 viewDir = normalize(_WorldSpaceCameraPos - v2f.worldpos);
    float3 albedo = tex2D(_MainTex, v2f.uv).rgb * _Color;
    float oneMinusReflectivity;
    albedo = EnergyConservationBetweenDiffuseAndSpecular(albedo,
                                                         _SpecularColor, oneMinusReflectivity);

    UnityIndirect indirectLight;
    indirectLight.diffuse = 0;
    indirectLight.specular = 0;

    return UNITY_BRDF_PBS(albedo, _SpecularColor, oneMinusReflectivity,
                          _Smoothness, normalize(v2f.normal), viewDir,
                          CreateLight(v2f), indirectLight);
}

#endif
