// The alternative BRDF terms the templates offer per build (KilnBRDF.cginc, "the BRDF choices"),
// in double precision (see guards.h for the contract).
#ifndef KILN_REFERENCE_BRDF_CHOICES_H_
#define KILN_REFERENCE_BRDF_CHOICES_H_

namespace kiln::reference {

// Normalized Blinn-Phong, D = (n + 2) / (2 pi) cos^n with n = 2 / alpha^2 - 2 (Walter et al.
// 2007, section 5.2); 0 for cos <= 0.
double D_BlinnPhong(double cos_theta_h, double alpha);

// Hammon 2017: V = 0.5 / ((1 - alpha) 2 NoL NoV + alpha (NoL + NoV)), with V_SmithGGXCorrelated's
// clamps (NoV >= kMinNoV, NoL >= 1e-12).
double V_SmithGGXCorrelatedFast(double no_v, double no_l, double alpha);

// The unpolarized Fresnel reflectance of a dielectric whose normal-incidence reflectance is f0
// (Cook and Torrance 1982; Walter et al. 2007, eq. 22); f0 is clamped to 0.9998 (eta finite).
double F_Exact(double f0, double cos_theta_d);

}  // namespace kiln::reference

#endif  // KILN_REFERENCE_BRDF_CHOICES_H_
