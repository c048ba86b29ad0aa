Shader "Fuzz/Hlsl" {
    HLSLINCLUDE
    float4 _Tint;
    float4 Shade(float4 c) { return c * _Tint; }
    ENDHLSL
    SubShader { Pass {
        ZWrite Off Blend SrcAlpha OneMinusSrcAlpha Cull [_Cull]
        HLSLPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        float4x4 unity_ObjectToWorld; float4x4 unity_MatrixVP;
        float4 vert(float3 p : POSITION) : SV_POSITION {
            return mul(unity_MatrixVP, mul(unity_ObjectToWorld, float4(p, 1))); }
        float4 frag() : SV_Target { return Shade(float4(1, 1, 1, 0.5)); }
        ENDHLSL
    } }
}
