// property-keywords, K7010: a pass declares the keyword [Toggle] on a property would switch
// (_GLOW_ON for _Glow), but the property has no [Toggle], so setting it switches nothing. A
// property with its [Toggle] is not reported.
Shader "Lint/KeywordWithoutToggle"
{
    Properties
    {
        _Glow ("Glow", Float) = 0 // expect-warning K7010 {{a pass declares '_GLOW_ON', the keyword [Toggle] on property '_Glow' would switch, but the property has no [Toggle]}}
        [Toggle] _Shine ("Shine", Float) = 0
    }
    SubShader
    {
        Pass
        {
            Name "BASE"
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            #pragma shader_feature _GLOW_ON
            #pragma shader_feature _SHINE_ON
            float _Glow;
            float4 v(float4 p : POSITION) : SV_POSITION {
            #if defined(_GLOW_ON) || defined(_SHINE_ON)
                p.x += 1;
            #endif
                return p;
            }
            float4 f() : SV_Target {
                float4 c = _Glow;
            #if defined(_GLOW_ON)
                c.r = 1;
            #endif
            #if defined(_SHINE_ON)
                c.g = 1;
            #endif
                return c;
            }
            ENDCG
        }
    }
}
