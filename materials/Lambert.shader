// Lambert: c = c_r * c_l * max(0, n . l), the lecture's first lighting model.
Shader "Kiln/Lambert"
{
    Properties
    {
        _Color ("Color", Color) = (1, 1, 1, 1)
    }
    SubShader
    {
        Tags { "RenderType" = "Opaque" }

        Pass
        {
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma vertex MyVertexProgram
            #pragma fragment MyFragmentProgram
            #include "UnityStandardBRDF.cginc"

            float4 _Color;

            struct VertexData {
                float4 position : POSITION;
                float3 normal : NORMAL;
            };

            struct VertexToFragment {
                float4 position : SV_POSITION;
                float3 normal : NORMAL;
            };

            VertexToFragment MyVertexProgram(VertexData vert) {
                VertexToFragment v2f;
                v2f.position = UnityObjectToClipPos(vert.position);
                v2f.normal = UnityObjectToWorldNormal(vert.normal);
                return v2f;
            }

            float4 MyFragmentProgram(VertexToFragment v2f) : SV_TARGET {
                float3 lightDir = _WorldSpaceLightPos0.xyz;
                float3 lightColor = _LightColor0.rgb;
                return _Color * float4(lightColor * DotClamped(lightDir, normalize(v2f.normal)), 1);
            }
            ENDCG
        }
    }
}
