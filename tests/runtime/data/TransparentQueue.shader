// A shader in the Transparent queue with a Deferred pass: Unity draws it forward on the deferred
// path, after the opaque objects (docs/runtime.md, "Deferred path"); so does Kiln.
Shader "KilnTest/TransparentQueue"
{
    Properties
    {
        _Color ("Color", Color) = (0.2, 0.4, 0.8, 0.5)
    }

    CGINCLUDE
    #include "UnityCG.cginc"
    float4 _Color;

    float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
    float4 frag() : SV_Target { return _Color; }

    void gbuffer(float4 p : SV_POSITION, out float4 rt0 : SV_Target0, out float4 rt1 : SV_Target1,
                 out float4 rt2 : SV_Target2, out float4 rt3 : SV_Target3) {
        rt0 = _Color;
        rt1 = 0;
        rt2 = float4(0.5, 1, 0.5, 1);
        rt3 = float4(0, 0, 0, 1);
    }
    ENDCG

    SubShader
    {
        Tags { "Queue" = "Transparent" "RenderType" = "Transparent" }

        Pass
        {
            Name "FORWARD"
            Tags { "LightMode" = "ForwardBase" }
            Blend SrcAlpha OneMinusSrcAlpha
            ZWrite Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            ENDCG
        }

        Pass
        {
            Name "DEFERRED"
            Tags { "LightMode" = "Deferred" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment gbuffer
            ENDCG
        }
    }
}
