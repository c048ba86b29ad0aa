// KILN_SHADER_NAME: a physically based shader for many lights, written by
// `kiln new --template multilight`. The renderer draws ForwardBase once (main directional light
// plus SH ambient) and ForwardAdd once per further light, adding it with Blend One One; the
// light type is the DIRECTIONAL / POINT / SPOT keyword and UNITY_LIGHT_ATTENUATION applies the
// matching falloff (templates/AutoLight.cginc).
Shader "KILN_SHADER_NAME"
{
    Properties
    {
        [MainColor] _Color ("Color", Color) = (1, 1, 1, 1)
        [MainTexture] _MainTex ("Albedo", 2D) = "white" {}
        _SpecularColor ("Specular", Color) = (0.2, 0.2, 0.2, 1)
        _Smoothness ("Smoothness", Range(0, 1)) = 0.5
    }

    CGINCLUDE
    #include "UnityPBSLighting.cginc"
    #include "AutoLight.cginc"

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

    // CGINCLUDE text comes before each pass's CGPROGRAM, so a `#define` inside a pass would be
    // too late for this code: each pass has its own entry point instead.
    float4 Shade(Interpolators i, bool basePass) {
        float4 texel = tex2D(_MainTex, i.uv) * _Color;
        float oneMinusReflectivity;
        float3 albedo = EnergyConservationBetweenDiffuseAndSpecular(texel.rgb, _SpecularColor.rgb,
                                                                    oneMinusReflectivity);
        float3 n = SafeNormalize(i.normal);
        UnityLight light;
        light.dir = SafeNormalize(UnityWorldSpaceLightDir(i.worldPos));
        UNITY_LIGHT_ATTENUATION(attenuation, 0, i.worldPos);
        light.color = _LightColor0.rgb * attenuation;
        light.ndotl = DotClamped(n, light.dir);
        UnityIndirect indirect;
        indirect.diffuse = basePass ? ShadeSH9(float4(n, 1.0)) : 0;
        indirect.specular = 0;
        float4 c = UNITY_BRDF_PBS(albedo, _SpecularColor.rgb, oneMinusReflectivity, _Smoothness, n,
                                  SafeNormalize(UnityWorldSpaceViewDir(i.worldPos)), light,
                                  indirect);
        return float4(c.rgb, texel.a);
    }

    float4 BaseFragment(Interpolators i) : SV_TARGET { return Shade(i, true); }
    float4 AddFragment(Interpolators i) : SV_TARGET { return Shade(i, false); }
    ENDCG

    SubShader
    {
        Tags { "RenderType" = "Opaque" }

        Pass
        {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex Vertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment BaseFragment
            ENDCG
        }

        Pass
        {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma vertex Vertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment AddFragment
            #pragma multi_compile_fragment DIRECTIONAL POINT SPOT
            ENDCG
        }
    }
}
