// The renderer end to end: the glTF samples and the demo scene render headless with zero
// validation messages, additive passes per light, colour-property decoding, missing variants,
// damaged packs, and the persisted pipeline cache.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "runtime/runtime_fixture.h"
#include "vk/pipeline_cache.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

size_t Covered(const runtime::LinearImage& image) {
    size_t n = 0;
    for (size_t i = 3; i < image.rgba.size(); i += 4) {
        n += image.rgba[i] > 0.0f;
    }
    return n;
}

class GltfSampleTest : public RuntimeTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(GltfSampleTest, RendersHeadlessWithoutValidationMessages) {
    const std::string path = std::string(KILN_SHARED_DIR) + "/gltf-samples/" + GetParam() +
                             "/glTF/" + GetParam() + ".gltf";
    if (!fs::exists(path)) {
        GTEST_SKIP() << path << " is absent (../shared not checked out): sample skipped";
    }
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(LoadInto(path, scene, warnings));
    runtime::FrameSettings settings;
    settings.width = 256;
    settings.height = 192;
    runtime::FrameStats stats;
    const runtime::LinearImage image = Render(scene, settings, &stats);
    EXPECT_GT(stats.objects, 0u);
    EXPECT_GT(Covered(image), image.rgba.size() / 4 / 20) << "less than 5% of the image drawn";
    for (float v : image.rgba) {
        ASSERT_TRUE(std::isfinite(v));
    }
}

INSTANTIATE_TEST_SUITE_P(Samples,
                         GltfSampleTest,
                         ::testing::Values("Box",
                                           "BoxTextured",
                                           "TextureCoordinateTest",
                                           "TextureEncodingTest",
                                           "MetalRoughSpheresNoTextures",
                                           "NormalTangentTest",
                                           "LightsPunctualLamp",
                                           "Cameras",
                                           "BoxVertexColors",
                                           "EmissiveStrengthTest"));

TEST_F(RuntimeTest, DemoSceneShowsEveryShippedMaterial) {
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(LoadInto(std::string(KILN_SOURCE_DIR) + "/scenes/demo/demo.gltf", scene, warnings));
    EXPECT_EQ(scene.material_files.size(), 10u);
    EXPECT_EQ(scene.lights.size(), 3u);
    runtime::FrameStats stats;
    const runtime::LinearImage image = Render(scene, {}, &stats);
    EXPECT_EQ(stats.objects, 11u);
    EXPECT_EQ(stats.base_passes, 11u);
    // Point and spot light on the four objects whose shaders have a ForwardAdd pass
    // (StandardMetallic, MultiLight, Deferred and the floor's glTF material).
    EXPECT_EQ(stats.add_passes, 8u);
    EXPECT_GT(Covered(image), image.rgba.size() / 4 / 2);
}

// A loaded scene has an id: its buffers and material instances are uploaded and resolved on the
// first frame only, and later frames draw the same pixels from what was kept. A scene without an
// id (built in code) is uploaded again each frame; giving an edited scene a new id does the same.
TEST_F(RuntimeTest, LoadedScenesKeepTheirBuffersAndMaterialsBetweenFrames) {
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(LoadInto(std::string(KILN_SOURCE_DIR) + "/scenes/demo/demo.gltf", scene, warnings));
    ASSERT_NE(scene.id, 0u);
    runtime::FrameSettings settings;
    settings.width = 96;
    settings.height = 64;
    runtime::FrameStats first, second, third;
    const runtime::LinearImage a = Render(scene, settings, &first);
    const runtime::LinearImage b = Render(scene, settings, &second);
    EXPECT_GT(first.buffers_uploaded, 0u);
    EXPECT_EQ(first.materials_resolved,
              10u + 1u);  // ten sidecar materials and the floor's glTF one
    EXPECT_EQ(second.buffers_uploaded, 0u);
    EXPECT_EQ(second.materials_resolved, 0u);
    EXPECT_EQ(second.pipelines_created, 0u);
    EXPECT_EQ(a.rgba, b.rgba);

    scene.id = runtime::NewSceneId();  // "edited": everything again
    Render(scene, settings, &third);
    EXPECT_EQ(third.buffers_uploaded, first.buffers_uploaded);
    EXPECT_EQ(third.materials_resolved, first.materials_resolved);

    runtime::Scene unnamed = SphereOnFloor(RuntimeData("multi_light.material"));
    ASSERT_EQ(unnamed.id, 0u);
    for (int frame = 0; frame < 2; ++frame) {
        runtime::FrameStats stats;
        Render(unnamed, settings, &stats);
        EXPECT_EQ(stats.buffers_uploaded, 4u) << "frame " << frame;  // sphere and floor
        EXPECT_EQ(stats.materials_resolved, 1u) << "frame " << frame;
    }
}

runtime::Scene LoneSphere(const std::string& material, int point_lights) {
    runtime::Scene scene = SphereOnFloor(RuntimeData(material));
    scene.instances.pop_back();  // no floor
    for (int i = 0; i < point_lights; ++i) {
        runtime::Light l;
        l.type = runtime::LightType::kPoint;
        l.intensity = 2.0f + float(i);
        l.position = {std::cos(float(i)) * 2.5f, 1.5f, std::sin(float(i)) * 2.5f};
        scene.lights.push_back(l);
    }
    return scene;
}

TEST_F(RuntimeTest, NPointLightsRunNAdditivePasses) {
    for (int n : {1, 3, 6}) {
        runtime::FrameSettings settings;
        settings.width = 64;
        settings.height = 48;
        settings.pixel_lights = 8;
        runtime::FrameStats stats;
        Render(LoneSphere("multi_light.material", n), settings, &stats);
        EXPECT_EQ(stats.base_passes, 1u);
        EXPECT_EQ(stats.add_passes, uint32_t(n)) << n << " point lights";
        EXPECT_EQ(stats.vertex_lit, 0u);
    }
}

// The image's alpha (and so the EXR's) is coverage: 1 on the opaque sphere however many additive
// passes light it, 0 on the background. It once held 1 + the number of additive passes.
TEST_F(RuntimeTest, AlphaIsCoverageWhateverTheNumberOfAdditivePasses) {
    runtime::FrameSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.pixel_lights = 8;
    runtime::FrameStats stats;
    const runtime::LinearImage image =
        Render(LoneSphere("multi_light.material", 3), settings, &stats);
    ASSERT_EQ(stats.add_passes, 3u);
    size_t covered = 0, background = 0;
    for (size_t i = 3; i < image.rgba.size(); i += 4) {
        const float a = image.rgba[i];
        ASSERT_TRUE(a == 0.0f || a == 1.0f) << "alpha " << a << " at pixel " << i / 4;
        (a == 1.0f ? covered : background)++;
    }
    EXPECT_GT(covered, image.rgba.size() / 4 / 10);
    EXPECT_GT(background, image.rgba.size() / 4 / 10);
}

// An image wider than the device allows (lavapipe: 16384) is downscaled with a warning instead of
// creating an invalid image (which only the validation layer used to notice).
TEST_F(RuntimeTest, ImagesLargerThanTheDeviceLimitAreDownscaledWithAWarning) {
    runtime::Scene scene = SphereOnFloor("");
    scene.material_files.clear();  // the glTF material on Kiln/StandardMetallic
    runtime::SceneImage big;
    big.name = "wide";
    big.width = 17000;
    big.height = 2;
    big.rgba8.assign(size_t(big.width) * big.height * 4, 200);
    scene.images.push_back(big);
    scene.materials[0].base_color_texture.image = 0;
    runtime::FrameSettings settings;
    settings.width = 32;
    settings.height = 24;
    runtime::FrameStats stats;
    Render(scene, settings, &stats);
    std::string all;
    for (const Diagnostic& w : stats.warnings.all())
        all += FormatDiagCode(w.code) + " " + w.message + "\n";
    EXPECT_NE(all.find("K0013 glTF material 'm': image 0 'wide' is 17000x2, larger than the "
                       "device's limit of 16384; "
                       "downscaled to 8500x1"),
              std::string::npos)
        << all;
}

TEST_F(RuntimeTest, ASceneWithNothingToDrawIsAnError) {
    runtime::Scene scene = SphereOnFloor(RuntimeData("lambert.material"));
    scene.instances.clear();
    runtime::LinearImage image;
    runtime::FrameStats stats;
    const Status e = renderer_.Render(scene, {}, color_, image, stats);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, DiagCode::kBadScene);
    EXPECT_EQ(e.error().message, "the scene: nothing to draw (no node of the scene has a mesh)");
}

TEST_F(RuntimeTest, NegativeCameraIndicesOtherThanTheNamedModesAreErrors) {
    runtime::Scene scene = SphereOnFloor(RuntimeData("lambert.material"));
    runtime::FrameSettings settings;
    settings.width = 16;
    settings.height = 12;
    settings.camera = -3;
    runtime::LinearImage image;
    runtime::FrameStats stats;
    Status e = renderer_.Render(scene, settings, color_, image, stats);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, DiagCode::kBadScene);
    settings.camera = runtime::FrameSettings::kCameraAuto;
    e = renderer_.Render(scene, settings, color_, image, stats);
    ASSERT_TRUE(Ok(e));
    EXPECT_EQ(stats.camera, "automatic");
}

TEST_F(RuntimeTest, PixelLightCountLimitsAdditivePassesAndTheRestBecomeVertexLights) {
    runtime::FrameSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.pixel_lights = 2;
    runtime::FrameStats stats;
    Render(LoneSphere("multi_light.material", 5), settings, &stats);
    EXPECT_EQ(stats.add_passes, 2u);
    EXPECT_EQ(stats.vertex_lit, 1u);  // the other three lit per vertex (VERTEXLIGHT_ON)
}

// -Os keeps every uniform-block member (the stages share one buffer per block) and renders what
// -O renders. Tolerance 1e-3 linear: the two pass lists may fold and reorder float arithmetic
// differently, a few ulps per term, far below one 8-bit step (about 1.5e-3 at mid-grey in linear).
TEST_F(RuntimeTest, SizeOptimizedPackRendersLikeTheDefault) {
    runtime::RendererOptions options;
    options.validation = true;
    options.float32_target = true;
    runtime::Renderer small;
    ASSERT_TRUE(CreateInto(options, small));
    Status e = small.AddPack(KILN_SIZE_PACK);
    ASSERT_TRUE(Ok(e));
    runtime::FrameSettings settings;
    settings.width = 64;
    settings.height = 48;
    const runtime::Scene scene = LoneSphere("multi_light.material", 2);
    runtime::LinearImage expected = Render(scene, settings), got;
    runtime::FrameStats stats;
    e = small.Render(scene, settings, color_, got, stats);
    ASSERT_TRUE(Ok(e));
    EXPECT_EQ(stats.add_passes, 2u);
    ASSERT_EQ(got.rgba.size(), expected.rgba.size());
    float worst = 0;
    for (size_t i = 0; i < got.rgba.size(); ++i)
        worst = std::max(worst, std::abs(got.rgba[i] - expected.rgba[i]));
    EXPECT_LT(worst, 1e-3f);
    EXPECT_GT(Covered(got), got.rgba.size() / 4 / 10);
    EXPECT_TRUE(small.ValidationMessages().empty());
}

TEST_F(RuntimeTest, ColorPropertyIsDecodedFromSrgbWithTheStandardFormula) {
    // Unlit writes _Color; the material file says (0.5, 0.25, 0.75) in sRGB.
    runtime::Scene scene = LoneSphere("unlit_color.material", 0);
    runtime::FrameSettings settings;
    settings.width = 64;
    settings.height = 48;
    const runtime::LinearImage image = Render(scene, settings);
    const size_t center = (size_t{24} * 64 + 32) * 4;
    ASSERT_GT(image.rgba[center + 3], 0.0f);
    EXPECT_NEAR(image.rgba[center + 0], SrgbToLinear(0.5), 1e-5);
    EXPECT_NEAR(image.rgba[center + 1], SrgbToLinear(0.25), 1e-5);
    EXPECT_NEAR(image.rgba[center + 2], SrgbToLinear(0.75), 1e-5);

    // The OCIO path against the formula over the whole range, and [HDR] values above 1.
    double worst = 0;
    for (int i = 0; i <= 1000; ++i) {
        const float x = float(i) / 1000.0f;
        float rgb[3] = {x, x, x};
        color_.SrgbToLinear(rgb, false);
        worst = std::max(worst, std::fabs(double(rgb[0]) - SrgbToLinear(x)));
    }
    EXPECT_LT(worst, 2e-6);
    float hdr[3] = {1.5f, 2.0f, 1.5f}, ldr[3] = {1.5f, 2.0f, 1.5f};
    color_.SrgbToLinear(hdr, true);
    color_.SrgbToLinear(ldr, false);
    EXPECT_NEAR(hdr[0], std::pow((1.5 + 0.055) / 1.055, 2.4), 1e-4);
    EXPECT_FLOAT_EQ(ldr[0], 1.0f);
}

class ProbeShaderTest : public RuntimeTest {
  protected:
    // The centre pixel of a 64x48 render of `scene` without lights.
    glm::vec4 CenterPixel(const runtime::Scene& scene) {
        runtime::FrameSettings settings;
        settings.width = 64;
        settings.height = 48;
        settings.default_light = false;
        const runtime::LinearImage image = Render(scene, settings);
        const size_t center = (size_t{24} * 64 + 32) * 4;
        if (image.rgba.size() < center + 4) {
            return glm::vec4(-1.0f);
        }
        return {image.rgba[center], image.rgba[center + 1], image.rgba[center + 2],
                image.rgba[center + 3]};
    }
};

TEST_F(ProbeShaderTest, DefaultTexturesTakeTheShapeTheShaderDeclares) {
    // 3D "black", cube "white" and 2D-array "gray" (128/255) defaults, each bound as an image
    // view of its own type: the validation layer (on in TearDown) rejects any mismatch.
    const glm::vec4 c = CenterPixel(LoneSphere("texture_shapes.material", 0));
    EXPECT_EQ(c.r, 0.0f);
    EXPECT_EQ(c.g, 1.0f);
    EXPECT_NEAR(c.b, 128.0 / 255.0, 1e-6);
}

TEST_F(ProbeShaderTest, ReflectionProbeCubeIsTheAmbientSky) {
    // unity_SpecCube0 is the scene's uniform ambient radiance (a float cube, so values above 1
    // survive), decoded with unity_SpecCube0_HDR = (1, 1, 0, 0). RGBA16F stores the radiance to
    // 11 significant bits: tolerance 1e-3 relative.
    runtime::Scene scene = LoneSphere("texture_environment.material", 0);
    scene.ambient = glm::vec3(0.25f, 1.5f, 3.0f);
    const glm::vec4 c = CenterPixel(scene);
    EXPECT_NEAR(c.r, 0.25f, 0.25e-3f);
    EXPECT_NEAR(c.g, 1.5f, 1.5e-3f);
    EXPECT_NEAR(c.b, 3.0f, 3.0e-3f);
}

TEST_F(ProbeShaderTest, WorldTransformParamsCarryTheTransformsHandedness) {
    runtime::Scene scene = LoneSphere("texture_mirror.material", 0);
    EXPECT_EQ(CenterPixel(scene).r, 1.0f);
    scene.instances[0].world = glm::scale(scene.instances[0].world, glm::vec3(-1, 1, 1));
    EXPECT_EQ(CenterPixel(scene).r, 0.0f);
}

TEST_F(RuntimeTest, DisplayTransformEncodesSrgb) {
    std::vector<float> rgba = {0.214041f, 0.0f, 1.0f, 1.0f, 0.0031308f, 0.5f, 4.0f, 1.0f};
    color_.ApplyDisplay(rgba);
    EXPECT_NEAR(rgba[0], 0.5f, 1e-4);
    EXPECT_NEAR(rgba[2], 1.0f, 1e-5);
    EXPECT_NEAR(rgba[4], 0.04045f, 1e-4);
    EXPECT_NEAR(rgba[5], LinearToSrgb(0.5), 1e-4);
}

TEST_F(RuntimeTest, RenderingAStrippedVariantFailsWithTheVariantNamed) {
    runtime::Renderer stripped;
    runtime::RendererOptions options;
    options.validation = true;
    ASSERT_TRUE(CreateInto(options, stripped));
    ASSERT_TRUE(Ok(stripped.AddPack(KILN_STRIPPED_PACK)));
    runtime::Scene scene = LoneSphere("unlit_color.material", 0);
    scene.material_files.clear();                      // the glTF material: StandardMetallic ...
    scene.materials[0].emissive = glm::vec3(1, 0, 0);  // ... with _EMISSION
    runtime::LinearImage image;
    runtime::FrameStats stats;
    Status e = stripped.Render(scene, {}, color_, image, stats);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, DiagCode::kMissingVariant);
    EXPECT_NE(e.error().message.find("has no variant for keywords '_EMISSION'"), std::string::npos)
        << e.error().message;
    EXPECT_TRUE(stripped.ValidationMessages().empty());
}

// Every damaged pack is refused by the time its damaged bytes would be used: AddPack refuses
// what it checks at load (the header, the table, the shaders and passes); the variant data is
// refused at its first use (CheckVariantData, which selecting a variant runs), a module's SPIR-V
// when it is read (Spirv is empty, and building its pipeline fails).
TEST_F(RuntimeTest, DamagedPacksAreRejectedWithoutACrash) {
    std::ifstream in(KILN_MATERIALS_PACK, std::ios::binary);
    const std::vector<char> good((std::istreambuf_iterator<char>(in)), {});
    ASSERT_GT(good.size(), 1000u);
    // One renderer for every attempt (a rejected pack is never added). Each attempt writes a new
    // file, so a pack wrongly accepted and still mapped is never truncated under the mapping.
    const std::string stem =
        (fs::temp_directory_path() / ("kiln_damaged_" + std::to_string(getpid()) + "_")).string();
    int attempt = 0;
    auto try_bytes = [&](const std::vector<char>& bytes) {
        const std::string file = stem + std::to_string(attempt++) + ".kpack";
        std::ofstream(file, std::ios::binary | std::ios::trunc)
            .write(bytes.data(), std::streamsize(bytes.size()));
        Status error = renderer_.AddPack(file);
        fs::remove(file);  // unlinking keeps any mapping valid
        if (!error.ok())
            return error;
        const pack::Pack& added = renderer_.pack(renderer_.pack_count() - 1);
        if (Status checked = added.CheckVariantData(); !checked.ok())
            return checked;
        for (uint32_t m = 0; m < added.Count(pack::SectionTag::kModules); ++m) {
            if (added.Spirv(added.Module(m).value()).empty())
                return Status(Error{DiagCode::kPackChecksum, "module " + std::to_string(m)});
        }
        return Status();
    };
    size_t rejected = 0, tried = 0;
    // About 250 truncations and 300 bit flips spread over the pack, whatever its size (each
    // attempt reads the whole pack: the cost is the count times the size).
    const size_t step = std::max<size_t>(4099, good.size() / 250);
    const size_t bit_step = std::max<size_t>(7919, good.size() * 8 / 300);
    for (size_t len = 0; len < good.size(); len += len < 128 ? 1 : step) {  // truncations
        ++tried;
        rejected += !try_bytes(std::vector<char>(good.begin(), good.begin() + long(len))).ok();
    }
    for (size_t bit = 0; bit < good.size() * 8; bit += bit_step) {  // single bit flips
        std::vector<char> bytes = good;
        bytes[bit / 8] = char(bytes[bit / 8] ^ (1 << (bit % 8)));
        ++tried;
        rejected += !try_bytes(bytes).ok();
    }
    EXPECT_EQ(rejected, tried);
    std::vector<char> foreign = good;
    foreign[0] = 'X';
    const Status e = try_bytes(foreign);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, DiagCode::kNotAPack) << e.error().message;
}

TEST_F(RuntimeTest, PipelineCacheIsPersistedBehindAValidatedHeader) {
    const fs::path path =
        fs::temp_directory_path() / ("kiln_pipeline_cache_" + std::to_string(getpid()) + ".bin");
    fs::remove(path);
    runtime::Scene scene = LoneSphere("lambert.material", 0);
    {
        runtime::Renderer r;
        runtime::RendererOptions options;
        options.pipeline_cache = path.string();
        ASSERT_TRUE(CreateInto(options, r));
        ASSERT_TRUE(Ok(r.AddPack(KILN_MATERIALS_PACK)));
        runtime::LinearImage image;
        runtime::FrameStats stats;
        ASSERT_TRUE(Ok(r.Render(scene, {}, color_, image, stats)));
    }  // saved on destruction
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
    ASSERT_GE(bytes.size(), vk::kPipelineCacheHeaderSize);
    EXPECT_EQ(std::string(bytes.data(), 4), "KPLC");
    // A damaged cache is ignored with a note, never handed to the driver.
    bytes.back() = char(bytes.back() ^ 0x40);
    bytes[40] = char(bytes[40] + 1);  // data size no longer matches
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), std::streamsize(bytes.size()));
    runtime::Renderer r;
    runtime::RendererOptions options;
    options.pipeline_cache = path.string();
    ASSERT_TRUE(CreateInto(options, r));
    ASSERT_TRUE(Ok(r.AddPack(KILN_MATERIALS_PACK)));
    runtime::LinearImage image;
    runtime::FrameStats stats;
    ASSERT_TRUE(Ok(r.Render(scene, {}, color_, image, stats)));
    ASSERT_FALSE(stats.warnings.all().empty());
    const Diagnostic& w = stats.warnings.all()[0];
    EXPECT_EQ(w.code, DiagCode::kPipelineCacheIgnored);
    EXPECT_EQ(w.severity, Severity::kWarning);
    EXPECT_NE(w.message.find("ignored"), std::string::npos) << w.message;
    fs::remove(path);
}

}  // namespace
}  // namespace kiln::test
