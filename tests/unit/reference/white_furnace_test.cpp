// The white furnace: Lambert's directional albedo is 1; GGX with height-correlated Smith and
// F = 1 loses energy (single scattering) but never creates it, and the visible-normal estimator
// agrees with a brute-force quadrature.
#include <gtest/gtest.h>

#include "kiln/reference/white_furnace.h"

namespace kiln::reference {
namespace {

TEST(WhiteFurnace, LambertReflectsAllTheLight) {
    EXPECT_NEAR(LambertAlbedo(), 1.0, 1e-9);
}

TEST(WhiteFurnace, GgxSmithNeverCreatesEnergy) {
    for (double nv : {1e-3, 0.1, 0.5, 1.0}) {
        for (double p : {0.045, 0.25, 0.5, 1.0}) {
            const double a = GgxSmithAlbedo(nv, p * p);
            EXPECT_LE(a, 1.0 + 1e-3) << "n . v " << nv << ", perceptual roughness " << p;
            EXPECT_GT(a, 0.0) << "n . v " << nv << ", perceptual roughness " << p;
        }
    }
}

TEST(WhiteFurnace, GgxSmithMatchesAnIndependentQuadrature) {
    // The same integral of D V (n . l) by the midpoint rule over 400 x 400 cells uniform in
    // (cos theta_l, phi), computed separately (Python, double): 0.760213 at n . v = 0.1, alpha 1;
    // 0.988324 at n . v = 0.5, alpha 0.0625; 0.915781 at n . v = 1, alpha 0.25.
    EXPECT_NEAR(GgxSmithAlbedo(0.1, 1.0), 0.760213, 2e-3);
    EXPECT_NEAR(GgxSmithAlbedo(0.5, 0.0625), 0.988324, 2e-3);
    EXPECT_NEAR(GgxSmithAlbedo(1.0, 0.25), 0.915781, 2e-3);
    // Smooth at normal incidence nearly every ray leaves after one bounce.
    EXPECT_GT(GgxSmithAlbedo(1.0, 0.045 * 0.045), 0.999);
}

}  // namespace
}  // namespace kiln::reference
