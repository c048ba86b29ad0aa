// Includes UnityCG.cginc: the installed kiln must find its templates relative to itself.
Shader "Consumer/Lit" {
    Properties {
        _Color ("Color", Color) = (1, 1, 1, 1)
    }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            Blend SrcAlpha OneMinusSrcAlpha
            ZWrite Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ HALF_TINT
            #include "UnityCG.cginc"
            float4 _Color;
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
            float4 frag() : SV_Target {
            #ifdef HALF_TINT
                return _Color * 0.5;  // the keyword changes the code, so it is no alias
            #endif
                return _Color;
            }
            ENDCG
        }
    }
}
