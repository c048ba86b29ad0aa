// A Standard surface shader as Unity's "new surface shader" template writes it, with a vertex:
// function and addshadow, so that its generated ShadowCaster casts the displaced mesh.
Shader "Test/SurfaceStandard" {
    Properties {
        _Color ("Color", Color) = (1,1,1,1)
        _MainTex ("Albedo (RGB)", 2D) = "white" {}
        _Glossiness ("Smoothness", Range(0,1)) = 0.5
        _Metallic ("Metallic", Range(0,1)) = 0.0
        _Inflate ("Inflate", Range(0,0.2)) = 0.0
    }
    SubShader {
        Tags { "RenderType"="Opaque" }
        LOD 200
        CGPROGRAM
        #pragma surface surf Standard fullforwardshadows addshadow vertex:vert
        #pragma target 3.0
        sampler2D _MainTex;
        struct Input {
            float2 uv_MainTex;
            float3 viewDir;
        };
        half _Glossiness;
        half _Metallic;
        half _Inflate;
        fixed4 _Color;
        void vert(inout appdata_full v) {
            v.vertex.xyz += v.normal * _Inflate;
        }
        void surf(Input IN, inout SurfaceOutputStandard o) {
            fixed4 c = tex2D(_MainTex, IN.uv_MainTex) * _Color;
            o.Albedo = c.rgb;
            o.Metallic = _Metallic;
            o.Smoothness = _Glossiness;
            o.Alpha = c.a;
        }
        ENDCG
    }
    FallBack "Diffuse"
}
