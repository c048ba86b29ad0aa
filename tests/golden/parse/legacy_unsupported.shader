// What Kiln recognises but does not support: GLSL programs (an error), and the fixed-function
// commands it does not translate (ignored with a warning). The surface shader parses (its passes
// are generated when it is compiled: driver/surface_passes.h).
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
            SetTexture [_MainTex] { combine texture matrix [_Rotation] }
            Fog { Color (1, 0, 0, 1) }
            GLSLPROGRAM
            void main() {}
            ENDGLSL
        }
    }
}
