// The ambient light from a sky (docs/runtime.md, "Ambient"): an equirectangular radiance image,
// procedural or read from an HDR file, projected to SH once and read by ShadeSH9.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "kiln/reference/sh.h"
#include "render/frame_values.h"
#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

// Radiance a + b y: band-limited to order 1, so its irradiance is exact in closed form,
// E(n) / pi = a + (2/3) b n_y (Ramamoorthi and Hanrahan 2001: A0 = pi, A1 = 2 pi / 3).
std::vector<float> LinearSky(uint32_t w, uint32_t h, glm::vec3 a, glm::vec3 b) {
    std::vector<float> rgb;
    for (uint32_t v = 0; v < h; ++v) {
        for (uint32_t u = 0; u < w; ++u) {
            const double y = reference::EquirectDirection(u, v, w, h).y;
            const glm::vec3 c = a + b * float(y);
            rgb.insert(rgb.end(), {c.r, c.g, c.b});
        }
    }
    return rgb;
}

std::array<float, 4> Packed(const runtime::Values& v, const char* name) {
    const std::vector<float>& f = v.at(name);
    return {f[0], f[1], f[2], f[3]};
}

glm::dvec3 ShadeSH9(const runtime::Values& probe, const glm::dvec3& n) {
    const reference::PackedSH packed = {Packed(probe, "unity_SHAr"), Packed(probe, "unity_SHAg"),
                                        Packed(probe, "unity_SHAb"), Packed(probe, "unity_SHBr"),
                                        Packed(probe, "unity_SHBg"), Packed(probe, "unity_SHBb"),
                                        Packed(probe, "unity_SHC")};
    return reference::EvalPackedSH(packed, n);
}

// Tolerance 1e-3 relative: the image is 256 x 128 texels, whose midpoint quadrature of a + b y
// against the basis is exact to about 1e-5; the probe is packed in float.
TEST(Sky, AnImageIsProjectedSoShadeSH9IsItsIrradiance) {
    const glm::vec3 a(0.3f, 0.4f, 0.5f), b(0.2f, 0.1f, -0.1f);
    runtime::Scene scene;
    scene.ambient_mode = runtime::AmbientMode::kSky;
    scene.sky = runtime::MakeSky("linear", 256, 128, LinearSky(256, 128, a, b));
    const runtime::Values probe = runtime::ProbeValues(scene, {}, glm::vec3(0.0f));
    for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0),
                               glm::normalize(glm::dvec3(1, 1, -1))}) {
        const glm::dvec3 want = glm::dvec3(a) + 2.0 / 3.0 * glm::dvec3(b) * n.y;
        const glm::dvec3 got = ShadeSH9(probe, n);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(got[c], want[c], 1e-3 * std::abs(want[c]))
                << "normal (" << n.x << ", " << n.y << ", " << n.z << ") channel " << c;
        }
    }
    // Its mean over the sphere is a (y averages 0), and the caps are above and below it.
    EXPECT_NEAR(scene.sky->mean.r, a.r, 1e-4);
    EXPECT_NEAR(scene.sky->up.r, a.r + b.r * 0.75f, 1e-3);    // y uniform on [0.5, 1]
    EXPECT_NEAR(scene.sky->down.r, a.r - b.r * 0.75f, 1e-3);  // y uniform on [-1, -0.5]
    EXPECT_GT(scene.sky->faces[2].r, scene.sky->faces[3].r);  // +y brighter than -y
}

// The procedural sky's projection against an independent quadrature of the radiance it is
// documented to have (zenith blended into the horizon by y^(1/2) above it, the ground by
// (-y)^(1/2) below): 200,000 Fibonacci-sphere directions. Tolerance 2e-3 relative: the image is
// 256 x 128 texels of a function with a kink at the horizon.
TEST(Sky, TheProceduralSkyIsProjectedAsItsRadianceIntegrates) {
    const glm::dvec3 zenith(0.1, 0.2, 0.4), horizon(0.3, 0.35, 0.4), ground(0.08, 0.07, 0.06);
    const auto sky =
        runtime::ProceduralSky(glm::vec3(zenith), glm::vec3(horizon), glm::vec3(ground));
    reference::SH9 want;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / n;
        const double r = std::sqrt(1.0 - y * y);
        const double phi = double(i) * 2.399963229728653;
        const glm::dvec3 d(r * std::cos(phi), y, r * std::sin(phi));
        const glm::dvec3 l = y >= 0 ? glm::mix(horizon, zenith, std::sqrt(y))
                                    : glm::mix(horizon, ground, std::sqrt(-y));
        const auto basis = reference::SHBasis(d);
        for (size_t k = 0; k < 9; ++k) {
            want.L[k] += l * basis[k] * (4.0 * M_PI / n);
        }
    }
    for (size_t k = 0; k < 9; ++k) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(sky->sh[k][c], want.L[k][c], 2e-3 * std::abs(want.L[0][c]))
                << "coefficient " << k << " channel " << c;
        }
    }
}

// On the device: the sphere's centre (normal +z, on the horizon) shows ShadeSH9 of the sky.
TEST_F(RuntimeTest, ASkyLightsTheSceneThroughShadeSH9) {
    runtime::Scene scene = SphereOnFloor(RuntimeData("light_modes.material"));
    scene.instances.pop_back();  // no floor
    scene.cameras[0].world =
        glm::inverse(glm::lookAtRH(glm::vec3(0, 1, 5), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0)));
    const glm::vec3 a(0.3f, 0.4f, 0.5f), b(0.2f, 0.1f, -0.1f);
    scene.ambient_mode = runtime::AmbientMode::kSky;
    scene.sky = runtime::MakeSky("linear", 256, 128, LinearSky(256, 128, a, b));
    runtime::FrameSettings settings;
    settings.width = settings.height = 63;
    settings.default_light = false;
    const runtime::LinearImage image = Render(scene, settings);
    const size_t i = (size_t(image.height / 2) * image.width + image.width / 2) * 4;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(image.rgba[i + size_t(c)], a[c], 1e-3 * a[c]) << "channel " << c;
    }
    // Above the centre the normal tilts up: the red and green gradient brightens it.
    const size_t up =
        (size_t(image.height / 2 - image.height / 8) * image.width + image.width / 2) * 4;
    EXPECT_GT(image.rgba[up], image.rgba[i]);
    EXPECT_LT(image.rgba[up + 2], image.rgba[i + 2]);
}

// An HDR file (Radiance RGBE, written here) is read as a sky, scaled; a missing or broken file
// is an error naming it.
TEST(Sky, AnHdrFileIsReadScaledAndErrorsNameTheFile) {
    const std::string dir = ::testing::TempDir();
    const std::string path = dir + "/sky_test.hdr";
    {
        std::ofstream f(path, std::ios::binary);
        const int w = 16, h = 8;
        f << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << h << " +X " << w << "\n";
        for (int i = 0; i < w * h; ++i) {
            // 0.5 exactly: mantissa 128 with exponent 128 (2^0) -> 128 / 256 = 0.5.
            const unsigned char rgbe[4] = {128, 64, 32, 128};
            f.write(reinterpret_cast<const char*>(rgbe), 4);
        }
    }
    const Result<std::shared_ptr<const runtime::Sky>> sky = runtime::LoadSky(path, 2.0f);
    ASSERT_TRUE(sky.ok()) << sky.error().message;
    EXPECT_EQ(sky.value()->width, 16u);
    EXPECT_EQ(sky.value()->height, 8u);
    EXPECT_NEAR(sky.value()->mean.r, 1.0f, 1e-3);  // 0.5 x 2
    EXPECT_NEAR(sky.value()->mean.g, 0.5f, 1e-3);
    EXPECT_NEAR(sky.value()->mean.b, 0.25f, 1e-3);
    const auto missing = runtime::LoadSky(dir + "/no_such_sky.hdr");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("no_such_sky.hdr"), std::string::npos);
    std::ofstream(dir + "/broken.hdr") << "#?RADIANCE\nnot an image";
    const auto broken = runtime::LoadSky(dir + "/broken.hdr");
    ASSERT_FALSE(broken.ok());
    EXPECT_NE(broken.error().message.find("broken.hdr: cannot read the sky image"),
              std::string::npos)
        << broken.error().message;
}

}  // namespace
}  // namespace kiln::test
