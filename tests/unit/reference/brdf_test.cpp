// The reference BRDF against hand-derived values and its defining integrals.
#include "kiln/reference/brdf.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kiln/reference/guards.h"

namespace kiln::reference {
namespace {

TEST(ReferenceBrdf, RoughnessIsPerceptualSquaredAndClamped) {
    EXPECT_DOUBLE_EQ(RoughnessFromSmoothness(0.5), 0.25);
    EXPECT_DOUBLE_EQ(RoughnessFromSmoothness(0.0), 1.0);
    // guard: smoothness 1 would be alpha 0 (a delta); clamped to 0.045^2
    EXPECT_DOUBLE_EQ(RoughnessFromSmoothness(1.0), 0.045 * 0.045);
}

TEST(ReferenceBrdf, GgxPeakIsOneOverPiAlphaSquared) {
    EXPECT_NEAR(D_GGX(1.0, 0.5), 1.0 / (kPi * 0.25), 1e-12);
    EXPECT_NEAR(D_GGX(1.0, 1.0), 1.0 / kPi, 1e-12);  // alpha = 1 is uniform: 1/pi everywhere
    EXPECT_NEAR(D_GGX(0.3, 1.0), 1.0 / kPi, 1e-12);
    EXPECT_EQ(D_GGX(-0.1, 0.5), 0.0);
}

// The projected microfacet area equals the macro-surface's: int D(h) (n . h) dw = 1.
TEST(ReferenceBrdf, GgxIsNormalizedOverTheHemisphere) {
    for (double alpha : {0.05, 0.25, 0.6, 1.0}) {
        const int steps = 200000;
        double sum = 0.0;
        for (int i = 0; i < steps; ++i) {
            const double theta = (i + 0.5) * (kPi / 2) / steps;
            sum += D_GGX(std::cos(theta), alpha) * std::cos(theta) * std::sin(theta);
        }
        EXPECT_NEAR(2.0 * kPi * sum * (kPi / 2) / steps, 1.0, 1e-4) << "alpha " << alpha;
    }
}

TEST(ReferenceBrdf, SmithVisibilityAtNormalIncidenceIsOneQuarter) {
    // G2 = 1 (no masking at theta = 0), so V = 1 / (4 * 1 * 1) for any roughness.
    for (double alpha : {0.002, 0.25, 1.0})
        EXPECT_NEAR(V_SmithGGXCorrelated(1.0, 1.0, alpha), 0.25, 1e-12);
    // Lambda(0) = 0; Lambda(60 deg, alpha 1) = (-1 + sqrt(1 + 3)) / 2 = 0.5
    EXPECT_EQ(Lambda_GGX(1.0, 0.5), 0.0);
    EXPECT_NEAR(Lambda_GGX(0.5, 1.0), 0.5, 1e-12);
    // then G2 = 1 / (1 + 0.5 + 0.5) = 0.5 and V = 0.5 / (4 * 0.25) = 0.5
    EXPECT_NEAR(V_SmithGGXCorrelated(0.5, 0.5, 1.0), 0.5, 1e-12);
}

TEST(ReferenceBrdf, SmithVisibilityMatchesFilamentsClosedForm) {
    // The shader uses 0.5 / (NoL sqrt(NoV^2 (1 - a^2) + a^2) + NoV sqrt(NoL^2 (1 - a^2) + a^2));
    // the reference computes G2 / (4 NoL NoV) from Lambda. They are the same function.
    for (double alpha : {0.01, 0.3, 0.9}) {
        for (double nv : {0.05, 0.4, 1.0}) {
            for (double nl : {0.1, 0.7, 1.0}) {
                const double a2 = alpha * alpha;
                const double closed = 0.5 / (nl * std::sqrt(nv * nv * (1 - a2) + a2) +
                                             nv * std::sqrt(nl * nl * (1 - a2) + a2));
                EXPECT_NEAR(V_SmithGGXCorrelated(nv, nl, alpha), closed, 1e-9 * closed);
            }
        }
    }
}

TEST(ReferenceBrdf, SchlickAtNormalAndGrazingIncidence) {
    EXPECT_EQ(F_Schlick(glm::dvec3(0.04), 1.0), glm::dvec3(0.04));
    EXPECT_EQ(F_Schlick(glm::dvec3(0.04), 0.0), glm::dvec3(1.0));
    EXPECT_NEAR(F_Schlick(glm::dvec3(0.04), 0.5).x, 0.04 + 0.96 / 32.0, 1e-15);
}

TEST(ReferenceBrdf, StandardAtNormalIncidenceIsDiffusePlusF0OverFourAlphaSquared) {
    // n = l = v: D = 1 / (pi a^2), V = 1/4, F = F0, so pi D V F = F0 / (4 a^2);
    // smoothness 0.5: a = 0.25, F0 = 0.04 -> 0.16.
    StandardInputs in;
    in.diffuse_color = glm::dvec3(0.5);
    in.specular_color = glm::dvec3(0.04);
    in.one_minus_reflectivity = 0.96;
    in.smoothness = 0.5;
    in.light_color = glm::dvec3(1.0);
    EXPECT_NEAR(StandardBrdf(in).x, 0.5 + 0.16, 1e-12);
    in.indirect_diffuse = glm::dvec3(0.2);  // adds diffuse * ambient = 0.1
    EXPECT_NEAR(StandardBrdf(in).y, 0.5 + 0.16 + 0.1, 1e-12);
}

TEST(ReferenceBrdf, MetallicParameterization) {
    EXPECT_EQ(SpecularColorFromMetallic({0.9, 0.5, 0.1}, 1.0), glm::dvec3(0.9, 0.5, 0.1));
    EXPECT_EQ(SpecularColorFromMetallic({0.9, 0.5, 0.1}, 0.0), glm::dvec3(0.04));
    EXPECT_DOUBLE_EQ(OneMinusReflectivityFromMetallic(0.0), 0.96);
    EXPECT_DOUBLE_EQ(OneMinusReflectivityFromMetallic(1.0), 0.0);
}

}  // namespace
}  // namespace kiln::reference
