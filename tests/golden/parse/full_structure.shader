// Every structural construct of a ShaderLab file.
Shader "Golden/FullStructure"
{
    Properties
    {
        [MainColor] _Color ("Color", Color) = (1, 0.5, 0.25, 1)
        [MainTexture] _MainTex ("Albedo", 2D) = "white" {}
        _Cutoff ("Alpha cutoff", Range(0, 1)) = 0.5
        [Enum(UnityEngine.Rendering.CullMode)] _Cull ("Cull", Float) = 2
    }

    CGINCLUDE
    #include "UnityCG.cginc"
    float4 _Color;
    ENDCG

    Category
    {
        Tags { "Queue" = "Geometry" }
        Cull [_Cull]

        SubShader
        {
            Tags { "RenderType" = "Opaque" "IgnoreProjector" = "True" }
            LOD 200
            ZWrite On

            HLSLINCLUDE
            // subshader-level shared code
            ENDHLSL

            Pass
            {
                Name "FORWARD"
                Tags { "LightMode" = "ForwardBase" }
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #pragma multi_compile_fwdbase
                #pragma shader_feature _ _ALPHATEST_ON
                float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
                float4 frag() : SV_Target { return _Color; }
                ENDCG
            }

            UsePass "Legacy Shaders/VertexLit/SHADOWCASTER"
            GrabPass { "_BackgroundTexture" }
        }
    }

    SubShader
    {
        Pass
        {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
            float4 frag() : SV_Target { return 1; }
            ENDHLSL
        }
    }

    Fallback "Diffuse"
    CustomEditor "Kiln.ShaderGUI"
    Dependency "BaseMapShader" = "Golden/Base"
}
