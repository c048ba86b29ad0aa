// UsePass (issue 38): uses_outline.shader copies this shader's OUTLINE pass; a green shell drawn
// front-face-culled, pushed out along the normals. tests/cli/stages_test.cpp draws both.
Shader "Test/Outlined" {
    SubShader {
        Pass {
            Name "Outline"
            Tags { "LightMode" = "Always" }
            Cull Front
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 p : POSITION, float3 n : NORMAL) : SV_POSITION { return UnityObjectToClipPos(p + float4(n * 0.05, 0)); }
            float4 frag() : SV_Target { return float4(0, 1, 0, 1); }
            ENDCG
        }
    }
}
