// KilnAttenuation.cginc: punctual light falloff with distance and spot cone.
//
// Units: world units are metres. A light's range r is where its contribution reaches 0; r <= 0
// means unlimited (glTF KHR_lights_punctual: an absent range is infinite). The runtime passes
// 1 / r^2 (0 for unlimited) so the window costs no division per pixel.
#ifndef KILN_ATTENUATION_INCLUDED
#define KILN_ATTENUATION_INCLUDED

#include "KilnCommon.cginc"

// Lights are treated as spheres of 1 cm radius for the inverse-square law (Lagarde and de
// Rousiers 2014, "Moving Frostbite to PBR", section 4.2.2, eq. 24 context).
#define KILN_MIN_LIGHT_DISTANCE 0.01

// Inverse-square law 1 / d^2 (Frostbite eq. 24 with the 1 cm bound).
float Attenuation_InverseSquare(float distanceSq) {
    // guard: 1 / 0 at the light's position; bounded by the 1 cm light radius
    return 1.0 / max(distanceSq, KILN_MIN_LIGHT_DISTANCE * KILN_MIN_LIGHT_DISTANCE);
}

// Smooth window to the range: saturate(1 - (d / r)^4)^2 (Frostbite eq. 26; Karis 2013, eq. 9).
float Attenuation_RangeWindow(float distanceSq, float invRangeSq) {
    // guard: invRangeSq = 0 (unlimited range) gives 1; a negative value is taken by magnitude
    // so a mis-filled range never produces a negative or non-finite window
    float ratio2 = distanceSq * abs(invRangeSq);
    float w = saturate(1.0 - ratio2 * ratio2);
    return w * w;
}

// Distance attenuation of a point or spot light.
float Attenuation_Distance(float distanceSq, float invRangeSq) {
    return Attenuation_InverseSquare(distanceSq) * Attenuation_RangeWindow(distanceSq, invRangeSq);
}

// Spot cone (glTF KHR_lights_punctual, "Inner and Outer Cone Angles" reference code): smooth
// from 0 at the outer cone to 1 at the inner cone, squared.
// l: unit vector from the surface to the light; spotDir: unit direction the spot points in.
float Attenuation_SpotCone(float3 l, float3 spotDir, float cosOuter, float cosInner) {
    float cd = dot(spotDir, -l);
    // guard: inner >= outer angle (cosInner <= cosOuter) would divide by zero or a negative
    // number; the 1e-3 floor (glTF's value) makes the edge hard instead
    float scale = 1.0 / max(cosInner - cosOuter, 1e-3);
    float t = saturate((cd - cosOuter) * scale);
    return t * t;
}

#endif  // KILN_ATTENUATION_INCLUDED
