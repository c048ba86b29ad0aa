// Lecture 06 (Light), Textured: assembled from the slides as a student would write it.
Shader "Lecture/Textured"
{
    Properties
    {
        _Color("Color", Color) = (1, 1, 1, 1)
        _Smoothness("Smoothness", Range(0, 1)) = 0.5
        _SpecularColor("Specular", Color) = (0.5, 0.5, 0.5)
        _MainTex("Albedo", 2D) = "white" {}
    }
    SubShader
    {
        Pass
        {
            Tags {
                "LightMode" = "ForwardBase"
            }
            CGPROGRAM
            #pragma vertex MyVertexProgram
            #pragma fragment MyFragmentProgram
            #include "UnityStandardBRDF.cginc"

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

            float4 MyFragmentProgram(VertexToFragment v2f) :SV_TARGET{
                float3 lightDir = _WorldSpaceLightPos0.xyz;
                float3 viewDir = normalize(_WorldSpaceCameraPos - v2f.worldpos);
                float4 lightColor = _LightColor0.rgb;
                float4 albedo = tex2D(_MainTex, v2f.uv).rgb * _Color;
                float4 diffuse = albedo * (unity_AmbientSky + (lightColor *
                    DotClamped(lightDir, normalize(v2f.normal))));
                float4 specular = _SpecularColor * lightColor * pow(DotClamped(
                    normalize(lightDir + viewDir),
                    normalize(v2f.normal)), _Smoothness * 100);
                return diffuse + specular;
            }
            ENDCG
        }
    }
}
