// keyword-effect, K7001: a keyword that no code reads changes nothing; every variant with it is
// the variant without it. A keyword both stages read is not reported.
Shader "Lint/KeywordChangesNothing"
{
    SubShader
    {
        Pass
        {
            Name "BASE"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            // expect-warning@+1 K7001 {{keyword 'UNUSED_KW' of pass "BASE" changes no code}}
            #pragma multi_compile _ UNUSED_KW
            #pragma multi_compile _ USED_KW
            float4 v(float4 p : POSITION) : SV_POSITION {
            #if defined(USED_KW)
                p.x += 1;
            #endif
                return p;
            }
            float4 f() : SV_Target {
            #if defined(USED_KW)
                return 1;
            #else
                return 0;
            #endif
            }
            ENDCG
        }
    }
}
