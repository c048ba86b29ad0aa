// Several independent errors in one file: all are reported, and the parser recovers after each.
Shader "Golden/Errors"
{
    Properties
    {
        _Color ("Color", Colour) = (1, 1, 1, 1)
        _Gloss ("Gloss", Range(0, 1)) = 0.5
        _Gloss ("Gloss again", Float) = 1
    }
    SubShader
    {
        Cull Sideways
        Blend [_Missing] One    // not reported: _Color failed to parse, so this may be it
        Pas { Cull Back }
        Pass
        {
            Name "OK"
            LOD 100
            Stencil { Ref 300 }
            ColorMask RGBX
            Lighting Off
            CGPROGRAM
            #pragma surface surf Lambert
            ENDCG
        }
        ENDCG
    }
}
