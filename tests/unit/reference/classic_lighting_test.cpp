// The reference's classic models against values derived by hand from their equations.
#include "kiln/reference/classic_lighting.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kiln/reference/guards.h"

namespace kiln::reference {
namespace {

const glm::dvec3 kUp(0.0, 0.0, 1.0);

glm::dvec3 AtAngle(double degrees) {  // unit vector in the xz plane, `degrees` from +z
    const double r = degrees * kPi / 180.0;
    return {std::sin(r), 0.0, std::cos(r)};
}

TEST(ReferenceClassic, LambertIsAlbedoTimesLightTimesCosine) {
    // 0.5 * 2 * cos 60 = 0.5
    EXPECT_NEAR(LambertDiffuse(glm::dvec3(0.5), glm::dvec3(2.0), kUp, AtAngle(60)).x, 0.5, 1e-12);
    EXPECT_NEAR(LambertDiffuse(glm::dvec3(1.0), glm::dvec3(1.0), kUp, kUp).y, 1.0, 1e-12);
    // light from below the surface contributes nothing
    EXPECT_EQ(LambertDiffuse(glm::dvec3(1.0), glm::dvec3(1.0), kUp, -kUp).z, 0.0);
    EXPECT_EQ(LambertDiffuse(glm::dvec3(1.0), glm::dvec3(1.0), kUp, AtAngle(90.0001)).z, 0.0);
}

TEST(ReferenceClassic, AmbientIsAlbedoTimesAmbient) {
    EXPECT_EQ(AmbientConstant({0.5, 0.25, 1.0}, {0.2, 0.4, 0.0}), glm::dvec3(0.1, 0.1, 0.0));
}

TEST(ReferenceClassic, BlinnPhongHalfVectorAndLobe) {
    // l at 90 degrees from v = n: h is 45 degrees from n; cos 45^2 = 0.5
    const glm::dvec3 h = BlinnPhongHalfVector(AtAngle(90), kUp);
    EXPECT_NEAR(h.x, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(h.z, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(BlinnPhongSpecular(glm::dvec3(1.0), glm::dvec3(1.0), kUp, h, 2.0).x, 0.5, 1e-12);
    // mirror direction: the full specular colour times the light
    EXPECT_NEAR(BlinnPhongSpecular(glm::dvec3(0.3), glm::dvec3(2.0), kUp, kUp, 50.0).x, 0.6, 1e-12);
    EXPECT_NEAR(BlinnPhongExponent(0.5), 50.0, 1e-12);
    EXPECT_EQ(BlinnPhongExponent(-1.0), 0.0);
    EXPECT_EQ(BlinnPhongExponent(7.0), 100.0);
}

TEST(ReferenceClassic, GuardPowZeroToTheZeroIsOne) {
    // Smoothness 0 gives exponent 0: the lecture's pow(0, 0); the limit x^0 = 1 is used.
    const glm::dvec3 h = AtAngle(90);  // n . h = 0
    EXPECT_EQ(BlinnPhongSpecular(glm::dvec3(0.5), glm::dvec3(1.0), kUp, h, BlinnPhongExponent(0)),
              glm::dvec3(0.5));
    EXPECT_EQ(SafePow(0.0, 0.0), 1.0);
    EXPECT_EQ(SafePow(0.0, 3.0), 0.0);
    EXPECT_EQ(SafePow(-0.5, 2.0), 0.0) << "negative base counts as 0";
    EXPECT_NEAR(SafePow(0.25, 0.5), 0.5, 1e-15);
}

TEST(ReferenceClassic, GuardHalfVectorOfOppositeLightAndViewIsZeroNotNaN) {
    const glm::dvec3 h = BlinnPhongHalfVector(AtAngle(30), -AtAngle(30));
    EXPECT_EQ(h, glm::dvec3(0.0));
    EXPECT_EQ(BlinnPhongSpecular(glm::dvec3(1.0), glm::dvec3(1.0), kUp, h, 10.0), glm::dvec3(0.0));
    EXPECT_EQ(SafeNormalize(glm::dvec3(0.0)), glm::dvec3(0.0));
}

TEST(ReferenceClassic, EnergyConservationScalesByOneMinusTheStrongestSpecular) {
    double w = -1.0;
    const glm::dvec3 albedo = EnergyConservation(glm::dvec3(0.8), {0.2, 0.5, 0.1}, &w);
    EXPECT_DOUBLE_EQ(w, 0.5);
    EXPECT_EQ(albedo, glm::dvec3(0.4));
    // guard: a specular colour above 1 cannot make the diffuse weight negative
    EnergyConservation(glm::dvec3(1.0), glm::dvec3(1.5), &w);
    EXPECT_EQ(w, 0.0);
}

TEST(ReferenceClassic, GuardHdrResultsClampToTheHalfRange) {
    EXPECT_EQ(ClampToHalfRange(glm::dvec3(1e6, 1.0, 65504.0)), glm::dvec3(65504.0, 1.0, 65504.0));
}

}  // namespace
}  // namespace kiln::reference
