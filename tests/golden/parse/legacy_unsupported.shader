// What Kiln recognises but does not support: fixed-function commands (ignored with a warning),
// GLSL programs and surface shaders (errors).
Shader "Golden/Legacy"
{
    SubShader
    {
        CGPROGRAM
        #pragma surface surf Lambert
        ENDCG

        Pass
        {
            Lighting Off
            SetTexture [_MainTex] { combine texture }
            GLSLPROGRAM
            void main() {}
            ENDGLSL
        }
    }
}
