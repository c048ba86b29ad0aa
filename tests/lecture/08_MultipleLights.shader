// Lecture 06 (Light), MultipleLights: assembled from the slides as a student would write it.
Shader "Lecture/MultipleLights"
{
    Properties
    {
        _Color("Color", Color) = (1, 1, 1, 1)
        _Smoothness("Smoothness", Range(0, 1)) = 0.5
        _SpecularColor("Specular", Color) = (0.5, 0.5, 0.5)
        _MainTex("Albedo", 2D) = "white" {}
    }
    SubShader{
      Pass{
        Tags{"LightMode" = "ForwardBase"}
        CGPROGRAM
        #pragma target 3.0
        #pragma vertex MyVertexProgram
        #pragma fragment MyFragmentProgram
        #include "LightShader.cginc"
        ENDCG
      }
      Pass{
        Tags{"LightMode" = "ForwardAdd"}
        Blend One One
        ZWrite Off
        CGPROGRAM
        #pragma target 3.0
        #pragma vertex MyVertexProgram
        #pragma fragment MyFragmentProgram
        #include "LightShader.cginc"
        ENDCG
      }
    }
}
