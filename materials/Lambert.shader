// Lambert: c = c_r * c_l * max(0, n . l), the lecture's first lighting model (directional light).
Shader "Kiln/Lambert"
{
    Properties
    {
        [MainColor] _Color ("Color", Color) = (1, 1, 1, 1)
    }
    SubShader
    {
        Tags { "RenderType" = "Opaque" }

        Pass
        {
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma vertex ForwardVertex
            #pragma fragment LambertFragment
            #include "MaterialCommon.cginc"

            float4 _Color;

            float4 LambertFragment(Interpolators i) : SV_TARGET {
                float3 n = SafeNormalize(i.normal);
                UnityLight light = PixelLight(i.worldPos, n);
                return float4(Lambert_Diffuse(_Color.rgb, light.color, n, light.dir), _Color.a);
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
