// The lecture's empirical models in double precision (see guards.h for the contract).
// Light colour convention: a white Lambert surface facing a light of colour C shows C.
#ifndef KILN_REFERENCE_CLASSIC_LIGHTING_H_
#define KILN_REFERENCE_CLASSIC_LIGHTING_H_

#include <glm/vec3.hpp>

namespace kiln::reference {

// Lambert's cosine law: albedo * C * max(0, cos(theta_l)), theta_l the angle between n and l.
glm::dvec3 LambertDiffuse(const glm::dvec3& albedo,
                          const glm::dvec3& light_color,
                          const glm::dvec3& n,
                          const glm::dvec3& l);

// Constant ambient: albedo * ambient.
glm::dvec3 AmbientConstant(const glm::dvec3& albedo, const glm::dvec3& ambient);

// Blinn (1977): the half-way vector between the unit light and view directions, 0 when they are
// opposite.
glm::dvec3 BlinnPhongHalfVector(const glm::dvec3& l, const glm::dvec3& v);

// Blinn (1977): spec * C * cos(theta_h)^e, cos clamped to [0, 1], 0^0 = 1.
glm::dvec3 BlinnPhongSpecular(const glm::dvec3& spec,
                              const glm::dvec3& light_color,
                              const glm::dvec3& n,
                              const glm::dvec3& h,
                              double exponent);

// The lecture's exponent 100 * smoothness, smoothness clamped to [0, 1].
double BlinnPhongExponent(double smoothness);

// Energy conservation: diffuse weight 1 - max(spec) in [0, 1]; returns albedo * weight.
glm::dvec3 EnergyConservation(const glm::dvec3& albedo,
                              const glm::dvec3& spec,
                              double* one_minus_reflectivity);

}  // namespace kiln::reference

#endif  // KILN_REFERENCE_CLASSIC_LIGHTING_H_
