// GrabPass (issue 38), drawn by tests/cli/stages_test.cpp. Each fragment shows 1 - what was behind
// it when its GrabPass copied the colour target, so a copy that is missing, late or from the wrong
// target changes the colours the test checks.
// An opaque red pass, a GrabPass of it, then a pass showing the grabbed red inverted: cyan.
Shader "Test/GrabInvert" {
    SubShader {
        Pass {
            Name "RED"
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
            float4 frag() : SV_Target { return float4(1, 0, 0, 1); }
            ENDCG
        }
        GrabPass { }
        Pass {
            Name "INVERT"
            ZTest LEqual
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            sampler2D _GrabTexture;
            struct v2f { float4 pos : SV_POSITION; float4 grab : TEXCOORD0; };
            v2f vert(float4 p : POSITION) {
                v2f o;
                o.pos = UnityObjectToClipPos(p);
                o.grab = ComputeGrabScreenPos(o.pos);
                return o;
            }
            float4 frag(v2f i) : SV_Target {
                return float4(1 - tex2Dproj(_GrabTexture, UNITY_PROJ_COORD(i.grab)).rgb, 1);
            }
            ENDCG
        }
    }
}
