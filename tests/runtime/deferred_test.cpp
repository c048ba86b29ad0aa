// The deferred path (docs/runtime.md, "Deferred path"): the objects' Deferred passes write the
// G-buffer, one light pass per light shades it, and the rest is drawn forward afterwards. For
// opaque scenes it agrees with the forward path drawing every light per pixel: both evaluate the
// same BRDF and attenuation, and differ only by what the G-buffer quantizes (8-bit sRGB diffuse
// and specular colours, the normal's format and encoding) and the light pass's reconstruction of
// the world position from depth.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <vector>

#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

// How far two renders of the same frame are apart as a person sees them: R, G and B after the
// sRGB display encoding (clamped to [0, 1], as the PNG is written), over the pixels either covers
// (alpha > 0). Comparing displayed values keeps an HDR highlight of 10 from dominating with an
// error its 8-bit display value does not show.
struct Difference {
    double mean = 0;              // mean absolute difference of the displayed R, G, B (0..1)
    double p99 = 0;               // 99th percentile of the per-pixel largest channel difference
    double max = 0;               // largest channel difference
    size_t covered = 0;           // pixels covered in either
    size_t coverage_differs = 0;  // pixels covered in one image only
};

Difference Compare(const runtime::LinearImage& a, const runtime::LinearImage& b) {
    Difference d;
    EXPECT_EQ(a.rgba.size(), b.rgba.size());
    std::vector<double> worst;
    double sum = 0;
    for (size_t i = 0; i + 3 < std::min(a.rgba.size(), b.rgba.size()); i += 4) {
        const bool ca = a.rgba[i + 3] > 0, cb = b.rgba[i + 3] > 0;
        if (!ca && !cb) {
            continue;
        }
        ++d.covered;
        d.coverage_differs += ca != cb;
        double w = 0;
        for (size_t c = 0; c < 3; ++c) {
            const double diff = std::abs(LinearToSrgb(a.rgba[i + c]) - LinearToSrgb(b.rgba[i + c]));
            sum += diff;
            w = std::max(w, diff);
        }
        worst.push_back(w);
        d.max = std::max(d.max, w);
    }
    if (d.covered > 0) {
        d.mean = sum / double(3 * d.covered);
        std::sort(worst.begin(), worst.end());
        d.p99 = worst[std::min(worst.size() - 1, worst.size() * 99 / 100)];
    }
    return d;
}

std::ostream& operator<<(std::ostream& os, const Difference& d) {
    return os << "displayed difference: mean " << d.mean * 255 << "/255, p99 " << d.p99 * 255
              << "/255, max " << d.max * 255 << "/255 over " << d.covered << " pixels covered, "
              << d.coverage_differs << " covered in one image only";
}

runtime::Light MakeLight(runtime::LightType type,
                         glm::vec3 position,
                         glm::vec3 color,
                         float intensity,
                         float range = 0) {
    runtime::Light l;
    l.name = "light " + std::to_string(int(position.x * 10)) + "," +
             std::to_string(int(position.z * 10));
    l.type = type;
    l.position = position;
    l.color = color;
    l.intensity = intensity;
    l.range = range;
    l.direction = glm::normalize(glm::vec3(0, 0.5f, 0) - position);
    l.inner_cone = 0.3f;
    l.outer_cone = 0.7f;
    return l;
}

// A sphere on a floor lit by a sun, point lights with and without a range, and a spot.
runtime::Scene LitScene(const std::string& material) {
    runtime::Scene scene = SphereOnFloor(material);
    using T = runtime::LightType;
    runtime::Light sun = MakeLight(T::kDirectional, {}, {1, 0.95f, 0.9f}, 2.0f);
    sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    scene.lights = {sun, MakeLight(T::kPoint, {1.5f, 1.2f, 1.5f}, {1, 0.5f, 0.3f}, 6, 4),
                    MakeLight(T::kPoint, {-1.8f, 0.6f, 0.8f}, {0.3f, 0.5f, 1}, 5),
                    MakeLight(T::kSpot, {0.5f, 3.0f, 2.0f}, {1, 1, 1}, 30, 10)};
    return scene;
}

runtime::FrameSettings PathSettings(runtime::RenderPath path) {
    runtime::FrameSettings s;
    s.width = 160;
    s.height = 120;
    s.path = path;
    s.light_mode = runtime::LightMode::kPixel;  // the forward path draws every light per pixel
    s.pixel_lights = 64;
    return s;
}

// Tolerance, from what the G-buffer quantizes. The diffuse and specular colours are stored again
// as 8-bit sRGB: half a step of the stored colour, which is up to a few percent for dark colours
// (a dielectric's specular 0.04 is sRGB code 56), and the light then scales it, so a dark albedo
// under a bright light shows a few display steps. A 10-bit normal (1e-3 rad) moves a smooth
// highlight's edge by about a pixel. So the displayed images may differ by half a step (0.5/255)
// on average and by 4/255 for 99% of the pixels; the largest differences, at highlight edges,
// are not bounded. Coverage must not differ at all.
void ExpectAgree(const Difference& d) {
    EXPECT_GT(d.covered, 0u);
    EXPECT_EQ(d.coverage_differs, 0u) << d;
    EXPECT_LE(d.mean, 0.5 / 255) << d;
    EXPECT_LE(d.p99, 4.0 / 255) << d;
}

TEST_F(RuntimeTest, DeferredAgreesWithForwardOnAnOpaqueScene) {
    for (const std::string& material :
         {RuntimeData("deferred_metallic.material"),
          std::string(KILN_SOURCE_DIR) + "/materials/Deferred.material"}) {
        const runtime::Scene scene = LitScene(material);
        runtime::FrameStats fs, ds;
        const runtime::LinearImage forward =
            Render(scene, PathSettings(runtime::RenderPath::kForward), &fs);
        const runtime::LinearImage deferred =
            Render(scene, PathSettings(runtime::RenderPath::kDeferred), &ds);
        EXPECT_EQ(ds.gbuffer_draws, 2u) << material;  // sphere and floor
        EXPECT_EQ(ds.light_passes, 4u) << material;
        EXPECT_EQ(ds.base_passes + ds.add_passes, 0u) << material;
        EXPECT_EQ(fs.add_passes, 2u * 3u) << material;
        const Difference d = Compare(forward, deferred);
        SCOPED_TRACE(material);
        ExpectAgree(d);
    }
}

// With soft shadows of every light (a sun, two point lights, a spot), the deferred path's light
// passes sample the same shadow passes as the forward path's passes do: the images agree within
// the G-buffer's tolerance above. The shadows do change the image (a mean of more than two
// display steps), so this is not a comparison of two unshadowed frames.
TEST_F(RuntimeTest, DeferredAgreesWithForwardWithShadows) {
    const runtime::Scene scene = LitScene(RuntimeData("deferred_metallic.material"));
    runtime::FrameSettings forward_settings = PathSettings(runtime::RenderPath::kForward);
    runtime::FrameSettings deferred_settings = PathSettings(runtime::RenderPath::kDeferred);
    forward_settings.shadows = deferred_settings.shadows = runtime::Shadows::kSoft;
    runtime::FrameStats fs, ds;
    const runtime::LinearImage forward = Render(scene, forward_settings, &fs);
    const runtime::LinearImage deferred = Render(scene, deferred_settings, &ds);
    EXPECT_GT(ds.shadow_draws, 0u);
    EXPECT_EQ(ds.shadow_draws, fs.shadow_draws);  // the same shadow passes
    EXPECT_EQ(ds.light_passes, 4u);
    EXPECT_TRUE(ds.warnings.all().empty());
    const Difference d = Compare(forward, deferred);
    std::cout << "forward vs deferred, soft shadows: " << d << "\n";
    ExpectAgree(d);
    const Difference shadowed =
        Compare(deferred, Render(scene, PathSettings(runtime::RenderPath::kDeferred)));
    std::cout << "deferred with vs without shadows: " << shadowed << "\n";
    EXPECT_GT(shadowed.mean, 2.0 / 255) << shadowed;
}

// The G-buffer normal formats and encodings, whose error the setting exists to measure: Unity's
// RGB10A2 is within the tolerance, more bits give less error (RGBA16F <= RGB10A2 <= RGBA8, mean
// displayed difference), and the octahedral encoding, which keeps two channels, stays within one
// display step on average in every format.
TEST_F(RuntimeTest, GBufferNormalFormatsAndTheOctahedralEncoding) {
    const runtime::Scene scene = LitScene(RuntimeData("deferred_metallic.material"));
    const runtime::LinearImage forward = Render(scene, PathSettings(runtime::RenderPath::kForward));
    using N = runtime::GBufferSettings::Normals;
    std::map<N, double> xyz;
    for (N normals : {N::kRGB10A2, N::kRGBA8, N::kRGBA16F}) {
        for (bool octahedral : {false, true}) {
            runtime::FrameSettings settings = PathSettings(runtime::RenderPath::kDeferred);
            settings.gbuffer.normals = normals;
            settings.gbuffer.octahedral = octahedral;
            const Difference d = Compare(forward, Render(scene, settings));
            SCOPED_TRACE("normals " + std::to_string(int(normals)) +
                         (octahedral ? ", octahedral" : ", xyz"));
            EXPECT_EQ(d.coverage_differs, 0u) << d;
            if (octahedral) {
                EXPECT_LE(d.mean, 1.0 / 255) << d;
            } else {
                xyz[normals] = d.mean;
            }
            if (normals == N::kRGB10A2 && !octahedral) {
                ExpectAgree(d);
            }
        }
    }
    EXPECT_LE(xyz[N::kRGBA16F], xyz[N::kRGB10A2]);
    EXPECT_LE(xyz[N::kRGB10A2], xyz[N::kRGBA8]);
}

// Objects whose shader has no Deferred pass are drawn forward after the light passes, exactly as
// the forward path draws them.
TEST_F(RuntimeTest, DeferredDrawsObjectsWithoutADeferredPassForward) {
    const runtime::Scene scene = LitScene(RuntimeData("multi_light.material"));
    runtime::FrameStats fs, ds;
    const runtime::LinearImage forward =
        Render(scene, PathSettings(runtime::RenderPath::kForward), &fs);
    const runtime::LinearImage deferred =
        Render(scene, PathSettings(runtime::RenderPath::kDeferred), &ds);
    EXPECT_EQ(ds.gbuffer_draws, 0u);
    EXPECT_EQ(ds.light_passes, 0u);
    EXPECT_EQ(ds.base_passes, fs.base_passes);
    EXPECT_EQ(ds.add_passes, fs.add_passes);
    EXPECT_EQ(Compare(forward, deferred).max, 0.0);
}

// A shader in a transparent queue (its SubShader's "Queue" tag above 2500) is drawn forward by
// the deferred path though it has a Deferred pass, as Unity draws it, after the opaque objects.
TEST(DeferredPath, ATransparentQueueShaderIsDrawnForward) {
    PinVulkanLibraries();
    runtime::RendererOptions options;
    options.validation = true;
    runtime::Renderer renderer;
    ASSERT_TRUE(CreateInto(options, renderer));
    for (const char* pack : {KILN_MATERIALS_PACK, KILN_PROBE_PACK}) {
        ASSERT_TRUE(Ok(renderer.AddPack(pack)));
    }
    runtime::ColorPipeline color;
    ASSERT_TRUE(CreateColorInto({}, color));
    runtime::Scene scene = SphereOnFloor(RuntimeData("transparent_queue.material"));
    runtime::FrameSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.path = runtime::RenderPath::kDeferred;
    runtime::LinearImage image;
    runtime::FrameStats stats;
    ASSERT_TRUE(Ok(renderer.Render(scene, settings, color, image, stats)));
    EXPECT_EQ(stats.gbuffer_draws, 0u);
    EXPECT_GT(stats.base_passes, 0u);
    EXPECT_TRUE(renderer.ValidationMessages().empty());
}

// The lecture's scaling argument: the deferred path's cost grows with lights, not with lights x
// objects. 1, 8 and 64 point lights on both paths, with no validation message (the fixture
// fails on any), agreeing within the tolerance; a ranged light behind the camera gets no pass.
TEST_F(RuntimeTest, OneEightAndSixtyFourPointLightsOnBothPaths) {
    for (int n : {1, 8, 64}) {
        runtime::Scene scene = SphereOnFloor(RuntimeData("deferred_metallic.material"));
        for (int i = 0; i < n; ++i) {
            const float a = float(i) * 2.39996f;  // golden angle
            const glm::vec3 p(std::cos(a) * 2.2f, 0.3f + float(i % 7) * 0.4f, std::sin(a) * 2.2f);
            scene.lights.push_back(
                MakeLight(runtime::LightType::kPoint, p, {1, 0.8f + 0.03f * float(i % 5), 0.7f},
                          (2.0f + float(i % 5)) * 8.0f / float(n), i % 2 ? 3.5f : 0.0f));
        }
        runtime::FrameStats fs, ds;
        const runtime::LinearImage forward =
            Render(scene, PathSettings(runtime::RenderPath::kForward), &fs);
        const runtime::LinearImage deferred =
            Render(scene, PathSettings(runtime::RenderPath::kDeferred), &ds);
        EXPECT_EQ(ds.light_passes, uint32_t(n)) << n;
        EXPECT_EQ(ds.gbuffer_draws, 2u) << n;
        SCOPED_TRACE(std::to_string(n) + " lights");
        ExpectAgree(Compare(forward, deferred));
        for (float v : deferred.rgba) {
            ASSERT_TRUE(std::isfinite(v));
        }
        // Behind the camera (at (0.5, 2.8, 5) looking at the sphere), out of reach of the view.
        scene.lights.push_back(
            MakeLight(runtime::LightType::kPoint, {0.8f, 3.5f, 9.0f}, {1, 1, 1}, 50, 2.0f));
        Render(scene, PathSettings(runtime::RenderPath::kDeferred), &ds);
        EXPECT_EQ(ds.light_passes, uint32_t(n)) << n;
    }
}

// The light pass is a shader like any other, looked up by name in the loaded packs: without it,
// a deferred frame says which shader it needs and where it comes from.
TEST(DeferredPath, NamesTheLightPassShaderWhenNoPackHasIt) {
    PinVulkanLibraries();
    runtime::RendererOptions options;
    options.validation = true;
    runtime::Renderer renderer;
    ASSERT_TRUE(CreateInto(options, renderer));
    ASSERT_TRUE(Ok(renderer.AddPack(KILN_STRIPPED_PACK)));  // StandardMetallic only
    runtime::ColorPipeline color;
    ASSERT_TRUE(CreateColorInto({}, color));
    runtime::Scene scene = LitScene("");
    scene.material_files.clear();  // the glTF default material: Kiln/StandardMetallic
    runtime::FrameSettings settings = PathSettings(runtime::RenderPath::kDeferred);
    runtime::LinearImage image;
    runtime::FrameStats stats;
    const Status e = renderer.Render(scene, settings, color, image, stats);
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().message.find("'Hidden/Internal-DeferredShading'"), std::string::npos)
        << e.error().message;
    EXPECT_NE(e.error().message.find("materials/internal/DeferredShading.shader"),
              std::string::npos)
        << e.error().message;
    EXPECT_TRUE(renderer.ValidationMessages().empty());
}

// The light draws' bounds. A replacement light pass (tests/runtime/data/CountingLightPass.shader,
// loaded before the shipped pack, as Unity lets a project replace Internal-DeferredShading) adds
// 1/8 of red per light to every pixel a light's draws shade. With black surfaces and no ambient,
// the red channel counts the lights that shaded each pixel: the sun every pixel with geometry and
// never the background; a ranged point light every pixel within its range (the bounds are not too
// tight) and none well outside it (scissor, stencil mask and far depth do cut); a ranged light
// behind the camera gets no draw at all.
TEST(DeferredPath, LightDrawsShadeWhatTheLightReachesAndNotMuchMore) {
    PinVulkanLibraries();
    runtime::RendererOptions options;
    options.validation = true;
    options.float32_target = true;
    runtime::Renderer renderer;
    ASSERT_TRUE(CreateInto(options, renderer));
    for (const char* pack : {KILN_LIGHT_PASS_PACK, KILN_MATERIALS_PACK, KILN_PROBE_PACK}) {
        ASSERT_TRUE(Ok(renderer.AddPack(pack)));
    }
    runtime::ColorPipeline color;
    ASSERT_TRUE(CreateColorInto({}, color));
    runtime::Scene scene = SphereOnFloor(RuntimeData("deferred_black.material"));
    scene.ambient = glm::vec3(0.0f);
    using T = runtime::LightType;
    runtime::Light sun = MakeLight(T::kDirectional, {}, {1, 1, 1}, 1);
    sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, -0.3f));
    const glm::vec3 lamp(1.4f, 0.4f, 1.2f);
    const float range = 0.6f;
    scene.lights = {sun, MakeLight(T::kPoint, lamp, {1, 1, 1}, 5, range),
                    MakeLight(T::kPoint, {0.8f, 3.5f, 9.0f}, {1, 1, 1}, 5, 1.0f)};  // behind
    runtime::FrameSettings settings = PathSettings(runtime::RenderPath::kDeferred);
    runtime::LinearImage image, positions;
    runtime::FrameStats stats;
    ASSERT_TRUE(Ok(renderer.Render(scene, settings, color, image, stats)));
    EXPECT_EQ(stats.light_passes, 2u);  // the sun and the lamp; the light behind gets none
    scene.material_files["m"] = RuntimeData("probe_position.material");
    settings.path = runtime::RenderPath::kForward;
    ASSERT_TRUE(Ok(renderer.Render(scene, settings, color, positions, stats)));
    size_t covered = 0, inside = 0, lamp_shaded = 0, far_shaded = 0, background_shaded = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        const long count = std::lround(image.rgba[i] / 0.125f);
        if (positions.rgba[i + 3] <= 0.5f) {
            background_shaded += count != 0;
            continue;
        }
        ++covered;
        EXPECT_GE(count, 1) << "pixel " << i / 4 << " not lit by the sun";
        const glm::vec3 p(positions.rgba[i], positions.rgba[i + 1], positions.rgba[i + 2]);
        const float d = glm::length(p - lamp);
        lamp_shaded += count == 2;
        if (d < 0.98f * range) {
            ++inside;
            EXPECT_EQ(count, 2) << "pixel " << i / 4 << " within the lamp's range, not shaded";
        } else if (d > 3.5f * range) {
            far_shaded += count == 2;
        }
    }
    EXPECT_EQ(background_shaded, 0u);
    EXPECT_GT(inside, 100u);
    EXPECT_EQ(far_shaded, 0u);
    // The lamp's draws cover a small part of the view, a few times what its sphere covers
    // (measured on lavapipe at 160x120: 1,337 pixels shaded, 371 within range, 11,177 covered).
    EXPECT_LT(lamp_shaded, covered / 4) << lamp_shaded << " of " << covered;
    EXPECT_LT(lamp_shaded, 6 * inside) << lamp_shaded << " shaded, " << inside << " in range";
    EXPECT_TRUE(renderer.ValidationMessages().empty());
}

// The Done-when scenes: the demo scene (ten shipped materials, two of them with a Deferred pass,
// the glTF floor a third) and LightsPunctualLamp.
class DeferredSceneTest : public RuntimeTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(DeferredSceneTest, AgreesWithForward) {
    const std::string name = GetParam();
    const std::string path =
        name == "demo"
            ? std::string(KILN_SOURCE_DIR) + "/scenes/demo/demo.gltf"
            : std::string(KILN_SHARED_DIR) + "/gltf-samples/" + name + "/glTF/" + name + ".gltf";
    if (!fs::exists(path)) {
        GTEST_SKIP() << path << " is absent (../shared not checked out): sample skipped";
    }
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(LoadInto(path, scene, warnings));
    runtime::FrameSettings forward_settings = PathSettings(runtime::RenderPath::kForward);
    forward_settings.width = 320;
    forward_settings.height = 240;
    runtime::FrameSettings deferred_settings = forward_settings;
    deferred_settings.path = runtime::RenderPath::kDeferred;
    runtime::FrameStats ds;
    const runtime::LinearImage forward = Render(scene, forward_settings);
    const runtime::LinearImage deferred = Render(scene, deferred_settings, &ds);
    EXPECT_GT(ds.gbuffer_draws, 0u);
    EXPECT_GT(ds.light_passes, 0u);
    ExpectAgree(Compare(forward, deferred));
}

INSTANTIATE_TEST_SUITE_P(Scenes,
                         DeferredSceneTest,
                         ::testing::Values("demo", "LightsPunctualLamp"));

}  // namespace
}  // namespace kiln::test
