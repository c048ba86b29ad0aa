#include "kiln/reference/brdf.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "kiln/reference/guards.h"

namespace kiln::reference {

double RoughnessFromSmoothness(double smoothness) {
    const double perceptual = std::clamp(1.0 - Saturate(smoothness), kMinPerceptualRoughness, 1.0);
    return perceptual * perceptual;
}

double D_GGX(double cos_theta_h, double alpha) {
    if (cos_theta_h <= 0.0)
        return 0.0;  // chi+: microfacets facing away do not exist
    const double c2 = std::min(cos_theta_h * cos_theta_h, 1.0);
    const double a2 = alpha * alpha;
    const double d = a2 * c2 + (1.0 - c2);  // cos^2 (alpha^2 + tan^2)
    return a2 / (kPi * d * d);
}

double Lambda_GGX(double cos_theta, double alpha) {
    const double c2 = cos_theta * cos_theta;
    const double tan2 = (1.0 - c2) / c2;
    return (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2)) / 2.0;
}

double V_SmithGGXCorrelated(double no_v, double no_l, double alpha) {
    no_v = std::clamp(std::abs(no_v), kMinNoV, 1.0);
    no_l = std::clamp(no_l, 1e-12, 1.0);
    const double g2 = 1.0 / (1.0 + Lambda_GGX(no_v, alpha) + Lambda_GGX(no_l, alpha));
    return g2 / (4.0 * no_l * no_v);
}

glm::dvec3 F_Schlick(const glm::dvec3& f0, double cos_theta_d) {
    const double m = 1.0 - Saturate(cos_theta_d);
    return f0 + (glm::dvec3(1.0) - f0) * (m * m * m * m * m);
}

glm::dvec3 StandardBrdf(const StandardInputs& in) {
    const glm::dvec3 n = SafeNormalize(in.normal);
    const glm::dvec3 v = SafeNormalize(in.view_dir);
    const glm::dvec3 l = SafeNormalize(in.light_dir);
    const glm::dvec3 h = SafeNormalize(l + v);
    const double alpha = RoughnessFromSmoothness(in.smoothness);
    const double no_v = std::max(std::abs(glm::dot(n, v)), kMinNoV);
    const double no_l = Saturate(glm::dot(n, l));

    // Rendering equation for a punctual light, times pi for the light-colour convention:
    // (diffuse / pi + D V F) * (pi C) * NoL.
    const glm::dvec3 diffuse = in.diffuse_color * (in.indirect_diffuse + in.light_color * no_l);
    glm::dvec3 specular(0.0);
    if (no_l > 0.0) {
        const double d = D_GGX(Saturate(glm::dot(n, h)), alpha);
        const double vis = V_SmithGGXCorrelated(no_v, no_l, alpha);
        specular =
            kPi * d * vis * no_l * F_Schlick(in.specular_color, glm::dot(l, h)) * in.light_color;
    }
    // Unity's indirect specular: 1 / (alpha^2 + 1) and Fresnel towards smoothness + reflectivity.
    const double grazing = Saturate(in.smoothness + (1.0 - in.one_minus_reflectivity));
    const double m = 1.0 - Saturate(no_v);
    const glm::dvec3 fresnel =
        in.specular_color + (glm::dvec3(grazing) - in.specular_color) * (m * m * m * m * m);
    const glm::dvec3 indirect = in.indirect_specular * fresnel / (alpha * alpha + 1.0);
    return ClampToHalfRange(diffuse + specular + indirect);
}

glm::dvec3 SpecularColorFromMetallic(const glm::dvec3& base_color, double metallic) {
    const double m = Saturate(metallic);
    return glm::dvec3(kDielectricF0) * (1.0 - m) + base_color * m;
}

double OneMinusReflectivityFromMetallic(double metallic) {
    return (1.0 - kDielectricF0) * (1.0 - Saturate(metallic));
}

}  // namespace kiln::reference
