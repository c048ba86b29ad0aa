// keyword-effect, K7003: two keywords of one set that give identical code in every variant; one
// keyword would do. Keywords of a set that differ are not reported.
Shader "Lint/RedundantKeywords"
{
    SubShader
    {
        Pass
        {
            Name "BASE"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            // expect-warning@+1 K7003 {{keywords 'FOG_A' and 'FOG_B' of pass "BASE" give identical SPIR-V}}
            #pragma multi_compile _ FOG_A FOG_B
            #pragma multi_compile _ TINT_RED TINT_GREEN
            float4 v(float4 p : POSITION) : SV_POSITION {
            #if defined(FOG_A) || defined(FOG_B) || defined(TINT_RED) || defined(TINT_GREEN)
                p.x += 1;
            #endif
                return p;
            }
            float4 f() : SV_Target {
                float4 c = 1;
            #if defined(FOG_A) || defined(FOG_B)
                c.rgb *= 0.5;
            #endif
            #if defined(TINT_RED)
                c.r = 0;
            #elif defined(TINT_GREEN)
                c.g = 0;
            #endif
                return c;
            }
            ENDCG
        }
    }
}
