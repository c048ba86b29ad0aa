// The hand-written equivalent of lambert.shader's generated forward passes: Lambert's law for the
// pixel light with its attenuation and shadow, plus the SH ambient and vertex lights of the base pass.
Shader "Test/HandLambert" {
    Properties {
        _Color ("Color", Color) = (1,1,1,1)
        _MainTex ("Albedo", 2D) = "white" {}
    }
    CGINCLUDE
    #include "UnityCG.cginc"
    #include "Lighting.cginc"
    #include "AutoLight.cginc"
    sampler2D _MainTex;
    float4 _MainTex_ST;
    fixed4 _Color;
    struct v2f {
        float4 pos : SV_POSITION;
        float2 uv : TEXCOORD0;
        float3 worldNormal : TEXCOORD1;
        float3 worldPos : TEXCOORD2;
        half3 sh : TEXCOORD3;
        UNITY_LIGHTING_COORDS(4, 5)
    };
    v2f vert(appdata_full v) {
        v2f o;
        UNITY_INITIALIZE_OUTPUT(v2f, o);
        o.pos = UnityObjectToClipPos(v.vertex);
        o.uv = TRANSFORM_TEX(v.texcoord.xy, _MainTex);
        o.worldNormal = UnityObjectToWorldNormal(v.normal);
        o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
        o.sh = 0;
    #if UNITY_SHOULD_SAMPLE_SH
    #ifdef VERTEXLIGHT_ON
        o.sh += Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
            unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb,
            unity_LightColor[3].rgb, unity_4LightAtten0, o.worldPos, o.worldNormal);
    #endif
        o.sh = ShadeSHPerVertex(o.worldNormal, o.sh);
    #endif
        UNITY_TRANSFER_LIGHTING(o, v.texcoord1.xy);
        return o;
    }
    fixed4 frag(v2f i) : SV_Target {
        fixed4 albedo = tex2D(_MainTex, i.uv) * _Color;
        float3 n = normalize(i.worldNormal);
    #ifndef USING_DIRECTIONAL_LIGHT
        fixed3 l = normalize(UnityWorldSpaceLightDir(i.worldPos));
    #else
        fixed3 l = _WorldSpaceLightPos0.xyz;
    #endif
        UNITY_LIGHT_ATTENUATION(atten, i, i.worldPos)
        fixed4 c;
        c.rgb = albedo.rgb * _LightColor0.rgb * max(0, dot(n, l)) * atten;
    #ifdef UNITY_PASS_FORWARDBASE
    #if UNITY_SHOULD_SAMPLE_SH
        c.rgb += albedo.rgb * ShadeSHPerPixel(n, i.sh, i.worldPos);
    #endif
    #endif
        c.a = 1;
        return c;
    }
    ENDCG
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdbase
            ENDCG
        }
        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            ZWrite Off Blend One One
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdadd
            ENDCG
        }
    }
}
