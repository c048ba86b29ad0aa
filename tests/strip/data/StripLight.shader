// StripLight: a MultiLight-style shader for the scene-stripping tests. ForwardBase shades the main
// directional light, SH ambient and up to four vertex point lights (VERTEXLIGHT_ON); ForwardAdd
// adds one pixel light per pass (DIRECTIONAL, POINT or SPOT); a Deferred pass writes a G-buffer,
// which the forward path never draws. Full product: 2 + 3 + 2 = 7 variants.
Shader "Test/StripLight"
{
    Properties
    {
        _Color ("Color", Color) = (1, 1, 1, 1)
        _Smoothness ("Smoothness", Range(0, 1)) = 0.5
    }

    CGINCLUDE
    #include "MaterialCommon.cginc"

    float4 _Color;
    float _Smoothness;

    struct StripInterpolators {
        float4 position : SV_POSITION;
        float3 normal : TEXCOORD0;
        float3 worldPos : TEXCOORD1;
    #if defined(VERTEXLIGHT_ON)
        float3 vertexLight : TEXCOORD2;
    #endif
    };

    StripInterpolators StripVertex(VertexData v) {
        Interpolators common = ForwardVertex(v);
        StripInterpolators i;
        i.position = common.position;
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

    float4 StripShade(StripInterpolators i, bool basePass) {
        float3 n = SafeNormalize(i.normal);
        UnityIndirect indirect;
        indirect.diffuse = basePass ? ShadeSH9(float4(n, 1.0)) : 0;
        indirect.specular = 0;
    #if defined(VERTEXLIGHT_ON)
        indirect.diffuse += i.vertexLight;
    #endif
        float4 c = UNITY_BRDF_PBS(_Color.rgb, 0.04, 0.96, _Smoothness, n, ViewDirection(i.worldPos),
                                  PixelLight(i.worldPos, n), indirect);
        return float4(c.rgb, 1.0);
    }

    float4 StripBaseFragment(StripInterpolators i) : SV_TARGET { return StripShade(i, true); }
    float4 StripAddFragment(StripInterpolators i) : SV_TARGET { return StripShade(i, false); }

    // Unity's layout (UnityGBuffer.cginc): diffuse, specular and smoothness, normal, light.
    void StripGBuffer(StripInterpolators i, out float4 rt0 : SV_Target0,
                      out float4 rt1 : SV_Target1, out float4 rt2 : SV_Target2,
                      out float4 rt3 : SV_Target3) {
        rt0 = _Color;
    #if defined(UNITY_HDR_ON)
        rt0.rgb *= 2.0;
    #endif
        rt1 = float4(0.04, 0.04, 0.04, _Smoothness);
        rt2 = float4(SafeNormalize(i.normal) * 0.5 + 0.5, 1.0);
        rt3 = float4(0, 0, 0, 1);
    }
    ENDCG

    SubShader
    {
        Pass
        {
            Name "FORWARD"
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex StripVertex
            #pragma fragment StripBaseFragment
            #pragma target 3.0
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
            #pragma vertex StripVertex
            #pragma fragment StripAddFragment
            #pragma target 3.0
            #pragma multi_compile DIRECTIONAL POINT SPOT
            ENDCG
        }

        Pass
        {
            Name "DEFERRED"
            Tags { "LightMode" = "Deferred" }
            CGPROGRAM
            #pragma vertex StripVertex
            #pragma fragment StripGBuffer
            #pragma target 3.0
            #pragma multi_compile _ UNITY_HDR_ON
            ENDCG
        }
    }
}
