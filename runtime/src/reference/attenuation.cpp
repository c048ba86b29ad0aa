#include "kiln/reference/attenuation.h"

#include <algorithm>
#include <cmath>

#include "kiln/reference/guards.h"

namespace kiln::reference {

double InverseSquare(double distance) {
    const double d = std::max(std::abs(distance), kMinLightDistance);
    return 1.0 / (d * d);
}

double RangeWindow(double distance, double range) {
    if (!(range > 0.0))
        return 1.0;
    const double ratio = std::abs(distance) / range;
    if (ratio >= 1.0)
        return 0.0;  // also keeps ratio^4 from overflowing for huge distances
    const double w = Saturate(1.0 - ratio * ratio * ratio * ratio);
    return w * w;
}

double DistanceAttenuation(double distance, double range) {
    return InverseSquare(distance) * RangeWindow(distance, range);
}

double InverseRangeSquared(double range) {
    return range > 0.0 ? 1.0 / (range * range) : 0.0;
}

double SpotCone(double cos_to_axis, double outer_angle, double inner_angle) {
    const double cos_outer = std::cos(outer_angle);
    const double cos_inner = std::cos(inner_angle);
    const double scale = 1.0 / std::max(cos_inner - cos_outer, kMinConeCosDelta);
    const double t = Saturate((cos_to_axis - cos_outer) * scale);
    return t * t;
}

}  // namespace kiln::reference
