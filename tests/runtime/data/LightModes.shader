// LightModes: what a forward base pass receives from the lights that are not per-pixel, and
// nothing else: the spherical harmonics (ambient plus SH lights, ShadeSH9) and, with
// VERTEXLIGHT_ON, the four vertex lights evaluated at the vertices (Shade4PointLights) and
// interpolated. The light-mode tests compare it with the CPU reference evaluated the same way.
Shader "KilnTest/LightModes"
{
    SubShader
    {
        Pass
        {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex LightModesVertex
            #pragma fragment LightModesFragment
            #pragma multi_compile _ VERTEXLIGHT_ON
            #include "UnityCG.cginc"

            struct LightModesInterpolators {
                float4 pos : SV_POSITION;
                float3 normal : TEXCOORD0;
                float3 vertexLight : TEXCOORD1;
            };

            LightModesInterpolators LightModesVertex(appdata_base v) {
                LightModesInterpolators o;
                o.pos = UnityObjectToClipPos(v.vertex.xyz);
                o.normal = UnityObjectToWorldNormal(v.normal);
                o.vertexLight = 0;
            #if defined(VERTEXLIGHT_ON)
                float3 worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
                o.vertexLight = Shade4PointLights(
                    unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
                    unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb,
                    unity_LightColor[3].rgb, unity_4LightAtten0, worldPos, o.normal);
            #endif
                return o;
            }

            float4 LightModesFragment(LightModesInterpolators i) : SV_TARGET {
                float3 n = normalize(i.normal);
                return float4(ShadeSH9(float4(n, 1.0)) + i.vertexLight, 1.0);
            }
            ENDCG
        }
    }
}
