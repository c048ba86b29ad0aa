// property-keywords, K7009: a [Toggle(KW)] or [KeywordEnum] property switches a keyword no pass
// declares, so the switch does nothing. A property whose keyword a pass declares is not
// reported.
Shader "Lint/PropertyKeywordUndeclared"
{
    Properties
    {
        [Toggle(MISSING_KW)] _Missing ("Missing", Float) = 0 // expect-warning K7009 {{property '_Missing' ([Toggle]) switches keyword 'MISSING_KW', which no pass declares}}
        [Toggle(_DECLARED)] _Declared ("Declared", Float) = 0
        // expect-warning@+1 K7009 {{switches keyword '_MODE_TWO', which no pass declares}}
        [KeywordEnum(One, Two)] _Mode ("Mode", Float) = 0
    }
    SubShader
    {
        Pass
        {
            Name "BASE"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            #pragma shader_feature _DECLARED
            #pragma shader_feature _MODE_ONE
            float4 v(float4 p : POSITION) : SV_POSITION {
            #if defined(_DECLARED) || defined(_MODE_ONE)
                p.x += 1;
            #endif
                return p;
            }
            float4 f() : SV_Target {
            #if defined(_DECLARED)
                return 1;
            #elif defined(_MODE_ONE)
                return 0.5;
            #else
                return 0;
            #endif
            }
            ENDCG
        }
    }
}
