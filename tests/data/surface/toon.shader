// A custom lighting model (Unity manual, "Surface Shader lighting models"): a two-band toon ramp
// that gives pure red where the main light's N.L is above one half and pure blue elsewhere, with
// no ambient, no additive lights and no fog, so every pixel it draws is exactly one of the two.
Shader "Test/SurfaceToon" {
    Properties {
        _Color ("Color", Color) = (1,1,1,1)
    }
    SubShader {
        Tags { "RenderType"="Opaque" }
        CGPROGRAM
        #pragma surface surf ToonRamp noforwardadd noambient nofog nolightmap nometa
        fixed4 _Color;
        struct Input {
            float3 worldPos;
        };
        half4 LightingToonRamp(SurfaceOutput s, half3 viewDir, UnityGI gi) {
            half nl = dot(s.Normal, gi.light.dir);
            return half4(nl > 0.5 ? half3(1, 0, 0) : half3(0, 0, 1), 1);
        }
        void LightingToonRamp_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi) {
            gi.light = data.light;
        }
        void surf(Input IN, inout SurfaceOutput o) {
            o.Albedo = _Color.rgb;
        }
        ENDCG
    }
}
