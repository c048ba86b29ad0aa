// KILN_SHADER_NAME: a physically based shader (metallic workflow, one directional light and SH
// ambient), written by `kiln new --template pbs`. UNITY_BRDF_PBS is Kiln's GGX / Smith /
// Schlick BRDF (templates/UnityStandardBRDF.cginc).
Shader "KILN_SHADER_NAME"
{
    Properties
    {
        [MainColor] _Color ("Base Color", Color) = (1, 1, 1, 1)
        [MainTexture] _MainTex ("Base Color Map", 2D) = "white" {}
        _Metallic ("Metallic", Range(0, 1)) = 0
        _Smoothness ("Smoothness", Range(0, 1)) = 0.5
    }
    SubShader
    {
        Tags { "RenderType" = "Opaque" }

        Pass
        {
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma vertex Vertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment Fragment
            #include "UnityPBSLighting.cginc"

            float4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST;
            float _Metallic;
            float _Smoothness;

            struct VertexData {
                float4 position : POSITION;
                float3 normal : NORMAL;
                float2 uv : TEXCOORD0;
            };

            struct Interpolators {
                float4 position : SV_POSITION;
                float2 uv : TEXCOORD0;
                float3 normal : TEXCOORD1;
                float3 worldPos : TEXCOORD2;
            };

            Interpolators Vertex(VertexData v) {
                Interpolators i;
                i.position = UnityObjectToClipPos(v.position);
                i.worldPos = mul(unity_ObjectToWorld, float4(v.position.xyz, 1.0)).xyz;
                i.normal = UnityObjectToWorldNormal(v.normal);
                i.uv = TRANSFORM_TEX(v.uv, _MainTex);
                return i;
            }

            float4 Fragment(Interpolators i) : SV_TARGET {
                float4 base = tex2D(_MainTex, i.uv) * _Color;
                float3 specColor;
                float oneMinusReflectivity;
                float3 diffuse = DiffuseAndSpecularFromMetallic(base.rgb, _Metallic, specColor,
                                                                oneMinusReflectivity);
                float3 n = SafeNormalize(i.normal);
                UnityLight light;
                light.dir = SafeNormalize(UnityWorldSpaceLightDir(i.worldPos));
                light.color = _LightColor0.rgb;
                light.ndotl = DotClamped(n, light.dir);
                UnityIndirect indirect;
                indirect.diffuse = ShadeSH9(float4(n, 1.0));
                indirect.specular = 0;
                float4 c = UNITY_BRDF_PBS(diffuse, specColor, oneMinusReflectivity, _Smoothness, n,
                                          SafeNormalize(UnityWorldSpaceViewDir(i.worldPos)),
                                          light, indirect);
                return float4(c.rgb, base.a);
            }
            ENDCG
        }
    }
}
