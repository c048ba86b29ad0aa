// GrabPass (issue 38), drawn by tests/cli/stages_test.cpp. Each fragment shows 1 - what was behind
// it when its GrabPass copied the colour target, so a copy that is missing, late or from the wrong
// target changes the colours the test checks.
// A named GrabPass: copied once per frame, by the first object; every object samples that copy.
Shader "Test/GrabNamed" {
    SubShader {
        Tags { "Queue" = "Transparent" }
        GrabPass { "_Behind" }
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            sampler2D _Behind;
            float4 _Behind_TexelSize;
            struct v2f { float4 pos : SV_POSITION; float4 grab : TEXCOORD0; };
            v2f vert(float4 p : POSITION) {
                v2f o;
                o.pos = UnityObjectToClipPos(p);
                o.grab = ComputeGrabScreenPos(o.pos);
                return o;
            }
            float4 frag(v2f i) : SV_Target {
                float2 uv = i.grab.xy / i.grab.w + 0 * _Behind_TexelSize.xy;
                return float4(1 - tex2D(_Behind, uv).rgb, 1);
            }
            ENDCG
        }
    }
}
