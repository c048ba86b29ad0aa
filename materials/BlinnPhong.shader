// BlinnPhong: ambient + Lambert diffuse + Blinn-Phong specular c_s c_l max(0, n . h)^(100 s),
// the lecture's "Diffuse and specular" model. Smoothness 0 gives a constant highlight of 1
// (pow(0, 0) = 1 by the limit; SafePow), not NaN.
Shader "Kiln/BlinnPhong"
{
    Properties
    {
        [MainColor] _Color ("Color", Color) = (1, 1, 1, 1)
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
            #pragma fragment BlinnPhongFragment
            #include "MaterialCommon.cginc"

            float4 _Color;
            float4 _SpecularColor;
            float _Smoothness;

            float4 BlinnPhongFragment(Interpolators i) : SV_TARGET {
                float3 n = SafeNormalize(i.normal);
                float3 v = ViewDirection(i.worldPos);
                UnityLight light = PixelLight(i.worldPos, n);
                float3 h = BlinnPhong_HalfVector(light.dir, v);
                float3 c = Ambient_Constant(_Color.rgb, unity_AmbientSky.rgb) +
                           Lambert_Diffuse(_Color.rgb, light.color, n, light.dir) +
                           BlinnPhong_Specular(_SpecularColor.rgb, light.color, n, h,
                                               BlinnPhong_Exponent(_Smoothness));
                return float4(ClampToHalfRange(c), _Color.a);
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
