// The forward path's light modes (docs/runtime.md, "Light modes"): lights that are not per-pixel
// reach the base pass per vertex (Shade4PointLights at the vertices) or in the object's spherical
// harmonics (ShadeSH9). KilnTest/LightModes writes exactly those two terms, and each is checked
// against the CPU reference evaluated the same way: the reference SH projection of the same
// lights at the object's centre, and the reference attenuation at the vertex.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <fstream>
#include <vector>

#include "kiln/reference/attenuation.h"
#include "kiln/reference/sh.h"
#include "render/frame_values.h"
#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A unit sphere at (0, 1, 0) alone, seen head-on from +z: the centre pixel of an odd-sized image
// sees the point (0, 1, 1) with normal +z, which is a vertex of the sphere's tessellation.
runtime::Scene FacingSphere(const std::string& material) {
    runtime::Scene scene = SphereOnFloor(RuntimeData(material));
    scene.instances.pop_back();  // no floor
    scene.cameras[0].world =
        glm::inverse(glm::lookAtRH(glm::vec3(0, 1, 5), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0)));
    return scene;
}

runtime::Light Punctual(runtime::LightType type,
                        glm::vec3 position,
                        glm::vec3 color,
                        float intensity,
                        float range = 0) {
    runtime::Light l;
    l.type = type;
    l.position = position;
    l.color = color;
    l.intensity = intensity;
    l.range = range;
    l.direction = glm::normalize(glm::vec3(0, 1, 0) - position);  // spots aim at the centre
    l.inner_cone = 0.2f;
    l.outer_cone = 0.6f;
    return l;
}

runtime::FrameSettings Settings(runtime::LightMode mode) {
    runtime::FrameSettings s;
    s.width = s.height = 63;  // odd: one pixel at the exact centre
    s.default_light = false;
    s.light_mode = mode;
    return s;
}

glm::dvec3 CentrePixel(const runtime::LinearImage& img) {
    const size_t i = (size_t(img.height / 2) * img.width + img.width / 2) * 4;
    return {img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]};
}

// Illuminance (lux times colour) of `l` at `p` and the unit direction towards it.
std::pair<glm::dvec3, glm::dvec3> Reaching(const runtime::Light& l, const glm::dvec3& p) {
    const glm::dvec3 to = glm::dvec3(l.position) - p;
    const double d = glm::length(to);
    const glm::dvec3 dir = to / d;
    double falloff = reference::DistanceAttenuation(d, l.range);
    if (l.type == runtime::LightType::kSpot) {
        falloff *= reference::SpotCone(glm::dot(-dir, glm::dvec3(l.direction)), l.outer_cone,
                                       l.inner_cone);
    }
    return {glm::dvec3(l.color) * double(l.intensity) * falloff, dir};
}

// ShadeSH9 at n for the ambient plus `lights` projected at the object's centre.
glm::dvec3 ReferenceSH(const glm::vec3& ambient,
                       const std::vector<runtime::Light>& lights,
                       const glm::dvec3& center,
                       const glm::dvec3& n) {
    reference::SH9 sh;
    reference::AddConstantRadiance(sh, glm::dvec3(ambient));
    for (const runtime::Light& l : lights) {
        const auto [lux, dir] = Reaching(l, center);
        reference::AddDirectionalLight(sh, dir, lux);
    }
    return reference::AmbientFromSH(sh, n);
}

void ExpectClose(const glm::dvec3& got, const glm::dvec3& want, double relative) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], want[c], relative * std::abs(want[c]) + 1e-5)
            << "channel " << c << ": got " << got[c] << ", the reference gives " << want[c];
    }
}

// Tolerance 1e-3 relative: the shader evaluates the packed SH in fp32 from float constants, the
// reference in double; the centre pixel's normal is the vertex normal (barycentric (1, 0, 0)).
TEST_F(RuntimeTest, ShLightsAreTheReferenceProjectionOfTheSameLights) {
    runtime::Scene scene = FacingSphere("light_modes.material");
    scene.ambient = glm::vec3(0.02f, 0.03f, 0.04f);
    using T = runtime::LightType;
    scene.lights = {Punctual(T::kPoint, {0, 1, 3}, {1, 0.9f, 0.8f}, 20),
                    Punctual(T::kPoint, {2.5f, 2, 1}, {0.3f, 0.6f, 1}, 15, 6),
                    Punctual(T::kSpot, {-2, 1.5f, 2}, {1, 1, 1}, 30),
                    Punctual(T::kSpot, {0, 4, 0.5f}, {1, 0.4f, 0.2f}, 25, 8),
                    Punctual(T::kPoint, {0, 1, -3}, {1, 1, 1}, 40)};  // behind: ringing only
    runtime::FrameStats stats;
    const runtime::LinearImage image = Render(scene, Settings(runtime::LightMode::kSH), &stats);
    EXPECT_EQ(stats.sh_lit, 1u);
    EXPECT_EQ(stats.vertex_lit, 0u);
    EXPECT_EQ(stats.add_passes, 0u);
    const glm::dvec3 want = ReferenceSH(scene.ambient, scene.lights, {0, 1, 0}, {0, 0, 1});
    ExpectClose(CentrePixel(image), want, 1e-3);
    // The lights contribute visibly, not only the ambient.
    const glm::dvec3 ambient_only = ReferenceSH(scene.ambient, {}, {0, 1, 0}, {0, 0, 1});
    EXPECT_GT(want.r - ambient_only.r, 0.2);

    // In the automatic mode the same object draws them per pixel: no SH lights.
    runtime::FrameSettings automatic = Settings(runtime::LightMode::kAuto);
    automatic.pixel_lights = 8;
    Render(scene, automatic, &stats);
    EXPECT_EQ(stats.sh_lit, 0u);
}

// Tolerance 1e-3 relative: Shade4PointLights in fp32 at the vertex the centre pixel sees, against
// the reference's Lambert x attenuation in double.
TEST_F(RuntimeTest, VertexLightsAreShade4PointLightsAtTheVertices) {
    runtime::Scene scene = FacingSphere("light_modes.material");
    scene.ambient = glm::vec3(0.0f);
    using T = runtime::LightType;
    scene.lights = {Punctual(T::kPoint, {0, 1, 3}, {1, 0.9f, 0.8f}, 20),
                    Punctual(T::kPoint, {2.5f, 2, 1}, {0.3f, 0.6f, 1}, 15, 6),
                    Punctual(T::kPoint, {-2, 1.5f, 2}, {1, 1, 1}, 30, 4),
                    Punctual(T::kPoint, {0, 4, 0.5f}, {1, 0.4f, 0.2f}, 25)};
    runtime::FrameStats stats;
    const runtime::LinearImage image = Render(scene, Settings(runtime::LightMode::kVertex), &stats);
    EXPECT_EQ(stats.vertex_lit, 1u);
    EXPECT_EQ(stats.sh_lit, 0u);
    const glm::dvec3 vertex(0, 1, 1), n(0, 0, 1);
    glm::dvec3 want(0.0);
    for (const runtime::Light& l : scene.lights) {
        const auto [lux, dir] = Reaching(l, vertex);
        want += lux / kPi * std::max(glm::dot(n, dir), 0.0);  // _LightColor = lux / pi
    }
    EXPECT_GT(want.r, 0.2);
    ExpectClose(CentrePixel(image), want, 1e-3);

    // A fifth point light does not fit the four vertex slots: it goes to the SH.
    scene.lights.push_back(Punctual(T::kPoint, {1, 1, 2}, {1, 1, 1}, 5));
    Render(scene, Settings(runtime::LightMode::kVertex), &stats);
    EXPECT_EQ(stats.vertex_lit, 1u);
    EXPECT_EQ(stats.sh_lit, 1u);
}

// Unity's ranking in the automatic mode: the brightest --pixel-lights per pixel, up to four
// point lights per vertex, the rest in SH; every mode renders 1, 8 and 64 point lights with no
// validation message (the fixture fails on any) and finite pixels.
TEST_F(RuntimeTest, OneEightAndSixtyFourPointLightsInEveryMode) {
    for (int n : {1, 8, 64}) {
        runtime::Scene scene = FacingSphere("multi_light.material");
        for (int i = 0; i < n; ++i) {
            const float a = float(i) * 2.39996f;  // golden angle: spread around the sphere
            const glm::vec3 p(std::cos(a) * 3.0f, 1.0f + std::sin(float(i)) * 2.0f,
                              std::sin(a) * 3.0f);
            scene.lights.push_back(
                Punctual(runtime::LightType::kPoint, p, {1, 1, 1}, 2.0f + float(i % 5)));
        }
        for (runtime::LightMode mode : {runtime::LightMode::kAuto, runtime::LightMode::kPixel,
                                        runtime::LightMode::kVertex, runtime::LightMode::kSH}) {
            runtime::FrameSettings settings = Settings(mode);
            settings.width = 48;
            settings.height = 32;
            settings.pixel_lights = 2;
            runtime::FrameStats stats;
            const runtime::LinearImage image = Render(scene, settings, &stats);
            const uint32_t lights = uint32_t(n);
            switch (mode) {
                case runtime::LightMode::kAuto:
                    EXPECT_EQ(stats.add_passes, std::min(lights, 2u)) << n;
                    EXPECT_EQ(stats.vertex_lit, lights > 2 ? 1u : 0u) << n;
                    EXPECT_EQ(stats.sh_lit, lights > 6 ? 1u : 0u) << n;
                    break;
                case runtime::LightMode::kPixel:
                    EXPECT_EQ(stats.add_passes, lights) << n;
                    EXPECT_EQ(stats.vertex_lit + stats.sh_lit, 0u) << n;
                    break;
                case runtime::LightMode::kVertex:
                    EXPECT_EQ(stats.add_passes, 0u) << n;
                    EXPECT_EQ(stats.vertex_lit, 1u) << n;
                    EXPECT_EQ(stats.sh_lit, lights > 4 ? 1u : 0u) << n;
                    break;
                case runtime::LightMode::kSH:
                    EXPECT_EQ(stats.add_passes + stats.vertex_lit, 0u) << n;
                    EXPECT_EQ(stats.sh_lit, 1u) << n;
                    break;
            }
            for (float v : image.rgba) {
                ASSERT_TRUE(std::isfinite(v)) << n << " lights, mode " << int(mode);
            }
        }
    }
}

// Unity's gradient ambient: the probe is the trilight's projection (the reference's closed form,
// itself checked against numerical integration), so the sphere's centre (normal +z, on the
// horizon) shows ShadeSH9 of it within 1e-3 relative, and the upper half sees the sky.
TEST_F(RuntimeTest, TrilightAmbientIsTheGradientsProjection) {
    runtime::Scene scene = FacingSphere("light_modes.material");
    scene.ambient_mode = runtime::AmbientMode::kTrilight;
    scene.ambient = glm::vec3(0.4f, 0.5f, 0.9f);  // sky
    scene.ambient_equator = glm::vec3(0.2f, 0.2f, 0.15f);
    scene.ambient_ground = glm::vec3(0.05f, 0.03f, 0.02f);
    const runtime::LinearImage image = Render(scene, Settings(runtime::LightMode::kAuto));
    reference::SH9 sh;
    reference::AddTrilight(sh, glm::dvec3(scene.ambient), glm::dvec3(scene.ambient_equator),
                           glm::dvec3(scene.ambient_ground));
    ExpectClose(CentrePixel(image), reference::AmbientFromSH(sh, {0, 0, 1}), 1e-3);
    // A quarter of the way up and down the image, both on the sphere: sky above, ground below.
    auto at = [&](uint32_t y) {
        return double(image.rgba[(size_t(y) * image.width + image.width / 2) * 4 + 2]);
    };
    EXPECT_GT(at(image.height / 2 - image.height / 8), at(image.height / 2 + image.height / 8));
}

// Unity's per-light Render Mode: important lights are per pixel whatever the pixel-light count,
// not-important ones never (per vertex, or SH when not a point light), auto ones are ranked into
// what is left of the count. The fixed light modes ignore it.
TEST(LightRanking, ImportantAndNotImportantLightsAsUnityRanksThem) {
    using T = runtime::LightType;
    using I = runtime::LightImportance;
    std::vector<runtime::Light> lights = {
        Punctual(T::kPoint, {0, 1, 3}, {1, 1, 1}, 100),  // brightest
        Punctual(T::kPoint, {0, 1, 3}, {1, 1, 1}, 50),
        Punctual(T::kPoint, {0, 1, 3}, {1, 1, 1}, 10),  // dimmest
        Punctual(T::kSpot, {0, 1, 3}, {1, 1, 1}, 80)};
    lights[0].importance = I::kNotImportant;
    lights[2].importance = I::kImportant;
    lights[3].importance = I::kNotImportant;
    const glm::vec3 center(0, 1, 0);
    const runtime::ObjectLights one = runtime::LightsFor(lights, nullptr, center, 1.0f, 1);
    EXPECT_EQ(one.pixel, (std::vector<const runtime::Light*>{&lights[2]}));
    EXPECT_EQ(one.vertex, (std::vector<const runtime::Light*>{&lights[0], &lights[1]}));
    EXPECT_EQ(one.sh, (std::vector<const runtime::Light*>{&lights[3]}));  // a spot: no vertex
    const runtime::ObjectLights two = runtime::LightsFor(lights, nullptr, center, 1.0f, 2);
    EXPECT_EQ(two.pixel, (std::vector<const runtime::Light*>{&lights[2], &lights[1]}));
    const runtime::ObjectLights none = runtime::LightsFor(lights, nullptr, center, 1.0f, 0);
    EXPECT_EQ(none.pixel, (std::vector<const runtime::Light*>{&lights[2]}));  // still important
    const runtime::ObjectLights pixel =
        runtime::LightsFor(lights, nullptr, center, 1.0f, 0, runtime::LightMode::kPixel);
    EXPECT_EQ(pixel.pixel.size(), 4u);  // the fixed modes ignore the Render Mode
    // A not-important directional light is never the main light.
    std::vector<runtime::Light> suns(2);
    suns[0].type = suns[1].type = T::kDirectional;
    suns[0].intensity = 10;
    suns[0].importance = I::kNotImportant;
    EXPECT_EQ(runtime::MainLight(suns), &suns[1]);
}

TEST(LightRanking, TheSidecarSetsRenderModesByLightName) {
    const std::string dir = ::testing::TempDir();
    const std::string path = dir + "/lights.kiln.json";
    std::ofstream(path) << "{\"kiln_materials\": 1,\n \"lights\": {\"Lamp\": \"important\", "
                           "\"Sun\": \"not-important\"}}";
    runtime::Scene scene;
    scene.lights.resize(3);
    scene.lights[0].name = "Lamp";
    scene.lights[1].name = "Sun";
    scene.lights[2].name = "Fill";
    ASSERT_TRUE(Ok(runtime::LoadMaterialSidecar(path, scene)));
    EXPECT_EQ(scene.lights[0].importance, runtime::LightImportance::kImportant);
    EXPECT_EQ(scene.lights[1].importance, runtime::LightImportance::kNotImportant);
    EXPECT_EQ(scene.lights[2].importance, runtime::LightImportance::kAuto);
    std::ofstream(path) << "{\"lights\": {\"Lmap\": \"important\"}}";
    const Status typo = runtime::LoadMaterialSidecar(path, scene);
    ASSERT_FALSE(typo.ok());
    EXPECT_EQ(typo.error().message,
              path + ":1:21: the scene has no light named 'Lmap'; did you mean 'Lamp'?");
    std::ofstream(path) << "{\"lights\": {\"Lamp\": \"always\"}}";
    const Status bad = runtime::LoadMaterialSidecar(path, scene);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message,
              path + ":1:21: light 'Lamp' must be auto, important or not-important");
}

}  // namespace
}  // namespace kiln::test
