#include "kiln/reference/sh.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "kiln/reference/guards.h"

namespace kiln::reference {
namespace {

// R&H 2001, eq. 13 constants.
constexpr double kC1 = 0.429043, kC2 = 0.511664, kC3 = 0.743125, kC4 = 0.886227, kC5 = 0.247708;

}  // namespace

std::array<double, 9> SHBasis(const glm::dvec3& d) {
    const double x = d.x, y = d.y, z = d.z;
    return {0.282095,
            0.488603 * y,
            0.488603 * z,
            0.488603 * x,
            1.092548 * x * y,
            1.092548 * y * z,
            0.315392 * (3.0 * z * z - 1.0),
            1.092548 * x * z,
            0.546274 * (x * x - y * y)};
}

void AddDirectionalLight(SH9& sh, const glm::dvec3& d, const glm::dvec3& color) {
    const auto y = SHBasis(SafeNormalize(d));
    for (size_t i = 0; i < 9; ++i)
        sh.L[i] += color * y[i];
}

void AddConstantRadiance(SH9& sh, const glm::dvec3& color) {
    sh.L[0] += color * std::sqrt(4.0 * kPi);  // integral of Y_00 = 1 / sqrt(4 pi) over 4 pi sr
}

glm::dvec3 TrilightRadiance(const glm::dvec3& d,
                            const glm::dvec3& sky,
                            const glm::dvec3& equator,
                            const glm::dvec3& ground) {
    const double y = SafeNormalize(d).y;
    return y >= 0 ? equator + (sky - equator) * y : equator + (ground - equator) * -y;
}

void AddTrilight(SH9& sh,
                 const glm::dvec3& sky,
                 const glm::dvec3& equator,
                 const glm::dvec3& ground) {
    // L depends on y alone, and dOmega = dy dphi: over a circle of constant y, x^2 and z^2
    // average (1 - y^2) / 2 and the odd terms vanish. With I0 = int L dy = E + (S + G) / 2,
    // I1 = int L y dy = (S - G) / 3 and I2 = int L (3y^2 - 1) dy = (S + G - 2E) / 4 over
    // [-1, 1]: L_00 = 2 pi c0 I0, L_(y) = 2 pi c1 I1, and the (3z^2 - 1) and (x^2 - y^2) terms,
    // whose circle averages are both (1 - 3y^2) / 2, get -pi c I2.
    const glm::dvec3 i0 = equator + (sky + ground) * 0.5;
    const glm::dvec3 i1 = (sky - ground) / 3.0;
    const glm::dvec3 i2 = (sky + ground - 2.0 * equator) / 4.0;
    sh.L[0] += 2.0 * kPi * 0.282095 * i0;
    sh.L[1] += 2.0 * kPi * 0.488603 * i1;
    sh.L[6] += -kPi * 0.315392 * i2;
    sh.L[8] += -kPi * 0.546274 * i2;
}

glm::dvec3 EquirectDirection(uint32_t u, uint32_t v, uint32_t width, uint32_t height) {
    const double theta = kPi * (double(v) + 0.5) / double(height);
    const double phi = 2.0 * kPi * (double(u) + 0.5) / double(width) - kPi;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

double EquirectSolidAngle(uint32_t v, uint32_t width, uint32_t height) {
    const double top = kPi * double(v) / double(height);
    const double bottom = kPi * double(v + 1) / double(height);
    return 2.0 * kPi / double(width) * (std::cos(top) - std::cos(bottom));
}

void AddEquirect(SH9& sh, uint32_t width, uint32_t height, const float* rgb) {
    for (uint32_t v = 0; v < height; ++v) {
        const double omega = EquirectSolidAngle(v, width, height);
        for (uint32_t u = 0; u < width; ++u) {
            const float* t = rgb + (size_t(v) * width + u) * 3;
            const glm::dvec3 radiance(t[0], t[1], t[2]);
            const std::array<double, 9> y = SHBasis(EquirectDirection(u, v, width, height));
            for (size_t k = 0; k < 9; ++k) {
                sh.L[k] += radiance * (y[k] * omega);
            }
        }
    }
}

glm::dvec3 Irradiance(const SH9& sh, const glm::dvec3& n) {
    const double x = n.x, y = n.y, z = n.z;
    const auto& L = sh.L;
    return kC1 * L[8] * (x * x - y * y) + kC3 * L[6] * z * z + kC4 * L[0] - kC5 * L[6] +
           2.0 * kC1 * (L[4] * x * y + L[7] * x * z + L[5] * y * z) +
           2.0 * kC2 * (L[3] * x + L[1] * y + L[2] * z);
}

glm::dvec3 AmbientFromSH(const SH9& sh, const glm::dvec3& n) {
    return glm::max(Irradiance(sh, n) / kPi, glm::dvec3(0.0));
}

PackedSH PackSH9(const SH9& sh) {
    PackedSH p{};
    const auto& L = sh.L;
    for (int c = 0; c < 3; ++c) {
        // A = (x, y, z, 1) coefficients; B = (xy, yz, zz, zx); C = (x^2 - y^2).
        p[size_t(c)] = {float(2.0 * kC2 * L[3][c] / kPi), float(2.0 * kC2 * L[1][c] / kPi),
                        float(2.0 * kC2 * L[2][c] / kPi),
                        float((kC4 * L[0][c] - kC5 * L[6][c]) / kPi)};
        p[size_t(3 + c)] = {float(2.0 * kC1 * L[4][c] / kPi), float(2.0 * kC1 * L[5][c] / kPi),
                            float(kC3 * L[6][c] / kPi), float(2.0 * kC1 * L[7][c] / kPi)};
        p[6][size_t(c)] = float(kC1 * L[8][c] / kPi);
    }
    p[6][3] = 1.0f;
    return p;
}

glm::dvec3 EvalPackedSH(const PackedSH& packed, const glm::dvec3& n) {
    const double a[4] = {n.x, n.y, n.z, 1.0};
    const double b[4] = {n.x * n.y, n.y * n.z, n.z * n.z, n.z * n.x};
    glm::dvec3 e(0.0);
    for (int c = 0; c < 3; ++c) {
        double v = packed[6][size_t(c)] * (n.x * n.x - n.y * n.y);
        for (size_t k = 0; k < 4; ++k)
            v += packed[size_t(c)][k] * a[k] + packed[size_t(3 + c)][k] * b[k];
        e[c] = v;
    }
    return glm::max(e, glm::dvec3(0.0));
}

}  // namespace kiln::reference
