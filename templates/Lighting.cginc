// Lighting.cginc: the classic lighting models over a SurfaceOutput, with Unity's names.
#ifndef LIGHTING_INCLUDED
#define LIGHTING_INCLUDED

#include "UnityLightingCommon.cginc"
#include "UnityCG.cginc"
#include "UnityGBuffer.cginc"
#include "KilnClassicLighting.cginc"

struct SurfaceOutput {
    float3 Albedo;    // diffuse reflectance, linear
    float3 Normal;    // world-space unit normal
    float3 Emission;  // emitted colour, linear
    float Specular;   // Blinn-Phong exponent / 128, as in Unity
    float Gloss;      // specular intensity
    float Alpha;
};

// Lambert (lecture "Diffuse reflection") for one light.
float4 UnityLambertLight(SurfaceOutput s, UnityLight light) {
    return float4(Lambert_Diffuse(s.Albedo, light.color, s.Normal, light.dir), s.Alpha);
}

// Lambert plus the indirect diffuse light.
float4 LightingLambert(SurfaceOutput s, UnityGI gi) {
    float4 c = UnityLambertLight(s, gi.light);
    c.rgb += s.Albedo * gi.indirect.diffuse;
    return c;
}

// Blinn-Phong (lecture "Specular reflection") for one light. Unity reads the specular colour
// from a global _SpecColor; Kiln takes it as an argument so no hidden material property exists.
float4 UnityBlinnPhongLight(SurfaceOutput s, float3 viewDir, UnityLight light, float3 specColor) {
    float3 h = BlinnPhong_HalfVector(SafeNormalize(light.dir), SafeNormalize(viewDir));
    float3 diffuse = Lambert_Diffuse(s.Albedo, light.color, s.Normal, light.dir);
    float3 specular =
        BlinnPhong_Specular(specColor * s.Gloss, light.color, s.Normal, h, s.Specular * 128.0);
    return float4(diffuse + specular, s.Alpha);
}

#endif  // LIGHTING_INCLUDED
