// GrabPass (issue 38), drawn by tests/cli/stages_test.cpp. Each fragment shows 1 - what was behind
// it when its GrabPass copied the colour target, so a copy that is missing, late or from the wrong
// target changes the colours the test checks.
// An unnamed GrabPass: copied before every object that has it.
Shader "Test/GrabEach" {
    SubShader {
        Tags { "Queue" = "Transparent" }
        GrabPass { Name "BEHIND" }
        Pass {
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
                return float4(1 - tex2Dproj(_GrabTexture, i.grab).rgb, 1);
            }
            ENDCG
        }
    }
}
