#line 16 "templates/UnityShaderVariables.cginc"
                            cbuffer UnityPerCamera {
    float4 _Time;
    float4 _SinTime;
    float4 _CosTime;
    float4 unity_DeltaTime;
    float3 _WorldSpaceCameraPos;
    float4 _ProjectionParams;
    float4 _ScreenParams;


    float4 _ZBufferParams;
    float4 unity_OrthoParams;
           };

                                cbuffer UnityPerCameraRare {
    float4 unity_CameraWorldClipPlanes[6];
    float4x4 unity_CameraProjection;
    float4x4 unity_CameraInvProjection;
    float4x4 unity_WorldToCamera;
    float4x4 unity_CameraToWorld;
           };

                           cbuffer UnityPerFrame {
    float4x4 unity_MatrixV;
    float4x4 unity_MatrixInvV;
    float4x4 unity_MatrixVP;
    float4x4 glstate_matrix_projection;
    float4 unity_AmbientSky;
    float4 unity_AmbientEquator;
    float4 unity_AmbientGround;
    float4 unity_IndirectSpecColor;
    float4 glstate_lightmodel_ambient;
    float4 unity_ShadowColor;
           };

                           cbuffer UnityLighting {


    float4 _WorldSpaceLightPos0;
    float4 _LightColor0;
    float4 kiln_SpotDirection0;
    float4 kiln_LightParams0;
    float4 _LightPositionRange;
    float4 _LightProjectionParams;
    float4x4 unity_WorldToLight;


    float4 unity_4LightPosX0;
    float4 unity_4LightPosY0;
    float4 unity_4LightPosZ0;
    float4 unity_4LightAtten0;
    float4 unity_LightColor[8];

    float4 unity_LightPosition[8];
    float4 unity_LightAtten[8];
    float4 unity_SpotDirection[8];
    float4 unity_OcclusionMaskSelector;
    float4 unity_ProbesOcclusion;
           };


                              cbuffer UnityLightingOld {
        float3 unity_LightColor0, unity_LightColor1, unity_LightColor2, unity_LightColor3;
           };

                          cbuffer UnityShadows {
    float4 unity_ShadowSplitSpheres[4];
    float4 unity_ShadowSplitSqRadii;
    float4 unity_LightShadowBias;
    float4 _LightSplitsNear;
    float4 _LightSplitsFar;
    float4x4 unity_WorldToShadow[4];
    float4 _LightShadowData;
    float4 unity_ShadowFadeCenterAndType;
           };

                      cbuffer UnityFog {
    float4 unity_FogColor;

    float4 unity_FogParams;
           };


                         cbuffer UnityProbes {
    float4 unity_SHAr;
    float4 unity_SHAg;
    float4 unity_SHAb;
    float4 unity_SHBr;
    float4 unity_SHBg;
    float4 unity_SHBb;
    float4 unity_SHC;

    float4 unity_ProbeVolumeParams;
    float4x4 unity_ProbeVolumeWorldToObject;
    float4 unity_ProbeVolumeSizeInv;
    float4 unity_ProbeVolumeMin;
           };

                                   cbuffer UnityReflectionProbes {
    float4 unity_SpecCube0_BoxMax;
    float4 unity_SpecCube0_BoxMin;
    float4 unity_SpecCube0_ProbePosition;
    float4 unity_SpecCube0_HDR;
    float4 unity_SpecCube1_BoxMax;
    float4 unity_SpecCube1_BoxMin;
    float4 unity_SpecCube1_ProbePosition;
    float4 unity_SpecCube1_HDR;
           };
#line 127 "templates/UnityShaderVariables.cginc"
                              cbuffer UnityPerDrawRare {
    float4 unity_LODFade;
    float4 unity_WorldTransformParams;
    float4 unity_RenderingLayer;
    float4 unity_LightmapST;
    float4 unity_DynamicLightmapST;
    float4 unity_Lightmap_HDR;
    float4 unity_DynamicLightmap_HDR;
    float4 unity_MotionVectorsParams;
           };


[[vk :: push_constant]]cbuffer UnityPerDraw {
    float4x4 unity_ObjectToWorld;
    float4x4 unity_WorldToObject;
};


                                  Texture2D unity_Lightmap;SamplerState samplerunity_Lightmap;
                                               Texture2D unity_LightmapInd;
                                    Texture2D unity_ShadowMask;SamplerState samplerunity_ShadowMask;
                                         Texture2D unity_DynamicLightmap;SamplerState samplerunity_DynamicLightmap;
                                                         Texture2D unity_DynamicDirectionality;
                                                 Texture2D unity_DynamicNormal;
                                     TextureCube unity_SpecCube0;SamplerState samplerunity_SpecCube0;
                                               TextureCube unity_SpecCube1;

                                             Texture3D unity_ProbeVolumeSH;SamplerState samplerunity_ProbeVolumeSH;


static uint unity_StereoEyeIndex = 0;
#line 11 "templates/UnityLightingCommon.cginc"
     float4 _SpecColor;
#line 17 "templates/UnityLightingCommon.cginc"
struct UnityLight {
    float3 color;
        float3 dir;
       float ndotl;
};


struct UnityIndirect {
        float3 diffuse;
        float3 specular;
};

struct UnityGI {
    UnityLight light;
    UnityIndirect indirect;
};


struct UnityGIInput {
    UnityLight light;
    float3 worldPos;
        float3 worldViewDir;
       float atten;
        float3 ambient;
    float4 lightmapUV;


    float4 boxMin[2];


    float4 boxMax[2];
    float4 probePosition[2];

    float4 probeHDR[2];
};
#line 21 "templates/KilnCommon.cginc"
float3 SafeNormalize(float3 v){
    float len2 = dot(v, v);

    return len2 > 1e-12 ? v * rsqrt(len2): float3(0.0, 0.0, 0.0);
}
#line 8 "templates/UnityGBuffer.cginc"
struct UnityStandardData {
        float3 diffuseColor;
       float occlusion;
        float3 specularColor;
       float smoothness;
    float3 normalWorld;
};
#line 45 "templates/UnityCG.cginc"
struct appdata_base {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;

};
struct appdata_tan {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;

};
struct appdata_full {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
    float4 texcoord2 : TEXCOORD2;
    float4 texcoord3 : TEXCOORD3;
    float4 color : COLOR;

};
#line 122 "templates/UnityCG.cginc"
inline float3 UnityWorldSpaceLightDir(in float3 worldPos){
    return _WorldSpaceLightPos0 . xyz - worldPos * _WorldSpaceLightPos0 . w;
}
#line 247 "templates/UnityCG.cginc"
struct v2f_vertex_lit {
    float2 uv : TEXCOORD0;
         float4 diff : COLOR0;
         float4 spec : COLOR1;
};
#line 444 "templates/UnityCG.cginc"
struct appdata_img {
    float4 vertex : POSITION;
        float2 texcoord : TEXCOORD0;

};
struct v2f_img {
    float4 pos : SV_POSITION;
        float2 uv : TEXCOORD0;


};
#line 9 "templates/UnityDeprecated.cginc"
inline float DotClamped(float3 a, float3 b){
    return saturate(dot(a, b));
}
#line 12 "templates/UnityImageBasedLighting.cginc"
struct Unity_GlossyEnvironmentData {
       float roughness;
        float3 reflUVW;
};
#line 10 "templates/KilnClassicLighting.cginc"
float3 Lambert_Diffuse(float3 albedo, float3 lightColor, float3 n, float3 l){
    return albedo * lightColor * saturate(dot(n, l));
}
#line 155 "templates/UnityShadowLibrary.cginc"
float UnityComputeShadowFadeDistance(float3 wpos, float z){
    float sphereDist = distance(wpos, unity_ShadowFadeCenterAndType . xyz);
    return lerp(z, sphereDist, unity_ShadowFadeCenterAndType . w);
}

   float UnityComputeShadowFade(float fadeDist){
    return saturate(fadeDist * _LightShadowData . z + _LightShadowData . w);
}
#line 176 "templates/UnityShadowLibrary.cginc"
    float UnitySampleBakedOcclusion(float2 lightmapUV, float3 worldPos){
#line 181 "templates/UnityShadowLibrary.cginc"
    return 1.0;

}
#line 198 "templates/UnityShadowLibrary.cginc"
   float UnityMixRealtimeAndBakedShadows(float realtimeShadowAttenuation, float bakedShadowAttenuation,
                                        float fade){
#line 203 "templates/UnityShadowLibrary.cginc"
    return lerp(realtimeShadowAttenuation, 1.0, fade);

}
#line 51 "templates/UnityPBSLighting.cginc"
struct SurfaceOutputStandard {
         float3 Albedo;
    float3 Normal;
        float3 Emission;
       float Metallic;
       float Smoothness;
       float Occlusion;
        float Alpha;
};
#line 101 "templates/UnityPBSLighting.cginc"
struct SurfaceOutputStandardSpecular {
         float3 Albedo;
         float3 Specular;
    float3 Normal;
        float3 Emission;
       float Smoothness;
       float Occlusion;
        float Alpha;
};
#line 64 "templates/AutoLight.cginc"
   float UnityRealtimeShadowAt(float3 worldPos){
#line 72 "templates/AutoLight.cginc"
    return 1.0;

