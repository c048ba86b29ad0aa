// UnityDeprecated.cginc: lighting terms Unity 5's early Standard shader used, kept because
// hand-written shaders still call them (DotClamped most of all). Each is the published formula.
#ifndef UNITY_DEPRECATED_INCLUDED
#define UNITY_DEPRECATED_INCLUDED

#include "UnityCG.cginc"

// max(0, a . b): the clamped cosine of Lambert's law.
inline half DotClamped(half3 a, half3 b) {
    return saturate(dot(a, b));
}
inline half LambertTerm(half3 normal, half3 lightDir) {
    return DotClamped(normal, lightDir);
}
inline half BlinnTerm(half3 normal, half3 halfDir) {
    return DotClamped(normal, halfDir);
}

// Fresnel with a roughness-dependent fade of the grazing term (Lazarov 2013).
inline half3 LazarovFresnelTerm(half3 F0, half roughness, half cosA) {
    half t = Pow5(1.0 - saturate(cosA));
    t /= 4.0 - 3.0 * roughness;
    return F0 + (1.0 - F0) * t;
}
// Fresnel with a spherical-Gaussian fit of the fifth power (Lagarde 2012).
inline half3 SebLagardeFresnelTerm(half3 F0, half roughness, half cosA) {
    half t = exp2((-5.55473 * cosA - 6.98316) * cosA);
    return F0 + (max(F0, 1.0 - roughness) - F0) * t;
}

// Cook-Torrance geometric term over 4 n.l n.v (Cook and Torrance 1982).
inline half CookTorranceVisibilityTerm(half NdotL, half NdotV, half NdotH, half VdotH) {
    // guard: grazing angles make the denominators vanish
    VdotH += 1e-5f;
    half G = min(1.0, min(2.0 * NdotH * NdotV / VdotH, 2.0 * NdotH * NdotL / VdotH));
    return G / (NdotL * NdotV + 1e-4f);
}
// Kelemen and Szirmay-Kalos 2001: 1 / (4 (l.h)^2).
inline half KelemenVisibilityTerm(half LdotH) {
    return 1.0 / max(4.0 * LdotH * LdotH, 1e-5);
}
// Kelemen's term blended by roughness (Unity's approximation).
inline half ModifiedKelemenVisibilityTerm(half LdotH, half perceptualRoughness) {
    half c = 0.797884560802865;  // sqrt(2 / pi)
    half k = perceptualRoughness * perceptualRoughness * c;
    half gH = LdotH * (1 - k) + k;
    return 1.0 / max(gH * gH, 1e-5);
}
// Separable Smith-Schlick visibility for GGX with k = a / 2 (Karis 2013).
inline half SmithGGXVisibilityTerm(half NdotL, half NdotV, half perceptualRoughness) {
    half k = (perceptualRoughness * perceptualRoughness) / 2;
    half gL = NdotL * (1 - k) + k;
    half gV = NdotV * (1 - k) + k;
    return 1.0 / max(gL * gV, 1e-5);
}
inline half ImplicitVisibilityTerm() {
    return 1;
}
// Normalized Blinn-Phong distribution (n + 2) / (2 pi) (n.h)^n.
inline half RDFBlinnPhongNormalizedTerm(half NdotH, half n) {
    half normTerm = (n + 2.0) / (2.0 * KILN_PI);
    return normTerm * SafePow(NdotH, n);
}
// Roughness -> Blinn-Phong exponent: 2 / a^4 - 2 (Walter et al. 2007, section 5.2).
half RoughnessToSpecPower(half roughness) {
    half m = max(roughness * roughness, 1e-4);
    half n = (2.0 / (m * m)) - 2.0;
    return max(n, 1e-4);
}

inline half3 DecodeHDR_NoLinearSupportInSM2(half4 data, half4 decodeInstructions) {
    return DecodeHDR(data, decodeInstructions);
}

#endif  // UNITY_DEPRECATED_INCLUDED
