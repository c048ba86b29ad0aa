// The Unity-named half-precision terms of UnityStandardBRDF.cginc, in double precision (see
// guards.h for the contract): with --precision half they are the library's binary16 arithmetic,
// which kiln stability's "Unity half terms" grid checks.
#ifndef KILN_REFERENCE_UNITY_TERMS_H_
#define KILN_REFERENCE_UNITY_TERMS_H_

namespace kiln::reference {

// Burley's diffuse without the 1/pi (Burley 2012, eq. 5): (1 + (F_D90 - 1)(1 - n.l)^5)
// (1 + (F_D90 - 1)(1 - n.v)^5), F_D90 = 0.5 + 2 (l.h)^2 perceptual roughness; cosines saturated.
double DisneyDiffuse(double no_v, double no_l, double lo_h, double perceptual_roughness);

// Separable Smith with Schlick's k (Schlick 1994): 1 / (g(n.l) g(n.v)), g(c) = c (1 - k) + k,
// the product bounded below by kHalfMin so the result stays within binary16. Without the 1/4 of
// the microfacet denominator, as the template's SmithVisibilityTerm.
double SmithVisibility(double no_l, double no_v, double k);

// Beckmann's k = alpha sqrt(2 / pi) (Schlick 1994), as SmithBeckmannVisibilityTerm passes it.
double BeckmannK(double alpha);

}  // namespace kiln::reference

#endif  // KILN_REFERENCE_UNITY_TERMS_H_
