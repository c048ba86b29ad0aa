// The engine-keyword stripping profile (issue 38): a ForwardBase pass written as lighting
// tutorials write it. Its interpolators have no `lightmapUV`, which Unity's AutoLight.cginc reads
// in SHADOWS_SHADOWMASK variants (UNITY_LIGHT_ATTENUATION -> UnityComputeForwardShadows(
// a.lightmapUV, ...)); the #if below reproduces that expansion without Unity's includes. Unity
// never builds those variants unless a scene uses the Shadowmask lighting mode, so the shader
// compiles under Kiln's default profile and fails with --strict-variants
// (tests/cli/profile_test.cpp).
Shader "Tutorial/ShadowmaskInvalid" {
    Properties {
        _Color ("Tint", Color) = (1, 1, 1, 1)
    }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdbase
            #pragma multi_compile_fog
            #include "UnityCG.cginc"
            #include "Lighting.cginc"

            float4 _Color;

            struct v2f {
                float4 position : SV_POSITION;
                float3 normal : NORMAL;
                UNITY_FOG_COORDS(1)
            };

            v2f vert(appdata_base v) {
                v2f o;
                o.position = UnityObjectToClipPos(v.vertex);
                o.normal = UnityObjectToWorldNormal(v.normal);
                UNITY_TRANSFER_FOG(o, o.position);
                return o;
            }

            float4 frag(v2f i) : SV_Target {
            #if defined(SHADOWS_SHADOWMASK)
                float attenuation = i.lightmapUV.x;
            #else
                float attenuation = 1;
            #endif
                float3 n = normalize(i.normal);
                float4 col = _Color * saturate(dot(n, _WorldSpaceLightPos0.xyz)) * attenuation *
                             _LightColor0;
                UNITY_APPLY_FOG(i.fogCoord, col);
                return col;
            }
            ENDCG
        }
    }
}
