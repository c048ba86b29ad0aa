// keyword-declarations, K7007: one keyword in sets of two passes that overlap but differ, so it
// has two sets of companions. The same set in both passes is not reported.
Shader "Lint/KeywordDeclaredTwoWays"
{
    CGINCLUDE
    float4 v(float4 p : POSITION) : SV_POSITION {
    #if defined(FOG_A) || defined(FOG_B) || defined(SAME_KW)
        p.x += 1;
    #endif
        return p;
    }
    float4 f() : SV_Target {
        float4 c = 1;
    #if defined(FOG_A)
        c.r = 0;
    #elif defined(FOG_B)
        c.g = 0;
    #endif
    #if defined(SAME_KW)
        c.b = 0;
    #endif
        return c;
    }
    ENDCG
    SubShader
    {
        Pass
        {
            Name "FIRST"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            #pragma multi_compile _ FOG_A FOG_B
            #pragma multi_compile _ SAME_KW
            ENDCG
        }
        Pass
        {
            Name "SECOND"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            // expect-warning@+1 K7007 {{keyword 'FOG_A' is declared by '#pragma multi_compile _ FOG_A' in pass "SECOND" and by '#pragma multi_compile _ FOG_A FOG_B' in pass "FIRST"}}
            #pragma multi_compile _ FOG_A
            #pragma multi_compile _ SAME_KW
            ENDCG
        }
    }
}
