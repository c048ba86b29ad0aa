// The reference's light falloff against hand-derived values, including its guards.
#include "kiln/reference/attenuation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kiln/reference/guards.h"

namespace kiln::reference {
namespace {

TEST(ReferenceAttenuation, InverseSquareLaw) {
    EXPECT_DOUBLE_EQ(InverseSquare(2.0), 0.25);
    EXPECT_DOUBLE_EQ(InverseSquare(10.0), 0.01);
    // guard: at the light's position the light is a 1 cm sphere, not a singularity
    EXPECT_DOUBLE_EQ(InverseSquare(0.0), 1e4);
    EXPECT_DOUBLE_EQ(InverseSquare(0.001), 1e4);
}

TEST(ReferenceAttenuation, RangeWindowIsSmoothAndReachesZeroAtTheRange) {
    EXPECT_DOUBLE_EQ(RangeWindow(0.0, 10.0), 1.0);
    EXPECT_DOUBLE_EQ(RangeWindow(5.0, 10.0), (15.0 / 16.0) * (15.0 / 16.0));  // (1 - 1/16)^2
    EXPECT_EQ(RangeWindow(10.0, 10.0), 0.0);
    EXPECT_EQ(RangeWindow(1e6, 10.0), 0.0);
    // guard: range 0 or negative means unlimited (glTF: no range), never a division by zero
    EXPECT_EQ(RangeWindow(3.0, 0.0), 1.0);
    EXPECT_EQ(RangeWindow(3.0, -5.0), 1.0);
    EXPECT_DOUBLE_EQ(DistanceAttenuation(5.0, 10.0), 0.04 * (15.0 / 16.0) * (15.0 / 16.0));
}

TEST(ReferenceAttenuation, InverseRangeSquaredIsWhatTheShaderReceives) {
    EXPECT_DOUBLE_EQ(InverseRangeSquared(4.0), 1.0 / 16.0);
    EXPECT_EQ(InverseRangeSquared(0.0), 0.0);
    EXPECT_EQ(InverseRangeSquared(-2.0), 0.0);
    // the shader's window form saturate(1 - (d^2 / r^2)^2)^2 is the same function
    const double d = 3.0, r = 7.0;
    const double ratio2 = d * d * InverseRangeSquared(r);
    const double w = 1.0 - ratio2 * ratio2;
    EXPECT_NEAR(w * w, RangeWindow(d, r), 1e-15);
}

TEST(ReferenceAttenuation, SpotConeRampsFromOuterToInner) {
    const double outer = 45.0 * kPi / 180.0, inner = 30.0 * kPi / 180.0;
    EXPECT_EQ(SpotCone(1.0, outer, inner), 1.0);                       // on the axis
    EXPECT_EQ(SpotCone(std::cos(inner), outer, inner), 1.0);           // at the inner cone
    EXPECT_NEAR(SpotCone(std::cos(outer), outer, inner), 0.0, 1e-12);  // at the outer cone
    EXPECT_EQ(SpotCone(std::cos(60.0 * kPi / 180.0), outer, inner), 0.0);
    const double mid = 0.5 * (std::cos(outer) + std::cos(inner));
    EXPECT_NEAR(SpotCone(mid, outer, inner), 0.25, 1e-12);  // t = 1/2, squared
}

TEST(ReferenceAttenuation, GuardSpotWithInnerAtOrBeyondOuterHasAHardEdge) {
    const double a = 30.0 * kPi / 180.0;
    for (double inner : {a, a + 0.2}) {
        EXPECT_EQ(SpotCone(1.0, a, inner), 1.0);
        EXPECT_EQ(SpotCone(std::cos(a + 0.01), a, inner), 0.0);
        const double v = SpotCone(std::cos(a - 0.01), a, inner);
        EXPECT_TRUE(std::isfinite(v));
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
    }
}

}  // namespace
}  // namespace kiln::reference
