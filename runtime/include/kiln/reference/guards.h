// The CPU reference of Kiln's lighting models, in double precision: the oracle for GPU image
// tests and numerical-stability checks. Written from the cited equations, independently of the
// HLSL in templates/; it applies the same documented guards (docs/shader-library.md, "Numerical
// guards") so both agree on the documented domain, and is finite for every finite input.
//
// guards.h: the guard helpers and constants every model uses.
#ifndef KILN_REFERENCE_GUARDS_H_
#define KILN_REFERENCE_GUARDS_H_

#include <glm/vec3.hpp>

namespace kiln::reference {

inline constexpr double kPi = 3.14159265358979323846;
// Largest finite binary16 value; HDR results are clamped to it (16-bit float targets).
inline constexpr double kHalfMax = 65504.0;
// Smallest normal binary16 value, 2^-14: a divisor bounded by it keeps a quotient of 1 within
// binary16 (as KILN_HALF_MIN; a subnormal bound could be flushed to 0).
inline constexpr double kHalfMin = 6.103515625e-5;
// Squared length below which a vector counts as zero (as KILN_MIN_LENGTH_SQ).
inline constexpr double kMinLengthSq = 1e-12;

// v / |v|, or 0 when |v|^2 <= kMinLengthSq (normalize(0) is NaN).
glm::dvec3 SafeNormalize(const glm::dvec3& v);

// x^y on x >= 0, y >= 0 with the limits 0^0 = 1 and 0^y = 0 for y > 0; negative x counts as 0,
// negative y as 0.
double SafePow(double x, double y);

// min(c, kHalfMax) per channel; NaN is never produced for finite input.
glm::dvec3 ClampToHalfRange(const glm::dvec3& c);

double Saturate(double x);

}  // namespace kiln::reference

#endif  // KILN_REFERENCE_GUARDS_H_
