// EnergyConserving: BlinnPhongTextured with the diffuse albedo scaled by 1 - max(specular) so
// diffuse + specular reflectance never exceeds 1 (lecture "Energy conservation").
Shader "Kiln/EnergyConserving"
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
            #pragma vertex ForwardVertex
            #pragma fragment EnergyConservingFragment
            #include "MaterialCommon.cginc"

            float4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST;
            float4 _SpecularColor;
            float _Smoothness;

            float4 EnergyConservingFragment(Interpolators i) : SV_TARGET {
                float4 texel = tex2D(_MainTex, TRANSFORM_TEX(i.uv, _MainTex)) * _Color;
                float oneMinusReflectivity;
                float3 albedo = EnergyConservationBetweenDiffuseAndSpecular(
                    texel.rgb, _SpecularColor.rgb, oneMinusReflectivity);
                float3 n = SafeNormalize(i.normal);
                float3 v = ViewDirection(i.worldPos);
                UnityLight light = PixelLight(i.worldPos, n);
                float3 h = BlinnPhong_HalfVector(light.dir, v);
                float3 c = Ambient_Constant(albedo, unity_AmbientSky.rgb) +
                           Lambert_Diffuse(albedo, light.color, n, light.dir) +
                           BlinnPhong_Specular(_SpecularColor.rgb, light.color, n, h,
                                               BlinnPhong_Exponent(_Smoothness));
                return float4(ClampToHalfRange(c), texel.a);
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
