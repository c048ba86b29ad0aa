// GeometryProbe: writes the interpolated world position (or, with _PROBE_NORMAL, the world
// normal before renormalization) that the shipped materials' fragment stages see. The reference
// tests evaluate the CPU lighting models on exactly these per-pixel inputs. Same vertex stage as
// the shipped forward materials (MaterialCommon.cginc's ForwardVertex).
Shader "KilnTest/GeometryProbe"
{
    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex ForwardVertex
            #pragma fragment ProbeFragment
            #pragma shader_feature _ _PROBE_NORMAL
            #include "MaterialCommon.cginc"

            float4 ProbeFragment(Interpolators i) : SV_TARGET {
            #if defined(_PROBE_NORMAL)
                return float4(i.normal, 1.0);
            #else
                return float4(i.worldPos, 1.0);
            #endif
            }
            ENDCG
        }
    }
}
