// keyword-effect, K7002: a set whose keywords change only one stage builds that stage's twin
// variants for nothing. Sets already declared for one stage (_vertex) are not reported, nor are
// sets that change both stages.
Shader "Lint/KeywordOneStage"
{
    SubShader
    {
        Pass
        {
            Name "BASE"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            // expect-warning@+1 K7002 {{keywords _ BEND of pass "BASE" change only its vertex stage}}
            #pragma multi_compile _ BEND
            #pragma multi_compile_vertex _ SWAY
            #pragma multi_compile _ BOTH
            float4 v(float4 p : POSITION) : SV_POSITION {
            #if defined(BEND)
                p.x += 1;
            #endif
            #if defined(SWAY)
                p.y += 1;
            #endif
            #if defined(BOTH)
                p.z += 1;
            #endif
                return p;
            }
            float4 f() : SV_Target {
            #if defined(BOTH)
                return 1;
            #else
                return 0;
            #endif
            }
            ENDCG
        }
    }
}
