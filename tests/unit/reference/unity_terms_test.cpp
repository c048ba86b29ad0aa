// The double-precision twins of the Unity-named half terms (kiln/reference/unity_terms.h): their
// limits, and the guard that keeps SmithVisibility within binary16.
#include "kiln/reference/unity_terms.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kiln/reference/guards.h"

namespace kiln::reference {
namespace {

TEST(UnityTerms, DisneyDiffuseIsOneFacingTheLightAndViewAndHalvesTwiceAtGrazing) {
    EXPECT_DOUBLE_EQ(DisneyDiffuse(1.0, 1.0, 0.3, 0.7), 1.0);
    // F_D90 = 0.5 at l . h = 0: each grazing factor is 1 + (0.5 - 1) = 0.5.
    EXPECT_DOUBLE_EQ(DisneyDiffuse(0.0, 0.0, 0.0, 1.0), 0.25);
    // F_D90 = 0.5 + 2 * 0.25 * 1 = 1: no retro-reflection term at all.
    EXPECT_DOUBLE_EQ(DisneyDiffuse(0.2, 0.6, 0.5, 1.0), 1.0);
    // Cosines are saturated: a back-facing n . l is the grazing one.
    EXPECT_DOUBLE_EQ(DisneyDiffuse(1.0, -0.5, 0.0, 1.0), DisneyDiffuse(1.0, 0.0, 0.0, 1.0));
}

TEST(UnityTerms, SmithVisibilityIsExactAwayFromTheGuardAndWithinBinary16AtIt) {
    const double k = BeckmannK(0.25);
    EXPECT_NEAR(k, 0.25 * std::sqrt(2.0 / kPi), 1e-15);
    const double g_l = 0.5 * (1.0 - k) + k, g_v = 0.8 * (1.0 - k) + k;
    EXPECT_DOUBLE_EQ(SmithVisibility(0.5, 0.8, k), 1.0 / (g_l * g_v));
    // k = 0 at grazing angles: 1 / 0 without the guard; 1 / 2^-14 = 16384 with it.
    EXPECT_DOUBLE_EQ(SmithVisibility(0.0, 0.0, 0.0), 16384.0);
    EXPECT_LT(SmithVisibility(0.0, 1e-7, 0.0), kHalfMax);
}

}  // namespace
}  // namespace kiln::reference
