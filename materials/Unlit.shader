// Unlit: a colour times an optional texture and the vertex colour (white where the mesh has
// none), no lighting; what the runtime draws a glTF KHR_materials_unlit material with (the
// texture's UV set and KHR_texture_transform as in GltfTexture.cginc, alphaMode MASK as
// _ALPHATEST_ON).
Shader "Kiln/Unlit"
{
    Properties
    {
        [MainColor] _Color ("Color", Color) = (1, 1, 1, 1)
        [MainTexture] _MainTex ("Texture", 2D) = "white" {}
        _Cutoff ("Alpha Cutoff", Range(0, 1)) = 0.5
        [HideInInspector] _MainTex_UV ("Texture UV", Vector) = (0, 0, 0, 0)
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
            #pragma shader_feature_local_fragment _ALPHATEST_ON
            #include "UnityCG.cginc"
            #include "GltfTexture.cginc"

            float4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST, _MainTex_UV;
            float _Cutoff;

            struct VertexData {
                float4 position : POSITION;
                float2 uv : TEXCOORD0;
                float2 uv1 : TEXCOORD1;
                float4 color : COLOR;
            };

            struct VertexToFragment {
                float4 position : SV_POSITION;
                float4 uv : TEXCOORD0;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
                float4 color : TEXCOORD1;
            };

            VertexToFragment MyVertexProgram(VertexData vert) {
                VertexToFragment v2f;
                v2f.position = UnityObjectToClipPos(vert.position);
                v2f.uv = float4(vert.uv, vert.uv1);
                v2f.color = vert.color;
                return v2f;
            }

            float4 MyFragmentProgram(VertexToFragment v2f) : SV_TARGET {
                float4 c = tex2D(_MainTex, GLTF_MAP_UV(v2f.uv, _MainTex)) * _Color * v2f.color;
            #if defined(_ALPHATEST_ON)
                clip(c.a - _Cutoff);
                c.a = 1.0;  // glTF: a MASK material is opaque where it is not cut out
            #endif
                return c;
            }
            ENDCG
        }
    }
    Fallback Off
}
