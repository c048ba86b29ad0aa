// MultiLight: the lecture's multiple-lights shader made robust. ForwardBase shades the main
// directional light, SH ambient and up to four per-vertex point lights (VERTEXLIGHT_ON);
// ForwardAdd adds one more pixel light per pass (DIRECTIONAL, POINT or SPOT), blended additively
// without depth writes. Physically based (specular workflow) as in the lecture.
Shader "Kiln/MultiLight"
{
    Properties
    {
        [MainColor] _Color ("Color", Color) = (1, 1, 1, 1)
        [MainTexture] _MainTex ("Albedo", 2D) = "white" {}
        _SpecularColor ("Specular", Color) = (0.2, 0.2, 0.2, 1)
        _Smoothness ("Smoothness", Range(0, 1)) = 0.5
    }

    CGINCLUDE
    #include "MaterialCommon.cginc"

    float4 _Color;
    sampler2D _MainTex;
    float4 _MainTex_ST;
    float4 _SpecularColor;
    float _Smoothness;

    struct MultiLightInterpolators {
        float4 position : SV_POSITION;
        float2 uv : TEXCOORD0;
        float3 normal : TEXCOORD1;
        float3 worldPos : TEXCOORD2;
    #if defined(VERTEXLIGHT_ON)
        float3 vertexLight : TEXCOORD3;  // diffuse light of the four vertex lights
    #endif
    };

    MultiLightInterpolators MultiLightVertex(VertexData v) {
        Interpolators common = ForwardVertex(v);
        MultiLightInterpolators i;
        i.position = common.position;
        i.uv = TRANSFORM_TEX(common.uv, _MainTex);
        i.normal = common.normal;
        i.worldPos = common.worldPos;
    #if defined(VERTEXLIGHT_ON)
        i.vertexLight = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
                                          unity_LightColor[0].rgb, unity_LightColor[1].rgb,
                                          unity_LightColor[2].rgb, unity_LightColor[3].rgb,
                                          unity_4LightAtten0, i.worldPos, i.normal);
    #endif
        return i;
    }

    // CGINCLUDE text precedes each pass's CGPROGRAM, so a `#define` in the pass would come too
    // late for this code: the base pass selects ambient through its own entry point instead.
    float4 MultiLightShade(MultiLightInterpolators i, bool basePass) {
        float4 texel = tex2D(_MainTex, i.uv) * _Color;
        float oneMinusReflectivity;
        float3 albedo = EnergyConservationBetweenDiffuseAndSpecular(texel.rgb, _SpecularColor.rgb,
                                                                    oneMinusReflectivity);
        float3 n = SafeNormalize(i.normal);
        UnityIndirect indirect;
        indirect.diffuse = basePass ? ShadeSH9(float4(n, 1.0)) : 0;
        indirect.specular = 0;
    #if defined(VERTEXLIGHT_ON)
        indirect.diffuse += i.vertexLight;
    #endif
        float4 c = UNITY_BRDF_PBS(albedo, _SpecularColor.rgb, oneMinusReflectivity, _Smoothness, n,
                                  ViewDirection(i.worldPos), PixelLight(i.worldPos, n), indirect);
        return float4(c.rgb, texel.a);
    }

    float4 MultiLightBaseFragment(MultiLightInterpolators i) : SV_TARGET {
        return MultiLightShade(i, true);
    }

    float4 MultiLightAddFragment(MultiLightInterpolators i) : SV_TARGET {
        return MultiLightShade(i, false);
    }
    ENDCG

    SubShader
    {
        Tags { "RenderType" = "Opaque" }

        Pass
        {
            Name "FORWARD"
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma vertex MultiLightVertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment MultiLightBaseFragment
            #pragma multi_compile _ VERTEXLIGHT_ON
            ENDCG
        }

        Pass
        {
            Name "FORWARD_DELTA"
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off

            CGPROGRAM
            #pragma vertex MultiLightVertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment MultiLightAddFragment
            #pragma multi_compile_fragment DIRECTIONAL POINT SPOT
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
