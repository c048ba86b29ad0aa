// keyword-limits, K7008: more local keywords in one shader than Unity before 2021.2 allows (64).
// The keywords change no code, so the fixture silences what keyword-effect says about that.
// lint-args: -Wno-K7001 -Wno-K7003
// expect-warning@+1 K7008 {{shader 'Lint/TooManyKeywords' declares 65 local keywords; Unity before 2021.2 allows 64 per shader}}
Shader "Lint/TooManyKeywords"
{
    SubShader
    {
        Pass
        {
            Name "BASE"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            #pragma shader_feature_local _ KW01 KW02 KW03 KW04 KW05 KW06 KW07 KW08 KW09 KW10 KW11 KW12 KW13 KW14 KW15 KW16 KW17 KW18 KW19 KW20 KW21 KW22 KW23 KW24 KW25 KW26 KW27 KW28 KW29 KW30 KW31 KW32 KW33 KW34 KW35 KW36 KW37 KW38 KW39 KW40 KW41 KW42 KW43 KW44 KW45 KW46 KW47 KW48 KW49 KW50 KW51 KW52 KW53 KW54 KW55 KW56 KW57 KW58 KW59 KW60 KW61 KW62 KW63 KW64 KW65
            float4 v(float4 p : POSITION) : SV_POSITION { return p; }
            float4 f() : SV_Target { return 1; }
            ENDCG
        }
    }
}
