// Order-2 spherical-harmonic ambient light in double precision (see guards.h for the contract):
// projection of radiance onto the real SH basis, the irradiance of Ramamoorthi and Hanrahan
// (2001), and the packing of that irradiance into the seven unity_SH* float4 the shaders read.
#ifndef KILN_REFERENCE_SH_H_
#define KILN_REFERENCE_SH_H_

#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

namespace kiln::reference {

// Radiance coefficients L_lm per RGB channel, ordered (0,0), (1,-1), (1,0), (1,1), (2,-2),
// (2,-1), (2,0), (2,1), (2,2) (Ramamoorthi and Hanrahan 2001, eq. 3 basis).
struct SH9 {
    std::array<glm::dvec3, 9> L{};
};

// The nine real basis functions at unit direction d (R&H 2001, eq. 3).
std::array<double, 9> SHBasis(const glm::dvec3& d);

// Adds a distant light of the given radiance-times-solid-angle arriving from unit direction d
// (a delta in the environment): L_lm += color * Y_lm(d).
void AddDirectionalLight(SH9& sh, const glm::dvec3& d, const glm::dvec3& color);

// Adds a constant radiance over the whole sphere: L_00 += color * sqrt(4 pi).
void AddConstantRadiance(SH9& sh, const glm::dvec3& color);

// Unity's gradient ambient ("Trilight"): `sky` straight up, `equator` at the horizon, `ground`
// straight down, linear in the direction's y between them.
glm::dvec3 TrilightRadiance(const glm::dvec3& d,
                            const glm::dvec3& sky,
                            const glm::dvec3& equator,
                            const glm::dvec3& ground);

// Adds the projection of the trilight radiance, in closed form (L depends on y alone; a test
// checks it against numerical integration of TrilightRadiance x SHBasis).
void AddTrilight(SH9& sh,
                 const glm::dvec3& sky,
                 const glm::dvec3& equator,
                 const glm::dvec3& ground);

// The unit direction at the centre of texel (u, v) of a width x height equirectangular image: row 0
// straight up (+y), the centre column looking down -z, +x three quarters of the way across:
// theta = pi (v + 0.5) / height from +y, phi = 2 pi (u + 0.5) / width - pi,
// d = (sin theta sin phi, cos theta, -sin theta cos phi).
glm::dvec3 EquirectDirection(uint32_t u, uint32_t v, uint32_t width, uint32_t height);

// The solid angle of a texel of row v: (2 pi / width) (cos theta_top - cos theta_bottom), exact;
// the rows of an image sum to 4 pi.
double EquirectSolidAngle(uint32_t v, uint32_t width, uint32_t height);

// Adds the projection of an equirectangular radiance image (linear RGB floats, row-major from
// the top): each texel's radiance x Y_lm at its centre x its solid angle.
void AddEquirect(SH9& sh, uint32_t width, uint32_t height, const float* rgb);

// Irradiance E(n) from the order-2 approximation (R&H 2001, eq. 13), unit n.
glm::dvec3 Irradiance(const SH9& sh, const glm::dvec3& n);

// What ShadeSH9 returns: max(E(n) / pi, 0) (ringing can make E negative).
glm::dvec3 AmbientFromSH(const SH9& sh, const glm::dvec3& n);

// The seven float4 of the UnityProbes block: unity_SHAr, Ag, Ab, SHBr, Bg, Bb, SHC (layout in
// templates/KilnSH.cginc and docs/shader-library.md), E / pi with the constants folded in.
using PackedSH = std::array<std::array<float, 4>, 7>;
PackedSH PackSH9(const SH9& sh);

// Evaluates a packed probe the way the shader does (for checking the packing).
glm::dvec3 EvalPackedSH(const PackedSH& packed, const glm::dvec3& n);

}  // namespace kiln::reference

#endif  // KILN_REFERENCE_SH_H_
