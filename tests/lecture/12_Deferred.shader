// Lecture 06 (Light), Deferred: the deferred-shader section assembled from the slides. The
// G-buffer pass writes four render targets (albedo and occlusion, specular, world normal,
// emission); the forward pass writes one colour.
Shader "Lecture/Deferred"
{
    Properties
    {
        _Color("Color", Color) = (1, 1, 1, 1)
        _Smoothness("Smoothness", Range(0, 1)) = 0.5
        _SpecularColor("Specular", Color) = (0.5, 0.5, 0.5)
        _MainTex("Albedo", 2D) = "white" {}
    }

    CGINCLUDE
    #include "UnityPBSLighting.cginc"

    float4 _Color;
    float _Smoothness;
    float4 _SpecularColor;
    sampler2D _MainTex;
    float4 _MainTex_ST;

    struct VertexData {
        float4 position : POSITION;
        float3 normal : NORMAL;
        float2 uv : TEXCOORD0;
    };

    struct Interpolators {
        float4 position : SV_POSITION;
        float2 uv : TEXCOORD0;
        float3 normal : NORMAL;
        float4 worldpos : TEXCOORD1;
    };

    Interpolators MyVertexProgram(VertexData vert) {
        Interpolators i;
        i.position = UnityObjectToClipPos(vert.position);
        i.worldpos = mul(unity_ObjectToWorld, vert.position);
        i.normal = UnityObjectToWorldNormal(vert.normal);
        i.uv = TRANSFORM_TEX(vert.uv, _MainTex);
        return i;
    }

    struct FragmentOutput{
        #if defined(DEFERRED_PASS)
            float4 gBuffer0 : SV_Target0;
            float4 gBuffer1 : SV_Target1;
            float4 gBuffer2 : SV_Target2;
            float4 gBuffer3 : SV_Target3;
        #else
            float4 color : SV_Target;
        #endif
    };

    FragmentOutput MyFragmentProgram (Interpolators i) {
        float3 albedo = tex2D(_MainTex, i.uv).rgb * _Color.rgb;
        float oneMinusReflectivity;
        albedo = EnergyConservationBetweenDiffuseAndSpecular(albedo, _SpecularColor.rgb,
                                                             oneMinusReflectivity);
        FragmentOutput output;
        #if defined(DEFERRED_PASS)
            output.gBuffer0 = float4(albedo, 1);
            output.gBuffer1 = float4(_SpecularColor.rgb, _Smoothness);
            output.gBuffer2 = float4(normalize(i.normal) * 0.5 + 0.5, 1);
            output.gBuffer3 = float4(0, 0, 0, 1);
        #else
            float3 lightDir = _WorldSpaceLightPos0.xyz;
            float3 lightColor = _LightColor0.rgb;
            output.color = float4(albedo * (unity_AmbientSky.rgb + lightColor *
                DotClamped(lightDir, normalize(i.normal))), 1);
        #endif
        return output;
    }
    ENDCG

    SubShader
    {
        Pass
        {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma target 3.0
            #pragma vertex MyVertexProgram
            #pragma fragment MyFragmentProgram
            ENDCG
        }
        Pass
        {
            Tags { "LightMode" = "Deferred" }
            CGPROGRAM
            #pragma target 3.0
            #pragma vertex MyVertexProgram
            #pragma fragment MyFragmentProgram
            #define DEFERRED_PASS
            ENDCG
        }
    }
}
