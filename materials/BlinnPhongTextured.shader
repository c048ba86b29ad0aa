// BlinnPhongTextured: BlinnPhong with the albedo read from a texture (lecture "Texturing").
Shader "Kiln/BlinnPhongTextured"
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
            #pragma fragment BlinnPhongTexturedFragment
            #include "MaterialCommon.cginc"

            float4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST;
            float4 _SpecularColor;
            float _Smoothness;

            float4 BlinnPhongTexturedFragment(Interpolators i) : SV_TARGET {
                float4 albedo = tex2D(_MainTex, TRANSFORM_TEX(i.uv, _MainTex)) * _Color;
                float3 n = SafeNormalize(i.normal);
                float3 v = ViewDirection(i.worldPos);
                UnityLight light = PixelLight(i.worldPos, n);
                float3 h = BlinnPhong_HalfVector(light.dir, v);
                float3 c = Ambient_Constant(albedo.rgb, unity_AmbientSky.rgb) +
                           Lambert_Diffuse(albedo.rgb, light.color, n, light.dir) +
                           BlinnPhong_Specular(_SpecularColor.rgb, light.color, n, h,
                                               BlinnPhong_Exponent(_Smoothness));
                return float4(ClampToHalfRange(c), albedo.a);
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
