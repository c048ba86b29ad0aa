// LambertAmbient: Lambert plus the lecture's constant ambient term, c_r * (c_a + c_l max(0, n . l)).
Shader "Kiln/LambertAmbient"
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
            #pragma fragment LambertAmbientFragment
            #include "MaterialCommon.cginc"

            float4 _Color;

            float4 LambertAmbientFragment(Interpolators i) : SV_TARGET {
                float3 n = SafeNormalize(i.normal);
                UnityLight light = PixelLight(i.worldPos, n);
                float3 c = Ambient_Constant(_Color.rgb, unity_AmbientSky.rgb) +
                           Lambert_Diffuse(_Color.rgb, light.color, n, light.dir);
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
