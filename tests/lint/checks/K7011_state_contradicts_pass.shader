// pass-state, K7011: render state the pass's LightMode or Queue contradicts. Reported: a
// ForwardAdd pass that replaces instead of adding and writes depth, a transparent pass writing
// depth, a Deferred pass that blends. Not reported: a ForwardAdd pass with Blend One One and
// ZWrite Off, and state a material property sets (Blend [_Src] [_Dst]).
// lint-args: -Werror=K7011
Shader "Lint/StateContradictsPass"
{
    Properties
    {
        [Enum(UnityEngine.Rendering.BlendMode)] _Src ("Src", Float) = 1
        [Enum(UnityEngine.Rendering.BlendMode)] _Dst ("Dst", Float) = 0
    }
    CGINCLUDE
    float4 v(float4 p : POSITION) : SV_POSITION { return p; }
    float4 f() : SV_Target { return 1; }
    ENDCG
    SubShader
    {
        Tags { "Queue" = "Transparent" }
        // expect-error@+1 K7011 {{pass "BASE" is in the transparent queue (Transparent) but writes depth}}
        Pass
        {
            Name "BASE"
            Tags { "LightMode" = "ForwardBase" }
            Blend SrcAlpha OneMinusSrcAlpha
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            ENDCG
        }
        // expect-error@+2 K7011 {{pass "ADD" (LightMode ForwardAdd) has no Blend}}
        // expect-error@+1 K7011 {{pass "ADD" (LightMode ForwardAdd) writes depth}}
        Pass
        {
            Name "ADD"
            Tags { "LightMode" = "ForwardAdd" }
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            ENDCG
        }
        Pass
        {
            Name "ADD_RIGHT"
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            ENDCG
        }
        Pass
        {
            Name "ADD_BY_MATERIAL"
            Tags { "LightMode" = "ForwardAdd" }
            Blend [_Src] [_Dst]
            ZWrite Off
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            ENDCG
        }
        Pass // expect-error K7011 {{pass "GBUFFER" (LightMode Deferred) blends}}
        {
            Name "GBUFFER"
            Tags { "LightMode" = "Deferred" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma vertex v
            #pragma fragment f
            ENDCG
        }
    }
}
