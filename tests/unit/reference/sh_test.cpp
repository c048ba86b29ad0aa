// The reference SH ambient: hand-derived irradiance values and the shader packing.
#include "kiln/reference/sh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "kiln/reference/guards.h"

namespace kiln::reference {
namespace {

TEST(ReferenceSH, ConstantRadianceOneGivesIrradiancePi) {
    // E = integral of 1 * cos over the hemisphere = pi; ShadeSH9 returns E / pi = 1, so a
    // white environment of radiance 1 lights an albedo-a surface to a.
    SH9 sh;
    AddConstantRadiance(sh, glm::dvec3(1.0));
    for (const glm::dvec3 n : {glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0)}) {
        EXPECT_NEAR(Irradiance(sh, n).x, kPi, 1e-5);
        EXPECT_NEAR(AmbientFromSH(sh, n).y, 1.0, 1e-5);
    }
}

TEST(ReferenceSH, DirectionalLightMatchesTheOrderTwoApproximation) {
    // A unit delta from +z: L00 = Y00, L10 = 0.488603, L20 = 2 * 0.315392. R&H eq. 13 gives
    // E(+z) = c3 L20 + c4 L00 - c5 L20 + 2 c2 L10 = 17/16 (the exact clamped cosine is 1),
    // E(x) = c4 L00 - c5 L20 = 3/32 (exact 0) and E(-z) = 1/16 (exact 0): the known ringing.
    SH9 sh;
    AddDirectionalLight(sh, {0, 0, 1}, glm::dvec3(1.0));
    EXPECT_NEAR(Irradiance(sh, {0, 0, 1}).x, 17.0 / 16.0, 1e-5);
    EXPECT_NEAR(Irradiance(sh, {1, 0, 0}).x, 3.0 / 32.0, 1e-5);
    EXPECT_NEAR(Irradiance(sh, {0, 0, -1}).x, 1.0 / 16.0, 1e-5);
}

TEST(ReferenceSH, GuardNegativeRingingIsClampedToZero) {
    // A pure linear lobe along +z (L10 = 5) has E(-z) = -2 c2 * 5 < 0.
    SH9 sh;
    sh.L[2] = glm::dvec3(5.0);
    EXPECT_LT(Irradiance(sh, {0, 0, -1}).x, 0.0);
    EXPECT_EQ(AmbientFromSH(sh, {0, 0, -1}), glm::dvec3(0.0));
}

TEST(ReferenceSH, PackedCoefficientsEvaluateToTheSameAmbient) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    SH9 sh;
    AddConstantRadiance(sh, {0.1, 0.2, 0.3});
    for (int i = 0; i < 5; ++i)
        AddDirectionalLight(sh, {u(rng), u(rng), u(rng)}, {u(rng) + 1, u(rng) + 1, u(rng) + 1});
    const PackedSH packed = PackSH9(sh);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 n = SafeNormalize({u(rng), u(rng), u(rng)});
        const glm::dvec3 want = AmbientFromSH(sh, n);
        const glm::dvec3 got = EvalPackedSH(packed, n);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c], want[c], 1e-5 * (1.0 + want[c]));  // float packing
    }
}

// The closed form against numerical integration of TrilightRadiance x SHBasis (midpoint rule,
// 1024 x 128 cells of equal solid angle; the integrand is smooth within each hemisphere and the
// cell edges meet y = 0, so the rule is accurate to about 1e-6 here).
TEST(ReferenceSH, TrilightProjectionIsTheIntegralOfTheGradient) {
    const glm::dvec3 sky(0.4, 0.5, 0.9), equator(0.2, 0.2, 0.15), ground(0.05, 0.03, 0.02);
    SH9 closed;
    AddTrilight(closed, sky, equator, ground);
    SH9 numeric;
    constexpr int ny = 1024, nphi = 128;
    const double pi = 3.14159265358979323846, cell = 4.0 * pi / (double(ny) * nphi);
    for (int i = 0; i < ny; ++i) {
        const double y = -1.0 + (i + 0.5) * 2.0 / ny, r = std::sqrt(1.0 - y * y);
        for (int j = 0; j < nphi; ++j) {
            const double phi = (j + 0.5) * 2.0 * pi / nphi;
            const glm::dvec3 d(r * std::cos(phi), y, r * std::sin(phi));
            const auto basis = SHBasis(d);
            for (size_t k = 0; k < 9; ++k)
                numeric.L[k] += TrilightRadiance(d, sky, equator, ground) * cell * basis[k];
        }
    }
    for (size_t k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(closed.L[k][c], numeric.L[k][c], 1e-5) << "coefficient " << k;
    // One colour everywhere is the flat ambient.
    SH9 flat, same;
    AddConstantRadiance(flat, equator);
    AddTrilight(same, equator, equator, equator);
    for (size_t k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(same.L[k][c], flat.L[k][c], 1e-6) << "coefficient " << k;
    // The sky lights an upward normal more than the ground a downward one.
    EXPECT_GT(AmbientFromSH(closed, {0, 1, 0}).z, AmbientFromSH(closed, {0, -1, 0}).z + 0.3);
}

}  // namespace
}  // namespace kiln::reference
