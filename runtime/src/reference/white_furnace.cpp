#include "kiln/reference/white_furnace.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "kiln/reference/brdf.h"
#include "kiln/reference/guards.h"

namespace kiln::reference {
namespace {

// Van der Corput radical inverse in base 2 (the Hammersley set's second coordinate).
double RadicalInverse(uint32_t bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return double(bits) * 2.3283064365386963e-10;
}

glm::dvec3 ViewAt(double no_v) {
    const double c = std::clamp(no_v, 0.0, 1.0);
    return {std::sqrt(1.0 - c * c), 0.0, c};
}

}  // namespace

double LambertAlbedo(uint32_t samples) {
    // Midpoint rule in (cos theta, phi), where d omega = d(cos theta) d phi.
    double sum = 0.0;
    for (uint32_t i = 0; i < samples; ++i) {
        const double no_l = (i + 0.5) / samples;
        for (uint32_t j = 0; j < samples; ++j)
            sum += (1.0 / kPi) * no_l;
    }
    return sum * (1.0 / samples) * (2.0 * kPi / samples);
}

double GgxSmithAlbedo(double no_v, double alpha, uint32_t samples) {
    const glm::dvec3 v = ViewAt(std::max(no_v, kMinNoV));
    const double g1_v = 1.0 / (1.0 + Lambda_GGX(v.z, alpha));
    double sum = 0.0;
    for (uint32_t i = 0; i < samples; ++i) {
        const double u1 = (i + 0.5) / samples, u2 = RadicalInverse(i);
        // A visible normal (Heitz 2018, "Sampling the GGX Distribution of Visible Normals",
        // listing 1): stretch the view, sample the projected hemisphere, unstretch.
        const glm::dvec3 vh = glm::normalize(glm::dvec3(alpha * v.x, alpha * v.y, v.z));
        const double len2 = vh.x * vh.x + vh.y * vh.y;
        const glm::dvec3 t1 =
            len2 > 0.0 ? glm::dvec3(-vh.y, vh.x, 0.0) / std::sqrt(len2) : glm::dvec3(1, 0, 0);
        const glm::dvec3 t2 = glm::cross(vh, t1);
        const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
        const double p1 = r * std::cos(phi);
        const double s = 0.5 * (1.0 + vh.z);
        const double p2 = (1.0 - s) * std::sqrt(1.0 - p1 * p1) + s * r * std::sin(phi);
        const glm::dvec3 nh =
            p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
        const glm::dvec3 h =
            glm::normalize(glm::dvec3(alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)));
        const glm::dvec3 l = 2.0 * glm::dot(v, h) * h - v;
        if (l.z <= 0.0)
            continue;  // reflected below the horizon: no contribution
        // f (n . l) / pdf(l) with pdf(l) = G1(v) D(h) / (4 n . v) and f = D V (F = 1):
        // 4 V (n . l)(n . v) / G1(v), which is G2 / G1(v) for a consistent V.
        sum += 4.0 * V_SmithGGXCorrelated(v.z, l.z, alpha) * l.z * v.z / g1_v;
    }
    return sum / samples;
}

}  // namespace kiln::reference
