// Live-edit test shader (the original): two untagged passes, an
// unlit colour and a constant added over it (Blend One One).
Shader "Test/Reload"
{
    Properties
    {
        _Color ("Color", Color) = (0.5, 0.5, 0.5, 1)
    }
    SubShader
    {
        CGINCLUDE
        #include "UnityCG.cginc"
        float4 _Color;

        float4 Vertex(float4 position : POSITION) : SV_POSITION {
            return UnityObjectToClipPos(position);
        }
        ENDCG

        Pass
        {
            CGPROGRAM
            #pragma vertex Vertex
            #pragma fragment Base
            float4 Base() : SV_Target {
                return _Color;
            }
            ENDCG
        }

        Pass
        {
            Blend One One
            CGPROGRAM
            #pragma vertex Vertex
            #pragma fragment Added
            float4 Added() : SV_Target {
                return float4(0.0, 0.0, 0.25, 0.0);
            }
            ENDCG
        }
    }
}
