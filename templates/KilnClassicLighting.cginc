// KilnClassicLighting.cginc: the empirical lighting models of the lecture, with the light-colour
// convention used throughout the library: a white Lambert surface facing a light of colour C
// shows exactly C (C is pi times the incident radiance; see docs/shader-library.md).
#ifndef KILN_CLASSIC_LIGHTING_INCLUDED
#define KILN_CLASSIC_LIGHTING_INCLUDED

#include "KilnCommon.cginc"

// Lambert's cosine law (Lambert 1760; lecture "Diffuse reflection"): c_r * c_l * max(0, n . l).
float3 Lambert_Diffuse(float3 albedo, float3 lightColor, float3 n, float3 l) {
    return albedo * lightColor * saturate(dot(n, l));
}

// Constant ambient term (lecture "Ambient light"): c_r * c_a.
float3 Ambient_Constant(float3 albedo, float3 ambientColor) {
    return albedo * ambientColor;
}

// Blinn-Phong half vector h = (l + v) / |l + v| (Blinn 1977, eq. 2).
float3 BlinnPhong_HalfVector(float3 l, float3 v) {
    // guard: l = -v gives l + v = 0; SafeNormalize returns 0, so n . h = 0 and the highlight is 0
    return SafeNormalize(l + v);
}

// Blinn-Phong specular lobe (Blinn 1977): c_s * c_l * max(0, n . h)^e, e = smoothness * 100 as in
// the lecture.
float3 BlinnPhong_Specular(float3 specColor, float3 lightColor, float3 n, float3 h,
                           float exponent) {
    // guard: SafePow gives pow(0, 0) = 1 and clamps the negative base max(0, n . h) cannot have
    return specColor * lightColor * SafePow(saturate(dot(n, h)), exponent);
}

// The lecture's exponent: smoothness in [0, 1] mapped to a Phong exponent in [0, 100].
float BlinnPhong_Exponent(float smoothness) {
    return saturate(smoothness) * 100.0;
}

// Energy conservation (lecture "Energy conservation"): the diffuse albedo is scaled by
// 1 - max(specular), so diffuse + specular reflectance never exceeds 1 per channel.
float SpecularStrength_Max(float3 specColor) {
    return max(max(specColor.r, specColor.g), specColor.b);
}
float3 EnergyConservation_Diffuse(float3 albedo, float3 specColor,
                                  out float oneMinusReflectivity) {
    // guard: a specular colour above 1 would make the diffuse weight negative
    oneMinusReflectivity = saturate(1.0 - SpecularStrength_Max(specColor));
    return albedo * oneMinusReflectivity;
}

#endif  // KILN_CLASSIC_LIGHTING_INCLUDED
