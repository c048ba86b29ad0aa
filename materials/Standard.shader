// Standard: physically based shading in the specular workflow, as in the lecture's PBS section
// (UNITY_BRDF_PBS: Lambert diffuse, GGX / Smith height-correlated / Schlick specular), with
// energy conservation and the scene's SH ambient as indirect diffuse light.
Shader "Kiln/Standard"
{
    Properties
    {
        [MainColor] _Color ("Color", Color) = (1, 1, 1, 1)
        [MainTexture] _MainTex ("Albedo", 2D) = "white" {}
        _SpecularColor ("Specular", Color) = (0.2, 0.2, 0.2, 1)
        _Smoothness ("Smoothness", Range(0, 1)) = 0.5
    }
    SubShader
    {
        Tags { "RenderType" = "Opaque" }

        Pass
        {
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma vertex ForwardVertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment StandardFragment
            #include "MaterialCommon.cginc"

            float4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST;
            float4 _SpecularColor;
            float _Smoothness;

            float4 StandardFragment(Interpolators i) : SV_TARGET {
                float4 texel = tex2D(_MainTex, TRANSFORM_TEX(i.uv, _MainTex)) * _Color;
                float oneMinusReflectivity;
                float3 albedo = EnergyConservationBetweenDiffuseAndSpecular(
                    texel.rgb, _SpecularColor.rgb, oneMinusReflectivity);
                float3 n = SafeNormalize(i.normal);
                UnityIndirect indirect;
                indirect.diffuse = ShadeSH9(float4(n, 1.0));
                indirect.specular = 0;
                float4 c = UNITY_BRDF_PBS(albedo, _SpecularColor.rgb, oneMinusReflectivity,
                                          _Smoothness, n, ViewDirection(i.worldPos),
                                          PixelLight(i.worldPos, n), indirect);
                return float4(c.rgb, texel.a);
            }
            ENDCG
        }

        // Casts shadows (docs/runtime.md, "Shadows").
        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }

            CGPROGRAM
            #pragma vertex ShadowCasterVertex
            #pragma fragment ShadowCasterFragment
            #pragma multi_compile_shadowcaster
            #include "ShadowCasterPass.cginc"
            ENDCG
        }
    }
}
