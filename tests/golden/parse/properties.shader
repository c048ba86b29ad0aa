// Every property type, default form and attribute.
Shader "Golden/Properties"
{
    Properties
    {
        [Header(Surface inputs)]
        [HDR] _EmissionColor ("Emission", Color) = (0, 0, 0, 1)
        [Gamma] _GammaColor ("Gamma colour", Color) = (0.5, 0.5, 0.5)
        _Offset ("Offset", Vector) = (0, -1.5, 2e-1, 1)
        _Float ("Float", Float) = -0.25
        _Int ("Int", Int) = 3
        _Integer ("Integer", Integer) = 7
        [PowerSlider(3.0)] _Shininess ("Shininess", Range(0.03, 1)) = 0.078125
        [IntRange] _Steps ("Steps", Range(0, 255)) = 100
        [Toggle(_ALPHATEST_ON)] _AlphaTest ("Alpha test", Float) = 0
        [ToggleOff] _Specular ("Specular highlights", Float) = 1
        [KeywordEnum(None, Add, Multiply)] _Overlay ("Overlay mode", Float) = 0
        [Enum(One, 1, SrcAlpha, 5)] _SrcBlend ("Source blend", Float) = 1
        [Space(10)]
        [NoScaleOffset] [Normal] _BumpMap ("Normal map", 2D) = "bump" {}
        [HideInInspector] _Black ("Black", 2D) = "black" {}
        [PerRendererData] _Gray ("Gray", 2D) = "gray" {}
        _Red ("Red", 2D) = "red" {}
        _Volume ("Volume", 3D) = "" {}
        _Sky ("Sky", Cube) = "" {}
        _Layers ("Layers", 2DArray) = "" {}
        _Skies ("Skies", CubeArray) = "" {}
    }
    SubShader
    {
        Pass
        {
            Blend [_SrcBlend] OneMinusSrcAlpha
        }
    }
}
