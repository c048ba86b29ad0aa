// Every render-state command, literal and property-referenced, at SubShader and Pass level.
Shader "Golden/RenderState"
{
    Properties
    {
        _Cull ("Cull", Float) = 2
        _ZTest ("ZTest", Float) = 4
        _ZWrite ("ZWrite", Float) = 1
        _Src ("Src", Float) = 1
        _Dst ("Dst", Float) = 0
        _Op ("Op", Float) = 0
        _Mask ("Mask", Float) = 15
        _Ref ("Stencil ref", Int) = 1
        _Comp ("Stencil comp", Int) = 8
    }
    SubShader
    {
        Cull Back
        ZTest LEqual
        ZWrite On
        ZClip True
        Pass
        {
            Cull [_Cull]
            ZTest [_ZTest]
            ZWrite [_ZWrite]
            AlphaToMask On
            Conservative False
            Offset -1, -1
            Blend [_Src] [_Dst], One OneMinusSrcAlpha
            Blend 1 Off
            Blend 2 DstColor Zero
            BlendOp Add, Max
            BlendOp 1 [_Op]
            ColorMask RGB
            ColorMask 0 1
            ColorMask [_Mask] 2
            Stencil
            {
                Ref [_Ref]
                ReadMask 255
                WriteMask 15
                Comp [_Comp]
                Pass Replace
                Fail Keep
                ZFail IncrWrap
                CompBack NotEqual
                PassBack DecrSat
            }
        }
    }
}
