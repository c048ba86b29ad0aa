Shader "Fuzz/keywords" {
    Properties { _Color ("Color", Color) = (1,1,1,1) _MainTex ("Tex", 2D) = "white" {} }
    SubShader {
        Tags { "RenderType"="Opaque" }
        Pass {
            Tags { "LightMode"="ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ RED BLUE
            #pragma shader_feature _ _GLOW
            #include "UnityCG.cginc"
            float4 _Color;
            sampler2D _MainTex;
            struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
            v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex);
                                       o.uv = v.texcoord.xy; return o; }
            float4 frag(v2f i) : SV_Target {
float4 c = _Color;
#ifdef RED
c.r = 1;
#endif
#if defined(BLUE)
c.b = 1;
#endif
#ifdef _GLOW
c *= 2;
#endif
return c;
            }
            ENDCG
        }
    }
}
