Shader "Test/MultiLight" {
    Properties {
        _Tint ("Tint", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo", 2D) = "white" {}
    }
    SubShader {
        Pass {
            Name "FORWARD_DELTA"
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile DIRECTIONAL POINT SPOT
            #include "light.cginc"
            #include "light.cginc"
            float4 _Tint;
            sampler2D _MainTex;
            float4 _MainTex_ST;
            float4x4 unity_ObjectToWorld;
            float4x4 unity_MatrixVP;
            struct appdata { float4 vertex : POSITION; float3 normal : NORMAL; float2 uv : TEXCOORD0; };
            struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; float3 normal : TEXCOORD1; float3 worldPos : TEXCOORD2; };
            v2f vert(appdata v) {
                v2f o;
                float4 wp = mul(unity_ObjectToWorld, v.vertex);
                o.pos = mul(unity_MatrixVP, wp);
                o.uv = v.uv * _MainTex_ST.xy + _MainTex_ST.zw;
                o.normal = mul((float3x3)unity_ObjectToWorld, v.normal);
                o.worldPos = wp.xyz;
                return o;
            }
            float4 frag(v2f i) : SV_Target {
                float3 l = LightDir(i.worldPos);
                float ndl = saturate(dot(normalize(i.normal), l));
                float3 albedo = tex2D(_MainTex, i.uv).rgb * _Tint.rgb;
                return float4(albedo * _LightColor0.rgb * ndl, 1);
            }
            ENDCG
        }
    }
}
