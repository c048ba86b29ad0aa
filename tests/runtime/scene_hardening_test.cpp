// The glTF loader on hostile files (issue 13's reproducers, rebuilt here): sizes that wrap,
// indices far out of range, deep and shared node hierarchies. Each loads or fails with a
// message; none crashes, hangs or allocates without bound.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "kiln/runtime/scene.h"

namespace kiln::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// One triangle (positions in a data URI), its mesh on node 0, one scene with node 0.
json Triangle() {
    // -1,0,0  1,0,0  0,1,0 as little-endian float32.
    const char* positions =
        "data:application/octet-stream;base64,AACAvwAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    return json{{"asset", {{"version", "2.0"}}},
                {"buffers", {{{"byteLength", 36}, {"uri", positions}}}},
                {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
                {"accessors",
                 {{{"bufferView", 0},
                   {"componentType", 5126},
                   {"count", 3},
                   {"type", "VEC3"},
                   {"min", {-1, 0, 0}},
                   {"max", {1, 1, 0}}}}},
                {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                {"nodes", {{{"mesh", 0}}}},
                {"scenes", {{{"nodes", {0}}}}},
                {"scene", 0}};
}

struct Loaded {
    std::optional<runtime::Error> error;
    runtime::Scene scene;
    std::vector<std::string> warnings;
};

Loaded Load(const json& gltf) {
    const fs::path dir = fs::temp_directory_path() / "kiln_scene_hardening";
    fs::create_directories(dir);
    const fs::path file = dir / (std::string(::testing::UnitTest::GetInstance()
                                                 ->current_test_info()
                                                 ->name()) +
                                 ".gltf");
    std::ofstream(file) << gltf.dump();
    Loaded out;
    out.error = runtime::LoadGltf(file.string(), out.scene, out.warnings);
    return out;
}

TEST(GltfHardening, TheTriangleLoads) {
    const Loaded l = Load(Triangle());
    ASSERT_FALSE(l.error) << l.error->message;
    EXPECT_EQ(l.scene.instances.size(), 1u);
}

// count * stride once wrapped, passed the bounds check and wrote past a 2-float allocation.
TEST(GltfHardening, AccessorCountsWhoseSizesWrapAreRejected) {
    for (uint64_t count : {uint64_t(6148914691236517206ull), uint64_t(9223372036854775809ull),
                           uint64_t(18446744073709551615ull)}) {
        json g = Triangle();
        g["accessors"][0]["count"] = count;
        const Loaded l = Load(g);
        ASSERT_TRUE(l.error) << count;
        EXPECT_NE(l.error->message.find("reads past its buffer view"), std::string::npos)
            << l.error->message;
    }
}

TEST(GltfHardening, AttributeIndicesOutOfRangeAreReportedNotFollowed) {
    json g = Triangle();
    g["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 100000000;
    g["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = -5;
    const Loaded l = Load(g);
    ASSERT_FALSE(l.error) << l.error->message;
    std::string all;
    for (const std::string& w : l.warnings)
        all += w + "\n";
    EXPECT_NE(all.find("attribute COLOR_0 ignored: accessor 100000000 does not exist"),
              std::string::npos)
        << all;
}

// A valid 100,000-node chain once overflowed the recursive walk's stack.
TEST(GltfHardening, ADeepChainLoadsWithoutRecursion) {
    json g = Triangle();
    json nodes = json::array();
    constexpr int kDepth = 100000;
    for (int i = 0; i < kDepth; ++i) {
        json n = {{"translation", {0, 0.001, 0}}};
        if (i + 1 < kDepth)
            n["children"] = {i + 1};
        else
            n["mesh"] = 0;
        nodes.push_back(n);
    }
    g["nodes"] = nodes;
    const Loaded l = Load(g);
    ASSERT_FALSE(l.error) << l.error->message;
    ASSERT_EQ(l.scene.instances.size(), 1u);
    EXPECT_NEAR(l.scene.instances[0].world[3][1], 100.0f, 0.1f);  // 100,000 x 1 mm
}

// 41 nodes whose children are [i+1, i+1] once expanded to 2^40 instances and never finished.
TEST(GltfHardening, SharedChildrenAndCyclesAreErrors) {
    json g = Triangle();
    json nodes = json::array();
    for (int i = 0; i < 41; ++i)
        nodes.push_back(i + 1 < 41 ? json{{"children", {i + 1, i + 1}}} : json{{"mesh", 0}});
    g["nodes"] = nodes;
    Loaded l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_EQ(l.error->kind, runtime::ErrorKind::kScene);
    EXPECT_NE(l.error->message.find("node 1 is a child of node 0 twice"), std::string::npos)
        << l.error->message;

    g["nodes"] = {{{"children", {1}}}, {{"children", {2}}}, {{"mesh", 0}, {"children", {1}}}};
    l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("node 1 is a child of node 0 and of node 2"),
              std::string::npos)
        << l.error->message;

    g["nodes"] = {{{"mesh", 0}, {"children", {0}}}};
    l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("node 0 is a child of node 0"), std::string::npos)
        << l.error->message;

    g["nodes"] = {{{"mesh", 0}, {"children", {7}}}};
    l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("node 0 has child 7, which does not exist"),
              std::string::npos)
        << l.error->message;

    g["nodes"] = {{{"children", {1}}}, {{"mesh", 0}}};
    g["scenes"] = {{{"nodes", {0, 1}}}};
    l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("node 1 is a scene root and a child of node 0"),
              std::string::npos)
        << l.error->message;
}

}  // namespace
}  // namespace kiln::testing
