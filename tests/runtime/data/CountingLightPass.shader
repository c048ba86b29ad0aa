// A replacement for the deferred path's light pass (Hidden/Internal-DeferredShading) that adds 1/8
// of red per light to every pixel it shades, whatever the light: the image then shows which
// pixels each light's draws reached. Same passes and render state as the shipped shader.
Shader "Hidden/Internal-DeferredShading"
{
    CGINCLUDE
    #include "UnityCG.cginc"

    struct LightVertex {
        float4 position : POSITION;
    };

    struct LightInterpolators {
        float4 position : SV_POSITION;
    };

    LightInterpolators LightPassVertex(LightVertex v) {
        LightInterpolators o;
        o.position = float4(v.position.xy, 0.0, 1.0);
        return o;
    }

    float4 CountFragment(LightInterpolators i) : SV_Target {
        return float4(0.125, 0.0, 0.0, 0.0);
    }
    ENDCG

    SubShader
    {
        Pass
        {
            Name "LIGHT"
            ZWrite Off
            ZTest GEqual
            Cull Off
            Blend One One
            ColorMask RGB
            CGPROGRAM
            #pragma vertex LightPassVertex
            #pragma fragment CountFragment
            #pragma multi_compile DIRECTIONAL POINT SPOT
            ENDCG
        }

        Pass
        {
            Name "LIGHT_MASK"
            ZWrite Off
            ZTest LEqual
            Cull Off
            ColorMask 0
            Stencil
            {
                Ref 1
                Comp Always
                Pass Replace
            }
            CGPROGRAM
            #pragma vertex LightPassVertex
            #pragma fragment CountFragment
            ENDCG
        }

        Pass
        {
            Name "LIGHT_BOUNDED"
            ZWrite Off
            ZTest GEqual
            Cull Off
            Blend One One
            ColorMask RGB
            Stencil
            {
                Ref 1
                Comp Equal
                Pass Zero
                ZFail Zero
            }
            CGPROGRAM
            #pragma vertex LightPassVertex
            #pragma fragment CountFragment
            #pragma multi_compile DIRECTIONAL POINT SPOT
            ENDCG
        }
    }
}
