// keyword-declarations, K7004: shader_feature of a keyword the engine sets for each draw (a light
// type, a shadow keyword) builds it only where a material enables it, so the engine's lookups
// miss. multi_compile of the same keyword is right and not reported.
Shader "Lint/EngineShaderFeature"
{
    SubShader
    {
        Pass
        {
            Name "ADD"
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            // expect-warning@+1 K7004 {{'POINT' is set by the engine for each draw}}
            #pragma shader_feature POINT
            #pragma multi_compile _ SPOT
            float4 v(float4 p : POSITION) : SV_POSITION {
            #if defined(POINT) || defined(SPOT)
                p.x += 1;
            #endif
                return p;
            }
            float4 f() : SV_Target {
            #if defined(POINT)
                return 1;
            #elif defined(SPOT)
                return 0.5;
            #else
                return 0;
            #endif
            }
            ENDCG
        }
    }
}
