// kiln lint's test shader: every K7xxx finding once, each at a line the test names.
Shader "Test/Wasteful"
{
    Properties
    {
        _Color ("Color", Color) = (1, 1, 1, 1)
        [Toggle(MISSING_KW)] _Missing ("Missing", Float) = 0
        _Glow ("Glow", Float) = 0
        [Toggle(_SHINY)] _Shiny ("Shiny", Float) = 0
    }

    CGINCLUDE
    float4 _Color;
    float4 v(float4 p : POSITION) : SV_POSITION {
    #if defined(BEND)
        p.x += 1;
    #endif
        return p;
    }
    float4 f() : SV_Target {
        float4 c = _Color;
    #if defined(FOG_A) || defined(FOG_B)
        c.rgb *= 0.5;
    #endif
    #if defined(_GLOW_ON)
        c.rgb += 1;
    #endif
    #if defined(_SHINY)
        c.a = 0.5;
    #endif
    #if defined(GLOBALISH) || defined(POINT)
        c.g = 0;
    #endif
        return c;
    }
    ENDCG

    SubShader
    {
        Tags { "Queue" = "Transparent" }

        Pass
        {
            Name "BASE"
            Tags { "LightMode" = "ForwardBase" }
            Blend SrcAlpha OneMinusSrcAlpha
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            #pragma multi_compile _ UNUSED_KW
            #pragma multi_compile _ FOG_A FOG_B
            #pragma multi_compile _ BEND
            #pragma shader_feature _GLOW_ON
            #pragma multi_compile _ _SHINY
            #pragma shader_feature GLOBALISH
            ENDCG
        }

        Pass
        {
            Name "ADD"
            Tags { "LightMode" = "ForwardAdd" "KilnMaxVariants" = "8" }
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            #pragma shader_feature POINT
            #pragma multi_compile _ FOG_A
            ENDCG
        }

        Pass
        {
            Name "GBUFFER"
            Tags { "LightMode" = "Deferred" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            ENDCG
        }
    }
}
