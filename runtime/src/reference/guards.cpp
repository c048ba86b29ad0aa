#include "kiln/reference/guards.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace kiln::reference {

glm::dvec3 SafeNormalize(const glm::dvec3& v) {
    const double len2 = glm::dot(v, v);
    return len2 > kMinLengthSq ? v / std::sqrt(len2) : glm::dvec3(0.0);
}

double SafePow(double x, double y) {
    x = std::max(x, 0.0);
    y = std::max(y, 0.0);
    if (y == 0.0)
        return 1.0;  // the limit of x^0 as x -> 0, and x^0 = 1 elsewhere
    if (x == 0.0)
        return 0.0;
    return std::pow(x, y);
}

glm::dvec3 ClampToHalfRange(const glm::dvec3& c) {
    return glm::min(c, glm::dvec3(kHalfMax));
}

double Saturate(double x) {
    return std::clamp(x, 0.0, 1.0);
}

}  // namespace kiln::reference
