// UsePass (issue 38): the outline pass of outlined.shader (beside this file, so found without
// being compiled itself), then an orange forward pass. tests/cli/stages_test.cpp draws it.
Shader "Test/UsesOutline" {
    SubShader {
        UsePass "Test/Outlined/OUTLINE"
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
            float4 frag() : SV_Target { return float4(1, 0.5, 0, 1); }
            ENDCG
        }
    }
}
