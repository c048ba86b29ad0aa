// keyword-declarations, K7005: multi_compile of keywords only material properties set builds
// every combination, where shader_feature would build those materials use. A set with a keyword
// code sets is not reported.
Shader "Lint/MaterialMultiCompile"
{
    Properties
    {
        [Toggle(_SHINY)] _Shiny ("Shiny", Float) = 0
        [Toggle(_MATTE)] _Matte ("Matte", Float) = 0
    }
    SubShader
    {
        Pass
        {
            Name "BASE"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            // expect-warning@+1 K7005 {{only material properties set _ _SHINY ([Toggle]/[KeywordEnum]), yet '#pragma multi_compile' builds every combination}}
            #pragma multi_compile _ _SHINY
            #pragma multi_compile _ _MATTE FROM_CODE
            float4 v(float4 p : POSITION) : SV_POSITION {
            #if defined(_SHINY) || defined(_MATTE) || defined(FROM_CODE)
                p.x += 1;
            #endif
                return p;
            }
            float4 f() : SV_Target {
                float4 c = 1;
            #if defined(_SHINY)
                c.a = 0.5;
            #endif
            #if defined(_MATTE)
                c.r = 0;
            #elif defined(FROM_CODE)
                c.g = 0;
            #endif
                return c;
            }
            ENDCG
        }
    }
}
