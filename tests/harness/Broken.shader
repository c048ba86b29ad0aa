// A deliberately broken shader for kiln test, each bug in one variant: BRIGHT divides by
// `_Exponent`, a Range(0, 4), so its minimum gives infinities; LEAK adds a term of the light's
// direction not scaled by its colour, so a light of intensity 0 still lights; the additive pass's
// POINT variant returns negative light, which darkens what the base pass drew.
Shader "Test/Broken"
{
    Properties
    {
        _Color ("Color", Color) = (0.8, 0.8, 0.8, 1)
        _Exponent ("Exponent", Range(0, 4)) = 1
    }

    CGINCLUDE
    #include "UnityCG.cginc"
    float4 _Color;
    float _Exponent;
    float4 _LightColor0;
    float4 _WorldSpaceLightPos0;

    struct v2f {
        float4 pos : SV_POSITION;
        float3 normal : TEXCOORD0;
    };

    v2f vert(float4 p : POSITION, float3 n : NORMAL) {
        v2f o;
        o.pos = UnityObjectToClipPos(p);
        o.normal = UnityObjectToWorldNormal(n);
        return o;
    }

    float4 base(v2f i) : SV_Target {
        float ndl = saturate(dot(normalize(i.normal), normalize(_WorldSpaceLightPos0.xyz)));
        float3 c = _Color.rgb * _LightColor0.rgb * ndl;
    #if defined(BRIGHT)
        c *= 1.0 / _Exponent;  // infinite at the Range minimum
    #endif
    #if defined(LEAK)
        c += 0.2 * ndl;  // not scaled by _LightColor0
    #endif
        return float4(c, 1);
    }

    float4 add(v2f i) : SV_Target {
        float ndl = saturate(dot(normalize(i.normal), normalize(_WorldSpaceLightPos0.xyz)));
        float3 c = _Color.rgb * _LightColor0.rgb * ndl;
    #if defined(POINT)
        c = -c;  // subtracts light
    #endif
        return float4(c, 1);
    }
    ENDCG

    SubShader
    {
        Pass
        {
            Name "FORWARD"
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment base
            #pragma multi_compile _ BRIGHT
            #pragma multi_compile _ LEAK
            ENDCG
        }

        Pass
        {
            Name "FORWARD_DELTA"
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment add
            #pragma multi_compile_fragment DIRECTIONAL POINT
            ENDCG
        }
    }
}
