// The reference is finite, non-negative and within the binary16 range on an adversarial grid:
// perceptual roughness 0..1 including 0, n . v and n . l in {-1, 0, 1e-7, 1}, light = +/- view,
// distance 0..1e6, range 0 and negative, inner cone >= outer, intensities up to 1e6.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "kiln/reference/attenuation.h"
#include "kiln/reference/brdf.h"
#include "kiln/reference/classic_lighting.h"
#include "kiln/reference/guards.h"
#include "kiln/reference/sh.h"

namespace kiln::reference {
namespace {

// Unit vector with the given cosine to +z, in the plane at azimuth phi.
glm::dvec3 WithCosine(double cosine, double phi) {
    const double s = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
    return {s * std::cos(phi), s * std::sin(phi), cosine};
}

bool Sane(const glm::dvec3& c) {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(c[i]) || c[i] < 0.0 || c[i] > kHalfMax)
            return false;
    }
    return true;
}

TEST(ReferenceAdversarial, EveryModelIsFiniteOnTheGrid) {
    const double cosines[] = {-1.0, 0.0, 1e-7, 1.0};
    const double smoothness[] = {1.0, 1.0 - 1e-9, 0.955, 0.5, 0.0};  // perceptual 0 .. 1
    const double distances[] = {0.0, 1e-7, 0.01, 1.0, 1e3, 1e6};
    const double ranges[] = {0.0, -1.0, 1e-3, 1.0, 1e6};
    const double intensities[] = {0.0, 1.0, 1e6};
    const double cones[][2] = {{0.5, 0.3}, {0.5, 0.5}, {0.3, 0.5}, {0.0, 0.0}, {1.6, 3.0}};
    const glm::dvec3 n(0.0, 0.0, 1.0);
    size_t evaluated = 0;

    for (double nv : cosines) {
        const glm::dvec3 v = WithCosine(nv, 0.0);
        for (double nl : cosines) {
            for (int light_case = 0; light_case < 3; ++light_case) {
                // free light direction, light = view, light = -view
                const glm::dvec3 l = light_case == 0   ? WithCosine(nl, 2.0)
                                     : light_case == 1 ? v
                                                       : -v;
                for (double s : smoothness) {
                    for (double intensity : intensities) {
                        for (double d : distances) {
                            for (double r : ranges) {
                                for (const auto& cone : cones) {
                                    const double atten =
                                        DistanceAttenuation(d, r) * SpotCone(nl, cone[0], cone[1]);
                                    const glm::dvec3 c(intensity * atten);
                                    StandardInputs in;
                                    in.diffuse_color = glm::dvec3(0.8);
                                    in.specular_color = glm::dvec3(1.0);
                                    in.one_minus_reflectivity = 0.0;
                                    in.smoothness = s;
                                    in.normal = n;
                                    in.view_dir = v;
                                    in.light_dir = l;
                                    in.light_color = c;
                                    in.indirect_diffuse = glm::dvec3(intensity);
                                    in.indirect_specular = glm::dvec3(intensity);
                                    const std::string where =
                                        "nv " + std::to_string(nv) + " nl " + std::to_string(nl) +
                                        " case " + std::to_string(light_case) + " s " +
                                        std::to_string(s) + " I " + std::to_string(intensity) +
                                        " d " + std::to_string(d) + " r " + std::to_string(r);
                                    ASSERT_TRUE(std::isfinite(atten) && atten >= 0.0) << where;
                                    ASSERT_TRUE(Sane(StandardBrdf(in))) << where;
                                    const glm::dvec3 h = BlinnPhongHalfVector(l, v);
                                    const glm::dvec3 classic = ClampToHalfRange(
                                        LambertDiffuse(glm::dvec3(1.0), c, n, l) +
                                        BlinnPhongSpecular(glm::dvec3(1.0), c, n, h,
                                                           BlinnPhongExponent(1.0 - s)));
                                    ASSERT_TRUE(Sane(classic)) << where;
                                    ++evaluated;
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    EXPECT_EQ(evaluated, 4u * 4 * 3 * 5 * 3 * 6 * 5 * 5);
}

TEST(ReferenceAdversarial, BrdfTermsAreFiniteAtTheirSingularities) {
    for (double alpha : {0.0, 1e-7, RoughnessFromSmoothness(1.0), 1.0}) {
        for (double c : {-1.0, 0.0, 1e-7, 1.0}) {
            for (double c2 : {-1.0, 0.0, 1e-7, 1.0}) {
                const double a = std::max(alpha, RoughnessFromSmoothness(1.0));  // as the shader
                EXPECT_TRUE(std::isfinite(V_SmithGGXCorrelated(c, c2, a))) << c << " " << c2;
                EXPECT_TRUE(std::isfinite(D_GGX(c, a))) << c;
                EXPECT_TRUE(std::isfinite(F_Schlick(glm::dvec3(0.04), c).x));
            }
        }
    }
}

TEST(ReferenceAdversarial, SHAmbientIsFiniteForExtremeProbes) {
    SH9 sh;
    AddConstantRadiance(sh, glm::dvec3(1e6));
    AddDirectionalLight(sh, {0, 0, 0}, glm::dvec3(1e6));  // a zero direction is ignored safely
    AddDirectionalLight(sh, {1, 1, 1}, glm::dvec3(1e6));
    for (const glm::dvec3 n : {glm::dvec3(0, 0, 1), glm::dvec3(0), glm::dvec3(-1, 0, 0)}) {
        const glm::dvec3 e = AmbientFromSH(sh, n);
        for (int c = 0; c < 3; ++c)
            EXPECT_TRUE(std::isfinite(e[c]) && e[c] >= 0.0);
    }
}

}  // namespace
}  // namespace kiln::reference
