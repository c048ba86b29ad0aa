#include "kiln/reference/brdf_choices.h"

#include <algorithm>
#include <cmath>

#include "kiln/reference/brdf.h"
#include "kiln/reference/guards.h"

namespace kiln::reference {

double D_BlinnPhong(double cos_theta_h, double alpha) {
    if (cos_theta_h <= 0.0)
        return 0.0;
    const double n = std::max(2.0 / (alpha * alpha) - 2.0, 0.0);
    return (n + 2.0) / (2.0 * kPi) * std::pow(std::min(cos_theta_h, 1.0), n);
}

double V_SmithGGXCorrelatedFast(double no_v, double no_l, double alpha) {
    no_v = std::clamp(std::abs(no_v), kMinNoV, 1.0);
    no_l = std::clamp(no_l, 1e-12, 1.0);
    return 0.5 / ((1.0 - alpha) * 2.0 * no_l * no_v + alpha * (no_l + no_v));
}

double F_Exact(double f0, double cos_theta_d) {
    const double s = std::sqrt(std::clamp(f0, 0.0, 0.9998));
    const double eta = (1.0 + s) / (1.0 - s);
    const double c = Saturate(cos_theta_d);
    const double g = std::sqrt(eta * eta - 1.0 + c * c);
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

}  // namespace kiln::reference
