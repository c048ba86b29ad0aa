// Shadows (FrameSettings::shadows, kiln render --shadows) on both paths: a sphere over a floor,
// seen straight down by an orthographic camera so that each pixel is a known floor point, lit by
// one light of each type. A CPU reference casts a ray from each floor point to the light: where it
// passes through the sphere well inside (or well outside) its radius, the render must show the
// floor unlit (or lit) by that light. The lit fraction is measured as (shadowed - ambient only) /
// (unshadowed - ambient only), so the BRDF and the light's falloff cancel. The validation layer
// reports nothing (the fixture fails any test on a message).
#include "runtime/runtime_fixture.h"

#include <glm/gtc/matrix_transform.hpp>

#include "kiln/pack/engine_names.h"

namespace kiln::test {
namespace {

constexpr uint32_t kSize = 128;  // pixels a side; the floor is 6 m, 4.7 cm a pixel
constexpr float kHalf = 3.0f;    // the floor's half extent (SphereOnFloor)

// The sphere (radius 1, centre (0, 1, 0)) over its floor in Kiln/StandardMetallic (the glTF
// default material mapped onto it: white, rough, dielectric), an orthographic camera straight
// down with -z at the top of the image, no ambient besides a dim flat one.
runtime::Scene ShadowScene(const runtime::Light& light) {
    runtime::Scene scene = SphereOnFloor("");
    scene.material_files.clear();
    scene.materials[0].metallic = 0;
    scene.materials[0].roughness = 1;
    runtime::Camera top;
    top.name = "top";
    top.perspective = false;
    top.xmag = top.ymag = kHalf;
    top.aspect = 1;
    top.znear = 1;
    top.zfar = 20;
    top.world =
        glm::inverse(glm::lookAtRH(glm::vec3(0, 10, 0), glm::vec3(0, 0, 0), glm::vec3(0, 0, -1)));
    scene.cameras = {top};
    scene.ambient = glm::vec3(0.02f);
    if (light.intensity > 0) {
        scene.lights = {light};
    }
    return scene;
}

// The floor point at the centre of pixel (x, y).
glm::vec3 FloorPoint(uint32_t x, uint32_t y) {
    return glm::vec3((float(x) + 0.5f) / kSize * 2 * kHalf - kHalf, 0,
                     (float(y) + 0.5f) / kSize * 2 * kHalf - kHalf);
}

// The closest the segment from `p` towards the light comes to the sphere's centre (infinity when
// the light is not above the sphere's side of the floor).
float ClosestApproach(const runtime::Light& light, const glm::vec3& p) {
    const glm::vec3 center(0, 1, 0);
    glm::vec3 dir;
    float length = 1e30f;
    if (light.type == runtime::LightType::kDirectional) {
        dir = -glm::normalize(light.direction);
    } else {
        dir = light.position - p;
        length = glm::length(dir);
        dir /= length;
    }
    const float t = std::clamp(glm::dot(center - p, dir), 0.0f, length);
    return glm::length(p + dir * t - center);
}

double Luminance(const runtime::LinearImage& image, uint32_t x, uint32_t y) {
    const float* c = &image.rgba[(size_t(y) * image.width + x) * 4];
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

struct ShadowCheck {
    size_t lit = 0, shadowed = 0;            // pixels the reference classifies
    size_t lit_wrong = 0, shadow_wrong = 0;  // ... that the render gets wrong
    size_t partial = 0;                      // lit fraction strictly between 0.1 and 0.9
};

class ShadowTest : public RuntimeTest {
  protected:
    // Renders the scene lit by `light` with shadows `mode`, without shadows and without the
    // light, along `path`, and checks every floor pixel outside the sphere's own footprint.
    ShadowCheck Check(const runtime::Light& light,
                      runtime::Shadows mode,
                      runtime::FrameStats* stats_out = nullptr,
                      const runtime::RenderPath& path = runtime::RenderPath::kForward) {
        runtime::FrameSettings settings;
        settings.path = path;
        settings.width = settings.height = kSize;
        settings.default_light = false;
        runtime::FrameStats stats;
        settings.shadows = mode;
        const runtime::LinearImage shadowed = Render(ShadowScene(light), settings, &stats);
        EXPECT_TRUE(stats.warnings.all().empty())
            << (stats.warnings.all().empty() ? "" : stats.warnings.all()[0].message);
        EXPECT_GT(stats.shadow_draws, 0u);
        if (stats_out) {
            *stats_out = stats;
        }
        settings.shadows = runtime::Shadows::kOff;
        const runtime::LinearImage unshadowed = Render(ShadowScene(light), settings);
        runtime::Light none = light;
        none.intensity = 0;
        const runtime::LinearImage ambient = Render(ShadowScene(none), settings);
        KeepImage(shadowed);  // KILN_TEST_IMAGES=<folder>: the shadowed render kept
        ShadowCheck out;
        for (uint32_t y = 0; y < kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                const glm::vec3 p = FloorPoint(x, y);
                if (p.x * p.x + p.z * p.z < 1.1f * 1.1f) {
                    continue;  // under the sphere: the camera sees the sphere
                }
                const double direct = Luminance(unshadowed, x, y) - Luminance(ambient, x, y);
                if (direct < 0.02) {
                    continue;  // outside the light's reach (a spot's cone)
                }
                const double fraction =
                    (Luminance(shadowed, x, y) - Luminance(ambient, x, y)) / direct;
                out.partial += fraction > 0.1 && fraction < 0.9 ? 1 : 0;
                // Margins: the filters and biases blur the edge by a few map texels.
                const float d = ClosestApproach(light, p);
                if (d < 0.85f) {
                    ++out.shadowed;
                    out.shadow_wrong += fraction > 0.1 ? 1 : 0;
                } else if (d > 1.15f) {
                    ++out.lit;
                    out.lit_wrong += fraction < 0.9 ? 1 : 0;
                }
            }
        }
        std::printf(
            "%s, %s, %s shadows: lit %zu (%zu wrong), shadowed %zu (%zu wrong), partly lit %zu\n",
            path.name.c_str(), light.name.c_str(),
            mode == runtime::Shadows::kSoft ? "soft" : "hard", out.lit, out.lit_wrong, out.shadowed,
            out.shadow_wrong, out.partial);
        return out;
    }
};

void ExpectMatchesReference(const ShadowCheck& c) {
    // A shadow of a sphere a metre across covers hundreds of pixels at this size.
    EXPECT_GT(c.shadowed, 300u);
    EXPECT_GT(c.lit, 1000u);
    // Every classified pixel agrees: the margins above absorb the filters.
    EXPECT_EQ(c.shadow_wrong, 0u) << "of " << c.shadowed << " shadowed pixels";
    EXPECT_EQ(c.lit_wrong, 0u) << "of " << c.lit << " lit pixels";
}

runtime::Light Directional() {
    runtime::Light l;
    l.name = "sun";
    l.type = runtime::LightType::kDirectional;
    l.direction = glm::normalize(glm::vec3(-0.6f, -1.0f, -0.3f));
    l.intensity = 3;
    return l;
}

runtime::Light Spot() {
    runtime::Light l;
    l.name = "spot";
    l.type = runtime::LightType::kSpot;
    l.position = glm::vec3(1.4f, 3.6f, 1.0f);
    l.direction = glm::normalize(glm::vec3(-0.9f, 0, -0.6f) - l.position);
    l.outer_cone = 0.75f;
    l.inner_cone = 0.6f;
    l.intensity = 40;
    return l;
}

runtime::Light Point() {
    runtime::Light l;
    l.name = "bulb";
    l.type = runtime::LightType::kPoint;
    l.position = glm::vec3(-1.2f, 3.2f, 0.9f);
    l.intensity = 40;
    return l;
}

TEST_F(ShadowTest, DirectionalLightShadowIsWhereTheReferenceSays) {
    runtime::FrameStats stats;
    ExpectMatchesReference(Check(Directional(), runtime::Shadows::kHard, &stats));
    // The map, the camera's depth (2 casters each) and the collector.
    EXPECT_EQ(stats.shadow_draws, 5u);
}

TEST_F(ShadowTest, SpotLightShadowIsWhereTheReferenceSays) {
    ExpectMatchesReference(Check(Spot(), runtime::Shadows::kHard));
}

TEST_F(ShadowTest, PointLightShadowIsWhereTheReferenceSays) {
    runtime::FrameStats stats;
    ExpectMatchesReference(Check(Point(), runtime::Shadows::kHard, &stats));
    EXPECT_EQ(stats.shadow_draws, 12u);  // six cube faces, two casters each
}

// SHADOWS_SOFT widens the penumbra: more pixels partly lit than with hard shadows, for each light
// type, and the reference still holds outside the margins.
TEST_F(ShadowTest, SoftShadowsHaveAWiderPenumbra) {
    for (const runtime::Light& light : {Directional(), Spot(), Point()}) {
        SCOPED_TRACE(light.name);
        const ShadowCheck hard = Check(light, runtime::Shadows::kHard);
        const ShadowCheck soft = Check(light, runtime::Shadows::kSoft);
        ExpectMatchesReference(soft);
        EXPECT_GT(soft.partial, hard.partial + hard.partial / 2) << light.name;
    }
}

// Without shadows the floor under the sphere is lit: the check above fails when shadows are
// dropped.
TEST_F(ShadowTest, WithoutShadowsTheReferenceFails) {
    runtime::FrameSettings settings;
    settings.width = settings.height = kSize;
    settings.default_light = false;
    const runtime::Light light = Directional();
    const runtime::LinearImage off = Render(ShadowScene(light), settings);
    settings.shadows = runtime::Shadows::kHard;
    const runtime::LinearImage on = Render(ShadowScene(light), settings);
    size_t darker = 0, shadowed = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const glm::vec3 p = FloorPoint(x, y);
            if (p.x * p.x + p.z * p.z > 1.1f * 1.1f && ClosestApproach(light, p) < 0.85f) {
                ++shadowed;
                darker += Luminance(on, x, y) < 0.5 * Luminance(off, x, y) ? 1 : 0;
            }
        }
    }
    EXPECT_GT(shadowed, 300u);
    EXPECT_EQ(darker, shadowed);
}

// The deferred path's light pass receives the same shadows (as Unity's: the screen-space shadows
// for a directional light, the map for a spot light, the cube for a point light): both objects
// go through the G-buffer (Kiln/StandardMetallic has a Deferred pass), so every floor pixel the
// check classifies is shaded by the light pass, and the reference holds there, hard and soft.
TEST_F(ShadowTest, DeferredPathShadowsAreWhereTheReferenceSays) {
    for (const runtime::Light& light : {Directional(), Spot(), Point()}) {
        SCOPED_TRACE(light.name);
        for (runtime::Shadows mode : {runtime::Shadows::kHard, runtime::Shadows::kSoft}) {
            runtime::FrameStats stats;
            ExpectMatchesReference(Check(light, mode, &stats, runtime::RenderPath::kDeferred));
            EXPECT_EQ(stats.gbuffer_draws, 2u);
            EXPECT_EQ(stats.light_passes, 1u);
            EXPECT_EQ(stats.base_passes + stats.add_passes, 0u);  // nothing drawn forward
            // The same shadow passes as the forward path's (the tests above).
            EXPECT_EQ(stats.shadow_draws, light.type == runtime::LightType::kPoint  ? 12u
                                          : light.type == runtime::LightType::kSpot ? 2u
                                                                                    : 5u);
        }
    }
}

TEST_F(ShadowTest, NoShadowCasterPassIsAWarning) {
    // Kiln/Unlit has no ShadowCaster pass (as Unity's unlit shaders).
    runtime::Scene scene =
        SphereOnFloor(std::string(KILN_SOURCE_DIR) + "/materials/Unlit.material");
    scene.lights = {Directional()};
    runtime::FrameSettings settings;
    settings.width = settings.height = 32;
    settings.shadows = runtime::Shadows::kHard;
    runtime::FrameStats stats;
    Render(scene, settings, &stats);
    EXPECT_EQ(stats.shadow_draws, 0u);
    ASSERT_FALSE(stats.warnings.all().empty());
    EXPECT_NE(stats.warnings.all()[0].message.find("ShadowCaster pass"), std::string::npos);
}

}  // namespace
}  // namespace kiln::test
