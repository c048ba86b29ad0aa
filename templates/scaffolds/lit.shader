// KILN_SHADER_NAME: a lit shader (ambient + Lambert + Blinn-Phong, one directional light),
// written by `kiln new --template lit`. The helpers come from templates/ and are guarded against
// NaN (docs/shader-library.md): SafeNormalize, BlinnPhong_Specular (pow(0, 0) = 1), ...
Shader "KILN_SHADER_NAME"
{
    Properties
    {
        [MainColor] _Color ("Color", Color) = (1, 1, 1, 1)
        [MainTexture] _MainTex ("Albedo", 2D) = "white" {}
        _SpecularColor ("Specular", Color) = (0.5, 0.5, 0.5, 1)
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
            #pragma fragment Fragment
            #include "UnityStandardBRDF.cginc"
            #include "Lighting.cginc"

            float4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST;
            float4 _SpecularColor;
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
                float4 albedo = tex2D(_MainTex, i.uv) * _Color;
                float3 n = SafeNormalize(i.normal);
                float3 l = SafeNormalize(UnityWorldSpaceLightDir(i.worldPos));
                float3 v = SafeNormalize(UnityWorldSpaceViewDir(i.worldPos));
                float3 h = BlinnPhong_HalfVector(l, v);
                float3 c = Ambient_Constant(albedo.rgb, unity_AmbientSky.rgb) +
                           Lambert_Diffuse(albedo.rgb, _LightColor0.rgb, n, l) +
                           BlinnPhong_Specular(_SpecularColor.rgb, _LightColor0.rgb, n, h,
                                               BlinnPhong_Exponent(_Smoothness));
                return float4(ClampToHalfRange(c), albedo.a);
            }
            ENDCG
        }
    }
}
