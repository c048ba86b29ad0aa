// The engine-keyword stripping profile with Unity's own includes (issue 38): the lighting-tutorial
// shape that fails in Unity's SHADOWS_SHADOWMASK variants, where AutoLight.cginc's
// UNITY_LIGHT_ATTENUATION reads `_ShadowCoord`, which SHADOW_COORDS declares only in SHADOWS_SCREEN
// variants. Unity builds those variants only for a scene in the Shadowmask mode; so does Kiln
// (tests/cli/profile_test.cpp compiles it against ../shared's 2022.3 CGIncludes).
Shader "Tutorial/UnityAtten" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdbase
            #include "UnityCG.cginc"
            #include "Lighting.cginc"
            #include "AutoLight.cginc"
            struct v2f {
                float4 pos : SV_POSITION;
                float3 worldPos : TEXCOORD0;
                SHADOW_COORDS(1)
            };
            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
                TRANSFER_SHADOW(o)
                return o;
            }
            float4 frag(v2f i) : SV_Target {
                UNITY_LIGHT_ATTENUATION(attenuation, i, i.worldPos)
                return attenuation * _LightColor0;
            }
            ENDCG
        }
    }
}
