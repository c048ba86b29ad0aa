// keyword-declarations, K7006: shader_feature of a keyword that looks set from code (no property
// drives it, and it does not start with '_' as material keywords do). Not reported: an
// underscore keyword, a _local one, and one a [Toggle] drives.
Shader "Lint/ShaderFeatureLooksGlobal"
{
    Properties
    {
        [Toggle(DRIVEN)] _Driven ("Driven", Float) = 0
    }
    SubShader
    {
        Pass
        {
            Name "BASE"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            // expect-warning@+1 K7006 {{'GLOBALISH' looks like a global keyword set from code}}
            #pragma shader_feature GLOBALISH
            #pragma shader_feature _MATERIALISH
            #pragma shader_feature_local LOCALISH
            #pragma shader_feature DRIVEN
            float4 v(float4 p : POSITION) : SV_POSITION {
            #if defined(GLOBALISH)
                p.x += 1;
            #endif
            #if defined(_MATERIALISH)
                p.y += 1;
            #endif
            #if defined(LOCALISH)
                p.z += 1;
            #endif
            #if defined(DRIVEN)
                p.w += 1;
            #endif
                return p;
            }
            float4 f() : SV_Target {
                float4 c = 0;
            #if defined(GLOBALISH)
                c.r = 1;
            #endif
            #if defined(_MATERIALISH)
                c.g = 1;
            #endif
            #if defined(LOCALISH)
                c.b = 1;
            #endif
            #if defined(DRIVEN)
                c.a = 1;
            #endif
                return c;
            }
            ENDCG
        }
    }
}
