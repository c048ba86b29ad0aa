// Lecture 06 (Light), DiffuseSpecular: assembled from the slides as a student would write it.
Shader "Lecture/DiffuseSpecular"
{
    Properties
    {
        _Color("Color", Color) = (1, 1, 1, 1)
        _Smoothness("Smoothness", Range(0, 1)) = 0.5
        _SpecularColor("Specular", Color) = (0.5, 0.5, 0.5)
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

            struct VertexData {
                float4 position : POSITION;
                float3 normal : NORMAL;
            };

            struct VertexToFragment {
                float4 position : SV_POSITION;
                float3 normal : NORMAL;
                float4 worldpos : TEXCOORD2;
            };

            VertexToFragment MyVertexProgram(VertexData vert) {
                VertexToFragment v2f;
                v2f.position = UnityObjectToClipPos(vert.position);
                v2f.normal = UnityObjectToWorldNormal(vert.normal);
                v2f.worldpos = mul(unity_ObjectToWorld, vert.position);
                return v2f;
            }

            float4 MyFragmentProgram(VertexToFragment v2f) :SV_TARGET{
                float3 lightDir = _WorldSpaceLightPos0.xyz;
                float3 viewDir = normalize(_WorldSpaceCameraPos - v2f.worldpos);
                float4 lightColor = _LightColor0.rgb;

                float4 diffuse = _Color * (unity_AmbientSky + (lightColor *
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
