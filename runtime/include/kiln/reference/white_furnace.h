// The white-furnace test (see guards.h for the library's contract): the directional albedo
// rho(v) = integral over the hemisphere of f(l, v) (n . l) dl of a BRDF under a uniform white
// environment, by deterministic quadrature. An energy-conserving BRDF has rho <= 1 for every v.
#ifndef KILN_REFERENCE_WHITE_FURNACE_H_
#define KILN_REFERENCE_WHITE_FURNACE_H_

#include <cstdint>

namespace kiln::reference {

// Lambert, f = albedo / pi with albedo 1: rho = 1 (for every view), by the midpoint rule over
// `samples`^2 cells uniform in (cos theta, phi).
double LambertAlbedo(uint32_t samples = 256);

// GGX with height-correlated Smith visibility (brdf.h) and F = 1, importance-sampled by the
// distribution of visible normals (Heitz 2018) over a Hammersley set of `samples` points: each
// sample is 4 V (n . l)(n . v) / G1(v), at most 1 when V is consistent with G1.
// alpha = perceptual roughness^2; n . v is clamped to kMinNoV as the BRDF clamps it.
double GgxSmithAlbedo(double no_v, double alpha, uint32_t samples = 16384);

}  // namespace kiln::reference

#endif  // KILN_REFERENCE_WHITE_FURNACE_H_
