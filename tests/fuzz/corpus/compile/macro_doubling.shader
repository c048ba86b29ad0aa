Shader "Fuzz/macro_doubling" {
    Properties { _Color ("Color", Color) = (1,1,1,1) _MainTex ("Tex", 2D) = "white" {} }
    SubShader {
        Tags { "RenderType"="Opaque" }
        Pass {
            Tags { "LightMode"="ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag

            #include "UnityCG.cginc"
            float4 _Color;
            sampler2D _MainTex;
            struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
            v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex);
                                       o.uv = v.texcoord.xy; return o; }
            float4 frag(v2f i) : SV_Target {
#define M1(i) ((i)+(i))
#define M2(i) (M1(i)+M1(i))
#define M3(i) (M2(i)+M2(i))
#define M4(i) (M3(i)+M3(i))
#define M5(i) (M4(i)+M4(i))
#define M6(i) (M5(i)+M5(i))
#define M7(i) (M6(i)+M6(i))
#define M8(i) (M7(i)+M7(i))
#define M9(i) (M8(i)+M8(i))
#define M10(i) (M9(i)+M9(i))
#define M11(i) (M10(i)+M10(i))
#define M12(i) (M11(i)+M11(i))
#define M13(i) (M12(i)+M12(i))
#define M14(i) (M13(i)+M13(i))
#define M15(i) (M14(i)+M14(i))
#define M16(i) (M15(i)+M15(i))
#define M17(i) (M16(i)+M16(i))
#define M18(i) (M17(i)+M17(i))
#define M19(i) (M18(i)+M18(i))
#define M20(i) (M19(i)+M19(i))
#define M21(i) (M20(i)+M20(i))
#define M22(i) (M21(i)+M21(i))
#define M23(i) (M22(i)+M22(i))
return M23(1);
            }
            ENDCG
        }
    }
}
