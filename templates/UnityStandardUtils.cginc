// UnityStandardUtils.cginc: diffuse/specular parameterizations with Unity's names.
#ifndef UNITY_STANDARD_UTILS_INCLUDED
#define UNITY_STANDARD_UTILS_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardBRDF.cginc"
#include "KilnClassicLighting.cginc"

// Linear-space dielectric specular colour (rgb) and 1 - its reflectivity (a).
#define unity_ColorSpaceDielectricSpec \
    float4(KILN_DIELECTRIC_F0, KILN_DIELECTRIC_F0, KILN_DIELECTRIC_F0, 1.0 - KILN_DIELECTRIC_F0)

// Strongest channel of the specular colour: the share of light the specular layer reflects.
float SpecularStrength(float3 specular) {
    return SpecularStrength_Max(specular);
}

// Scales the albedo so diffuse + specular reflectance stays <= 1 (lecture "Energy
// conservation"); oneMinusReflectivity receives the diffuse weight.
float3 EnergyConservationBetweenDiffuseAndSpecular(float3 albedo, float3 specColor,
                                                   out float oneMinusReflectivity) {
    return EnergyConservation_Diffuse(albedo, specColor, oneMinusReflectivity);
}

float OneMinusReflectivityFromMetallic(float metallic) {
    return OneMinusReflectivity_Metallic(metallic);
}

// Metallic workflow: base colour and metallic -> diffuse colour (returned), specular colour and
// the diffuse weight.
float3 DiffuseAndSpecularFromMetallic(float3 albedo, float metallic, out float3 specColor,
                                      out float oneMinusReflectivity) {
    specColor = SpecularColor_Metallic(albedo, metallic);
    oneMinusReflectivity = OneMinusReflectivity_Metallic(metallic);
    return albedo * oneMinusReflectivity;
}

#endif  // UNITY_STANDARD_UTILS_INCLUDED
