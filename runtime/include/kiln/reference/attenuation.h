// Punctual light falloff in double precision (see guards.h for the contract). Distances are in
// metres; a range <= 0 means unlimited (glTF KHR_lights_punctual: no range = infinite).
#ifndef KILN_REFERENCE_ATTENUATION_H_
#define KILN_REFERENCE_ATTENUATION_H_

namespace kiln::reference {

// Lights are spheres of 1 cm radius for the inverse-square law (Lagarde and de Rousiers 2014).
inline constexpr double kMinLightDistance = 0.01;
// Smallest cos(inner) - cos(outer) of a spot cone (glTF KHR_lights_punctual reference code).
inline constexpr double kMinConeCosDelta = 1e-3;

// Inverse-square law 1 / d^2 with d >= kMinLightDistance.
double InverseSquare(double distance);

// Smooth window to the range, saturate(1 - (d / r)^4)^2 (Lagarde and de Rousiers 2014, eq. 26);
// 1 for range <= 0.
double RangeWindow(double distance, double range);

// InverseSquare * RangeWindow: the distance attenuation of point and spot lights.
double DistanceAttenuation(double distance, double range);

// What the runtime stores for the shader (kiln_LightParams0.x, unity_4LightAtten0): 1 / r^2, or
// 0 for an unlimited range.
double InverseRangeSquared(double range);

// Spot cone: 0 outside the outer cone, 1 inside the inner one, a squared linear ramp in cos
// between (glTF KHR_lights_punctual). Angles are half-angles in radians from the spot's axis;
// cos_to_axis is cos of the angle between the spot's direction and the light-to-surface vector.
// inner >= outer gives a hard edge at the outer cone.
double SpotCone(double cos_to_axis, double outer_angle, double inner_angle);

}  // namespace kiln::reference

#endif  // KILN_REFERENCE_ATTENUATION_H_
