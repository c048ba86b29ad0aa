#include "kiln/reference/unity_terms.h"

#include <algorithm>
#include <cmath>

#include "kiln/reference/guards.h"

namespace kiln::reference {

double DisneyDiffuse(double no_v, double no_l, double lo_h, double perceptual_roughness) {
    const double fd90 = 0.5 + 2.0 * lo_h * lo_h * perceptual_roughness;
    const double light = 1.0 + (fd90 - 1.0) * std::pow(1.0 - Saturate(no_l), 5.0);
    const double view = 1.0 + (fd90 - 1.0) * std::pow(1.0 - Saturate(no_v), 5.0);
    return light * view;
}

double SmithVisibility(double no_l, double no_v, double k) {
    const double g_l = no_l * (1.0 - k) + k;
    const double g_v = no_v * (1.0 - k) + k;
    return 1.0 / std::max(g_l * g_v, kHalfMin);
}

double BeckmannK(double alpha) {
    return alpha * std::sqrt(2.0 / kPi);
}

}  // namespace kiln::reference
