// Deferred: the lecture's deferred shader. The Deferred pass writes the G-buffer with four
// render targets (UnityGBuffer.cginc / KilnGBuffer.cginc layout): RT0 diffuse colour and
// occlusion, RT1 specular colour and smoothness, RT2 world normal, RT3 emission + ambient (HDR).
// ForwardBase and ForwardAdd passes shade the same surface when the renderer runs the forward
// path (or draws the object forward); the deferred path's light pass
// (materials/internal/DeferredShading.shader) lights the G-buffer with the same BRDF.
Shader "Kiln/Deferred"
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
    #include "UnityGBuffer.cginc"

    float4 _Color;
    sampler2D _MainTex;
    float4 _MainTex_ST;
    float4 _SpecularColor;
    float _Smoothness;

    struct Surface {
        float3 diffuse;
        float oneMinusReflectivity;
        float alpha;
    };

    Surface ReadSurface(Interpolators i) {
        float4 texel = tex2D(_MainTex, TRANSFORM_TEX(i.uv, _MainTex)) * _Color;
        Surface s;
        s.diffuse = EnergyConservationBetweenDiffuseAndSpecular(texel.rgb, _SpecularColor.rgb,
                                                                s.oneMinusReflectivity);
        s.alpha = texel.a;
        return s;
    }

    struct GBufferOutput {
        float4 gBuffer0 : SV_Target0;
        float4 gBuffer1 : SV_Target1;
        float4 gBuffer2 : SV_Target2;
        float4 gBuffer3 : SV_Target3;
    };

    GBufferOutput GBufferFragment(Interpolators i) {
        Surface s = ReadSurface(i);
        UnityStandardData data;
        data.diffuseColor = s.diffuse;
        data.occlusion = 1.0;
        data.specularColor = _SpecularColor.rgb;
        data.smoothness = _Smoothness;
        data.normalWorld = SafeNormalize(i.normal);
        GBufferOutput o;
        UnityStandardDataToGbuffer(data, o.gBuffer0, o.gBuffer1, o.gBuffer2);
        o.gBuffer3 = GBuffer_EncodeEmission(s.diffuse * ShadeSH9(float4(data.normalWorld, 1.0)));
        return o;
    }

    float4 AddFragment(Interpolators i) : SV_Target {
        Surface s = ReadSurface(i);
        float3 n = SafeNormalize(i.normal);
        UnityIndirect none;
        none.diffuse = 0;
        none.specular = 0;
        float4 c = UNITY_BRDF_PBS(s.diffuse, _SpecularColor.rgb, s.oneMinusReflectivity,
                                  _Smoothness, n, ViewDirection(i.worldPos),
                                  PixelLight(i.worldPos, n), none);
        return float4(c.rgb, s.alpha);
    }

    float4 ForwardFragment(Interpolators i) : SV_Target {
        Surface s = ReadSurface(i);
        float3 n = SafeNormalize(i.normal);
        UnityIndirect indirect;
        indirect.diffuse = ShadeSH9(float4(n, 1.0));
        indirect.specular = 0;
        float4 c = UNITY_BRDF_PBS(s.diffuse, _SpecularColor.rgb, s.oneMinusReflectivity,
                                  _Smoothness, n, ViewDirection(i.worldPos),
                                  PixelLight(i.worldPos, n), indirect);
        return float4(c.rgb, s.alpha);
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
            #pragma vertex ForwardVertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment ForwardFragment
            ENDCG
        }

        Pass
        {
            Name "FORWARD_DELTA"
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma vertex ForwardVertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment AddFragment
            #pragma multi_compile_fragment DIRECTIONAL POINT SPOT
            ENDCG
        }

        Pass
        {
            Name "DEFERRED"
            Tags { "LightMode" = "Deferred" }
            CGPROGRAM
            #pragma vertex ForwardVertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment GBufferFragment
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
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
