// Unlit: a colour times an optional texture, no lighting.
Shader "Kiln/Unlit"
{
    Properties
    {
        [MainColor] _Color ("Color", Color) = (1, 1, 1, 1)
        [MainTexture] _MainTex ("Texture", 2D) = "white" {}
    }
    SubShader
    {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry" }
        LOD 100

        Pass
        {
            Name "UNLIT"
            Tags { "LightMode" = "Always" }

            CGPROGRAM
            #pragma vertex MyVertexProgram
            #pragma fragment MyFragmentProgram
            #include "UnityCG.cginc"

            float4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST;

            struct VertexData {
                float4 position : POSITION;
                float2 uv : TEXCOORD0;
            };

            struct VertexToFragment {
                float4 position : SV_POSITION;
                float2 uv : TEXCOORD0;
            };

            VertexToFragment MyVertexProgram(VertexData vert) {
                VertexToFragment v2f;
                v2f.position = UnityObjectToClipPos(vert.position);
                v2f.uv = TRANSFORM_TEX(vert.uv, _MainTex);
                return v2f;
            }

            float4 MyFragmentProgram(VertexToFragment v2f) : SV_TARGET {
                return tex2D(_MainTex, v2f.uv) * _Color;
            }
            ENDCG
        }
    }
    Fallback Off
}
