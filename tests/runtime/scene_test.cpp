// The glTF loader on the real samples and the glTF-Validator's KHR_lights_punctual files (skipped
// when ../shared is absent), tangent generation, and the material sidecar.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "kiln/runtime/scene.h"
#include "runtime/runtime_asserts.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

std::string Shared(const std::string& rel) {
    return std::string(KILN_SHARED_DIR) + "/gltf-samples/" + rel;
}
#define REQUIRE_SHARED()                                                               \
    if (!fs::exists(Shared(""))) {                                                     \
        GTEST_SKIP() << "../shared/gltf-samples is absent: glTF sample tests skipped"; \
    }

TEST(GltfLights, ValidatorFilesInvalidLightsAreRejectedWithAMessage) {
    REQUIRE_SHARED();
    const std::string dir = Shared("_validator-KHR_lights_punctual/data/light/");
    for (const char* bad : {"unknown_type.gltf", "spot_invalid_angles.gltf"}) {
        runtime::Scene scene;
        DiagnosticList warnings;
        ASSERT_TRUE(LoadInto(dir + bad, scene, warnings));
        EXPECT_TRUE(AnyWarning(warnings, "rejected")) << bad;
        // A warning with its code, about the scene file, not an error.
        bool coded = false;
        for (const Diagnostic& w : warnings.all()) {
            coded |= w.code == DiagCode::kSceneContentIgnored && w.file == dir + bad &&
                     w.severity == Severity::kWarning &&
                     w.message.find("rejected") != std::string::npos;
        }
        EXPECT_TRUE(coded) << bad;
        EXPECT_FALSE(warnings.has_errors());
    }
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(LoadInto(dir + "valid.gltf", scene, warnings));
    EXPECT_FALSE(AnyWarning(warnings, "rejected"));
}

TEST(GltfLights, EveryValidatorFileLoadsOrFailsCleanly) {
    REQUIRE_SHARED();
    for (const char* sub : {"light", "node"}) {
        for (const auto& entry :
             fs::directory_iterator(Shared("_validator-KHR_lights_punctual/data/") + sub)) {
            if (entry.path().extension() != ".gltf") {
                continue;
            }
            runtime::Scene scene;
            DiagnosticList warnings;
            (void)runtime::LoadGltf(entry.path().string(), warnings);  // must not crash
        }
    }
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(LoadInto(
        Shared("_validator-KHR_lights_punctual/data/node/unresolved_light_empty_root_array.gltf"),
        scene, warnings));
    EXPECT_TRUE(scene.lights.empty());
    EXPECT_TRUE(AnyWarning(warnings, "does not exist"));
}

TEST(GltfLights, LampHasFivePointLightsWithDefaultedColours) {
    REQUIRE_SHARED();
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(
        LoadInto(Shared("LightsPunctualLamp/glTF/LightsPunctualLamp.gltf"), scene, warnings));
    ASSERT_EQ(scene.lights.size(), 5u);
    for (const runtime::Light& l : scene.lights) {
        EXPECT_GE(l.intensity, 0.0f);
        EXPECT_TRUE(std::isfinite(l.position.x));
    }
}

TEST(GltfScene, SparseAccessorSampleRaisesItsThreePeaks) {
    REQUIRE_SHARED();
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(
        LoadInto(Shared("SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf"), scene, warnings));
    float top = 0;
    int raised = 0;
    for (const auto& v : scene.meshes.at(0).primitives.at(0).vertices) {
        top = std::max(top, v.position[1]);
        raised += v.position[1] > 1.5f;
    }
    EXPECT_EQ(top, 4.0f);  // the accessor's max, reached only through the substitutions
    EXPECT_EQ(raised, 3);
}

TEST(GltfScene, CamerasSampleHasAPerspectiveAndAnOrthographicCamera) {
    REQUIRE_SHARED();
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(LoadInto(Shared("Cameras/glTF/Cameras.gltf"), scene, warnings));
    ASSERT_EQ(scene.cameras.size(), 2u);
    EXPECT_NE(scene.cameras[0].perspective, scene.cameras[1].perspective);
}

TEST(GltfScene, MissingTangentsAreGeneratedOrthonormalToTheNormal) {
    REQUIRE_SHARED();
    runtime::Scene scene;
    DiagnosticList warnings;
    ASSERT_TRUE(LoadInto(Shared("NormalTangentTest/glTF/NormalTangentTest.gltf"), scene, warnings));
    ASSERT_FALSE(scene.meshes.empty());
    size_t checked = 0;
    for (const runtime::Mesh& m : scene.meshes) {
        for (const runtime::Primitive& p : m.primitives) {
            EXPECT_TRUE(p.has_tangents);
            for (const runtime::MeshVertex& v : p.vertices) {
                const glm::vec3 t = glm::make_vec3(v.tangent), n = glm::make_vec3(v.normal);
                EXPECT_NEAR(glm::length(t), 1.0f, 1e-4f);
                EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-4f);
                EXPECT_TRUE(v.tangent[3] == 1.0f || v.tangent[3] == -1.0f);
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 0u);
}

TEST(GltfScene, GeneratedTangentFollowsIncreasingU) {
    runtime::Primitive p;
    // A quad in the xy plane with u along +x, v along -y (glTF's v points down the image).
    const float xyuv[4][4] = {{0, 0, 0, 1}, {1, 0, 1, 1}, {1, 1, 1, 0}, {0, 1, 0, 0}};
    for (const auto& c : xyuv) {
        runtime::MeshVertex v{};
        v.position[0] = c[0];
        v.position[1] = c[1];
        v.normal[2] = 1;
        v.uv0[0] = c[2];
        v.uv0[1] = c[3];
        p.vertices.push_back(v);
    }
    p.indices = {0, 1, 2, 0, 2, 3};
    runtime::GenerateTangents(p);
    for (const runtime::MeshVertex& v : p.vertices) {
        EXPECT_NEAR(v.tangent[0], 1.0f, 1e-6f);
        EXPECT_NEAR(v.tangent[1], 0.0f, 1e-6f);
        // bitangent = w * cross(n, t) = w * (+y) must point up the image (the normal map's
        // green axis), i.e. towards decreasing v, which is +y here: w = +1.
        EXPECT_EQ(v.tangent[3], 1.0f);
    }
}

TEST(GltfScene, NotAGltfFileIsAnErrorNotACrash) {
    const fs::path dir = fs::temp_directory_path() / "kiln_scene_test";
    fs::create_directories(dir);
    for (const std::string& text : {std::string(""), std::string("{"),
                                    std::string("{\"asset\":{\"version\":\"2.0\"},\"meshes\":[{"
                                                "\"primitives\":[{\"attributes\":{\"POSITION\""
                                                ":7}}]}]}")}) {
        std::ofstream(dir / "bad.gltf") << text;
        runtime::Scene scene;
        DiagnosticList warnings;
        EXPECT_FALSE(runtime::LoadGltf((dir / "bad.gltf").string(), warnings)) << text;
    }
    runtime::Scene scene;
    DiagnosticList warnings;
    auto e = runtime::LoadGltf((dir / "missing.gltf").string(), warnings);
    ASSERT_FALSE(e);
    EXPECT_EQ(e.error().code, DiagCode::kBadScene);
    EXPECT_NE(e.error().message.find("no such file"), std::string::npos);
}

TEST(MaterialSidecar, PathsAreRelativeToTheSidecarAndUnknownFieldsAreErrors) {
    const fs::path dir = fs::temp_directory_path() / "kiln_sidecar_test";
    fs::create_directories(dir);
    std::ofstream(dir / "s.kiln.json")
        << R"({"kiln_materials": 1, "materials": {"Red": "red.material"}, "ambient": [0.1, 0.2, 0.3]})";
    runtime::Scene scene;
    ASSERT_TRUE(Ok(runtime::LoadMaterialSidecar((dir / "s.kiln.json").string(), scene)));
    EXPECT_EQ(scene.material_files.at("Red"), (dir / "red.material").string());
    EXPECT_FLOAT_EQ(scene.ambient.y, 0.2f);
    std::ofstream(dir / "t.kiln.json") << R"({"materiels": {}})";
    Status e = runtime::LoadMaterialSidecar((dir / "t.kiln.json").string(), scene);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, DiagCode::kBadScene);
    EXPECT_NE(e.error().message.find("unknown field 'materiels'"), std::string::npos);
}

}  // namespace
}  // namespace kiln::test
