#include "kiln/reference/classic_lighting.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "kiln/reference/guards.h"

namespace kiln::reference {

glm::dvec3 LambertDiffuse(const glm::dvec3& albedo,
                          const glm::dvec3& light_color,
                          const glm::dvec3& n,
                          const glm::dvec3& l) {
    // cos(theta_l) from the angle between the (unit) vectors; back-facing light contributes 0.
    const double cos_theta = glm::dot(n, l);
    return albedo * light_color * Saturate(cos_theta);
}

glm::dvec3 AmbientConstant(const glm::dvec3& albedo, const glm::dvec3& ambient) {
    return albedo * ambient;
}

glm::dvec3 BlinnPhongHalfVector(const glm::dvec3& l, const glm::dvec3& v) {
    return SafeNormalize(l + v);
}

glm::dvec3 BlinnPhongSpecular(const glm::dvec3& spec,
                              const glm::dvec3& light_color,
                              const glm::dvec3& n,
                              const glm::dvec3& h,
                              double exponent) {
    return spec * light_color * SafePow(Saturate(glm::dot(n, h)), exponent);
}

double BlinnPhongExponent(double smoothness) {
    return 100.0 * Saturate(smoothness);
}

glm::dvec3 EnergyConservation(const glm::dvec3& albedo,
                              const glm::dvec3& spec,
                              double* one_minus_reflectivity) {
    const double strongest = std::max({spec.x, spec.y, spec.z});
    const double weight = Saturate(1.0 - strongest);
    if (one_minus_reflectivity)
        *one_minus_reflectivity = weight;
    return albedo * weight;
}

}  // namespace kiln::reference
