// The physically based BRDF in double precision (see guards.h for the contract): GGX normal
// distribution, Smith height-correlated masking-shadowing, Schlick Fresnel, Lambert diffuse,
// in the light-colour convention of classic_lighting.h (the specular term carries a factor pi).
#ifndef KILN_REFERENCE_BRDF_H_
#define KILN_REFERENCE_BRDF_H_

#include <glm/vec3.hpp>

namespace kiln::reference {

// Smallest perceptual roughness (GGX at alpha = 0 is a delta), as KILN_MIN_PERCEPTUAL_ROUGHNESS.
inline constexpr double kMinPerceptualRoughness = 0.045;
// Smallest |n . v| used by the shading (interpolated normals can face away from the viewer).
inline constexpr double kMinNoV = 1e-5;
// Dielectric reflectance at normal incidence, ((1.5 - 1) / (1.5 + 1))^2.
inline constexpr double kDielectricF0 = 0.04;

// alpha = perceptual^2 with perceptual = 1 - smoothness (Burley 2012, section 5.4), perceptual
// roughness clamped to [kMinPerceptualRoughness, 1].
double RoughnessFromSmoothness(double smoothness);

// Walter et al. 2007, eq. 33: D(m) = chi+(m . n) alpha^2 / (pi cos^4 theta_m (alpha^2 + tan^2
// theta_m)^2), evaluated as alpha^2 / (pi (alpha^2 cos^2 + sin^2)^2).
double D_GGX(double cos_theta_h, double alpha);

// Heitz 2014, eq. 72: Lambda(theta) = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2, cos_theta > 0.
double Lambda_GGX(double cos_theta, double alpha);

// Heitz 2014, eq. 99 (height-correlated G2 = 1 / (1 + Lambda_v + Lambda_l)) divided by the
// microfacet denominator 4 (n . l)(n . v): V = G2 / (4 NoL NoV). NoV is clamped to kMinNoV and
// NoL to 1e-12 (the caller multiplies by NoL, so V's value at NoL -> 0 does not matter).
double V_SmithGGXCorrelated(double no_v, double no_l, double alpha);

// Schlick 1994, eq. 24: F = f0 + (1 - f0)(1 - cos)^5, cos clamped to [0, 1].
glm::dvec3 F_Schlick(const glm::dvec3& f0, double cos_theta_d);

// One light and the indirect light on a surface, as UNITY_BRDF_PBS: inputs are not required to
// be normalized; outputs are clamped to the binary16 range.
struct StandardInputs {
    glm::dvec3 diffuse_color{0.0};  // albedo after energy conservation
    glm::dvec3 specular_color{0.0};
    double one_minus_reflectivity = 1.0;
    double smoothness = 0.0;
    glm::dvec3 normal{0.0, 0.0, 1.0};
    glm::dvec3 view_dir{0.0, 0.0, 1.0};   // towards the viewer
    glm::dvec3 light_dir{0.0, 0.0, 1.0};  // towards the light
    glm::dvec3 light_color{0.0};          // colour x intensity x attenuation
    glm::dvec3 indirect_diffuse{0.0};     // irradiance / pi
    glm::dvec3 indirect_specular{0.0};
};
glm::dvec3 StandardBrdf(const StandardInputs& in);

// Metallic-roughness to specular parameters (glTF 2.0, Appendix B.3.5).
glm::dvec3 SpecularColorFromMetallic(const glm::dvec3& base_color, double metallic);
double OneMinusReflectivityFromMetallic(double metallic);

}  // namespace kiln::reference

#endif  // KILN_REFERENCE_BRDF_H_
