// Environment lighting (docs/runtime.md, "Ambient"): the reflection probe unity_SpecCube0 is the
// scene's ambient prefiltered per roughness mip with GGX, and StandardMetallic reads it as
// Unity's Standard shader does (Unity_GlossyEnvironment), so a metal lit by the sky alone shows
// the sky's prefiltered radiance.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "kiln/reference/brdf.h"
#include "render/reflection_probe.h"
#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

const glm::dvec3 kZenith(0.1, 0.2, 0.6), kHorizon(0.5, 0.45, 0.4), kGround(0.15, 0.1, 0.05);

// The procedural sky's radiance as documented (scene.h): the zenith blended into the horizon
// by y^(1/2) above it, the ground by (-y)^(1/2) below it.
glm::dvec3 SkyRadiance(const glm::dvec3& d) {
    return d.y >= 0 ? glm::mix(kHorizon, kZenith, std::sqrt(d.y))
                    : glm::mix(kHorizon, kGround, std::sqrt(-d.y));
}

// The split sum's prefiltered radiance at r (n = v = r), integrated independently of the probe:
// sum L(l) D(h) (n . l) / sum D(h) (n . l) over 400,000 Fibonacci-sphere directions, GGX D of
// alpha = perceptual roughness^2.
glm::dvec3 Prefiltered(const glm::dvec3& r, double perceptual_roughness) {
    const double a2 = std::pow(perceptual_roughness, 4.0);
    const int n = 400000;
    glm::dvec3 sum(0.0);
    double total = 0;
    for (int i = 0; i < n; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / n;
        const double s = std::sqrt(1.0 - y * y);
        const double phi = double(i) * 2.399963229728653;
        const glm::dvec3 l(s * std::cos(phi), y, s * std::sin(phi));
        const double nl = glm::dot(r, l);
        if (nl <= 0) {
            continue;
        }
        const double nh2 = (1.0 + nl) * 0.5;
        const double q = nh2 * (a2 - 1.0) + 1.0;
        const double w = a2 / (M_PI * q * q) * nl;
        sum += w * SkyRadiance(l);
        total += w;
    }
    return sum / total;
}

runtime::Scene SkyScene() {
    runtime::Scene scene;
    scene.ambient_mode = runtime::AmbientMode::kSky;
    scene.sky = runtime::ProceduralSky(glm::vec3(kZenith), glm::vec3(kHorizon), glm::vec3(kGround));
    return scene;
}

// The probe's texel in direction d of mip `mip`.
glm::dvec3 ProbeTexel(const runtime::ReflectionProbe& p, uint32_t mip, const glm::dvec3& d) {
    const uint32_t n = std::max(1u, p.size >> mip);
    // Brute force over the faces: the texel whose centre is closest in angle.
    double best = -2;
    glm::vec3 out(0.0f);
    for (uint32_t f = 0; f < 6; ++f) {
        for (uint32_t y = 0; y < n; ++y) {
            for (uint32_t x = 0; x < n; ++x) {
                const double a = 2.0 * (x + 0.5) / n - 1.0, b = 2.0 * (y + 0.5) / n - 1.0;
                const double c = glm::dot(runtime::CubeTexelDirection(f, a, b), d);
                if (c > best) {
                    best = c;
                    out = p.texels[mip][(size_t(f) * n + y) * n + x];
                }
            }
        }
    }
    return glm::dvec3(out);
}

// Each mip holds the prefiltered radiance of its roughness: within 3% of the independent
// integral at the texel centres nearest to six directions (the probe's mips are 64 to 1 texels a
// side, built from box-filtered copies of a 256 x 128 sky with a kink at the horizon).
TEST(ReflectionProbe, EachMipIsTheSkyPrefilteredAtItsRoughness) {
    const runtime::Scene scene = SkyScene();
    const runtime::ReflectionProbe probe = runtime::MakeReflectionProbe(scene);
    ASSERT_EQ(probe.mips, 7u);
    ASSERT_EQ(probe.texels.size(), 7u);
    EXPECT_NEAR(runtime::ProbeMipRoughness(0), 0.0, 1e-9);
    EXPECT_NEAR(runtime::ProbeMipRoughness(6), 1.0, 1e-9);
    for (uint32_t mip : {0u, 2u, 3u, 4u, 5u}) {
        const uint32_t n = probe.size >> mip;
        // Directions at texel centres of +y, +x, -y and +z, so that no interpolation is needed.
        const double c = 2.0 * (n / 2 + 0.5) / n - 1.0;
        for (const auto& [face, a, b] : {std::tuple{2u, c, c}, std::tuple{0u, c, c},
                                         std::tuple{3u, c, -c}, std::tuple{4u, c, c}}) {
            const glm::dvec3 d = runtime::CubeTexelDirection(face, a, b);
            const double r = runtime::ProbeMipRoughness(mip);
            const glm::dvec3 want = mip == 0 ? SkyRadiance(d) : Prefiltered(d, r);
            const glm::dvec3 got = ProbeTexel(probe, mip, d);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(got[k], want[k], 0.03 * want[k] + 2e-3)
                    << "mip " << mip << " face " << face << " channel " << k;
            }
        }
    }
    // The roughest mip is nearly the cosine-weighted mean: up brighter in blue than down.
    EXPECT_GT(ProbeTexel(probe, 6, {0, 1, 0}).b, ProbeTexel(probe, 6, {0, -1, 0}).b);
}

// A white metal sphere lit only by the sky (no lights): at the pixel facing the camera n = v, so
// UNITY_BRDF_PBS gives the probe's radiance along n at the roughness's mip, times the surface
// reduction 1 / (alpha^2 + 1) and F0 = 1 (reference::StandardBrdf). Perceptual roughness
// 0.34239 is mip 3 exactly, and the camera looks along the centre of a texel of mip 3 (8 a
// side), so the GPU reads that texel as the probe holds it (RGBA16F): within 1% of the
// independent integral (measured 0.1%: the probe's prefiltering at this texel and binary16's
// rounding; the probe's bound over all directions is 3%, the test above).
TEST_F(RuntimeTest, AMetalSphereLitOnlyByTheSkyShowsItsPrefilteredRadiance) {
    runtime::Scene scene = SkyScene();
    runtime::Mesh sphere;
    sphere.primitives.push_back(SpherePrimitive(1.0f, 128, 64));
    scene.meshes = {sphere};
    const double roughness = runtime::ProbeMipRoughness(3);
    ASSERT_NEAR(roughness, 0.34239, 1e-4);
    runtime::SceneMaterial metal;
    metal.name = "metal";
    metal.base_color = glm::vec4(1.0f);
    metal.metallic = 1.0f;
    metal.roughness = float(roughness);
    scene.materials = {metal};
    scene.instances.push_back({0, glm::mat4(1.0f), "sphere"});
    runtime::Camera cam;
    cam.name = "front";
    cam.yfov = 0.6f;
    cam.znear = 0.1f;
    cam.zfar = 20.0f;
    const glm::dvec3 axis = runtime::CubeTexelDirection(4, 0.375, -0.125);  // +z face, texel 5, 3
    cam.world =
        glm::inverse(glm::lookAtRH(glm::vec3(axis) * 4.0f, glm::vec3(0.0f), glm::vec3(0, 1, 0)));
    scene.cameras.push_back(cam);
    runtime::FrameSettings settings;
    settings.width = settings.height = 65;  // an odd size: a pixel centre on the axis
    settings.default_light = false;
    const runtime::LinearImage image = Render(scene, settings);
    const float* px = &image.rgba[(size_t(32) * 65 + 32) * 4];
    const glm::dvec3 got(px[0], px[1], px[2]);

    reference::StandardInputs in;
    in.specular_color = glm::dvec3(1.0);
    in.one_minus_reflectivity = reference::OneMinusReflectivityFromMetallic(1.0);
    in.smoothness = 1.0 - roughness;
    in.normal = in.view_dir = axis;
    in.indirect_specular = Prefiltered(axis, roughness);
    const glm::dvec3 want = reference::StandardBrdf(in);
    EXPECT_GT(got.r + got.g + got.b, 0.3) << "the metal is black";
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(got[k], want[k], 0.01 * want[k]) << "channel " << k;
    }
}

}  // namespace
}  // namespace kiln::test
