// The glTF loader on hostile files (issue 13's reproducers, rebuilt here): sizes that wrap,
// indices far out of range, deep and shared node hierarchies. Each loads or fails with a
// message; none crashes, hangs or allocates without bound.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "kiln/runtime/scene.h"
#include "runtime/gltf_files.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A little-endian 32-bit field of a .glb header or chunk.
std::string U32(uint32_t x) {
    std::string s;
    for (int i = 0; i < 4; ++i)
        s += char(x >> (8 * i));
    return s;
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

// Found by the glTF fuzz target: float indices (7e31) converted to uint32_t, undefined behaviour.
TEST(GltfHardening, IndicesMustBeUnsignedIntegers) {
    json g = Triangle();
    g["meshes"][0]["primitives"][0]["indices"] = 0;  // the float POSITION accessor
    const Loaded l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("the indices accessor 0 has component type 5126"),
              std::string::npos)
        << l.error->message;
}

TEST(GltfHardening, AttributeIndicesOutOfRangeAreReportedNotFollowed) {
    json g = Triangle();
    g["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 100000000;
    g["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = -5;
    const Loaded l = Load(g);
    ASSERT_FALSE(l.error) << l.error->message;
    const std::string all = AllWarnings(l);
    EXPECT_NE(all.find("attribute COLOR_0 ignored: accessor 100000000 does not exist"),
              std::string::npos)
        << all;
}

// Sparse accessors (glTF 2.0, 3.6.2.3): the base elements, then the substitutions; without a
// buffer view the base is zeros. Indices past the count and views too short are errors.
json SparseTriangle(int index, int base_view) {
    json g = Triangle();
    // A second buffer: one unsigned short index (then 2 padding bytes) and one VEC3 value.
    // Index `index`, value (5, 6, 7) as little-endian float32.
    const unsigned char bytes[16] = {uint8_t(index), 0,    0, 0, 0,    0,   0xa0, 0x40, 0, 0,
                                     0xc0,           0x40, 0, 0, 0xe0, 0x40};
    static const char* b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string enc;
    for (size_t i = 0; i < 16; i += 3) {
        const uint32_t n = uint32_t(bytes[i]) << 16 |
                           (i + 1 < 16 ? uint32_t(bytes[i + 1]) << 8 : 0) |
                           (i + 2 < 16 ? bytes[i + 2] : 0);
        enc += b64[n >> 18 & 63];
        enc += b64[n >> 12 & 63];
        enc += i + 1 < 16 ? b64[n >> 6 & 63] : '=';
        enc += i + 2 < 16 ? b64[n & 63] : '=';
    }
    g["buffers"].push_back(
        {{"byteLength", 16}, {"uri", "data:application/octet-stream;base64," + enc}});
    g["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", 2}});
    g["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 4}, {"byteLength", 12}});
    g["accessors"][0]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 1}, {"componentType", 5123}}},
                                   {"values", {{"bufferView", 2}}}};
    g["accessors"][0]["max"] = {5, 6, 7};
    if (base_view < 0) {
        g["accessors"][0].erase("bufferView");
    }
    return g;
}

TEST(GltfHardening, SparseAccessorsReplaceTheirElements) {
    for (int base : {0, -1}) {
        const Loaded l = Load(SparseTriangle(1, base));
        ASSERT_FALSE(l.error) << l.error->message;
        const auto& v = l.scene.meshes.at(0).primitives.at(0).vertices;
        ASSERT_EQ(v.size(), 3u);
        EXPECT_EQ(v[1].position[0], 5.0f);
        EXPECT_EQ(v[1].position[2], 7.0f);
        EXPECT_EQ(v[0].position[0], base == 0 ? -1.0f : 0.0f);  // kept, or zero without a view
    }
    const Loaded past = Load(SparseTriangle(3, 0));
    ASSERT_TRUE(past.error);
    EXPECT_NE(past.error->message.find("sparse index 3 is past its 3 elements"), std::string::npos)
        << past.error->message;
    json shortview = SparseTriangle(1, 0);
    shortview["accessors"][0]["sparse"]["count"] = 2;
    const Loaded s = Load(shortview);
    ASSERT_TRUE(s.error);
    EXPECT_NE(s.error->message.find("sparse indices reads past its buffer view"), std::string::npos)
        << s.error->message;
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
    EXPECT_EQ(l.error->code, DiagCode::kBadScene);
    EXPECT_NE(l.error->message.find("node 1 is a child of node 0 twice"), std::string::npos)
        << l.error->message;

    g["nodes"] = {{{"children", {1}}}, {{"children", {2}}}, {{"mesh", 0}, {"children", {1}}}};
    l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("node 1 is a child of node 0 and of node 2"), std::string::npos)
        << l.error->message;

    g["nodes"] = {{{"mesh", 0}, {"children", {0}}}};
    l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("node 0 is a child of node 0"), std::string::npos)
        << l.error->message;

    g["nodes"] = {{{"mesh", 0}, {"children", {7}}}};
    l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("node 0 has child 7, which does not exist"), std::string::npos)
        << l.error->message;

    g["nodes"] = {{{"children", {1}}}, {{"mesh", 0}}};
    g["scenes"] = {{{"nodes", {0, 1}}}};
    l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("node 1 is a scene root and a child of node 0"),
              std::string::npos)
        << l.error->message;
}

// tinygltf's JSON parser recurses once per level: 100,000 levels of extras crashed it.
TEST(GltfHardening, JsonNestedTooDeepIsRejectedBeforeParsing) {
    std::string text = Triangle().dump();
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    text.insert(1, "\"extras\": " + deep + ", ");
    Loaded l = LoadText(text);
    ASSERT_TRUE(l.error);
    EXPECT_EQ(l.error->code, DiagCode::kBadScene);
    EXPECT_NE(l.error->message.find("JSON nested more than 128 deep"), std::string::npos)
        << l.error->message;
    // Brackets inside strings do not count, and 100 levels are fine.
    text = Triangle().dump();
    text.insert(1, "\"extras\": {\"s\": \"" + std::string(1000, '[') +
                       "\", \"a\": " + std::string(100, '[') + std::string(100, ']') + "}, ");
    l = LoadText(text);
    EXPECT_FALSE(l.error) << l.error->message;
}

TEST(GltfHardening, TheJsonChunkOfABinaryFileIsCheckedToo) {
    const std::string json_text =
        "{\"asset\": " + std::string(1000, '[') + std::string(1000, ']') + "}";
    std::string chunk = json_text;
    while (chunk.size() % 4 != 0)
        chunk += ' ';
    const std::string glb = "glTF" + U32(2) + U32(uint32_t(20 + chunk.size())) +
                            U32(uint32_t(chunk.size())) + "JSON" + chunk;
    const Loaded l = LoadText(glb, ".glb");
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("JSON nested more than 128 deep"), std::string::npos)
        << l.error->message;
}

// Found by the glTF fuzz target: a .glb whose first buffer declares 0 bytes made tinygltf call
// std::vector::at(0) on an empty vector and throw out of the runtime (std::terminate).
TEST(GltfHardening, ABinaryFileWhoseFirstBufferIsEmptyIsAnError) {
    std::string chunk = "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 0}]}";
    while (chunk.size() % 4 != 0)
        chunk += ' ';
    const std::string bin = "abcd";
    const std::string glb = "glTF" + U32(2) + U32(uint32_t(28 + chunk.size() + bin.size())) +
                            U32(uint32_t(chunk.size())) + "JSON" + chunk +
                            U32(uint32_t(bin.size())) + "BIN" + std::string(1, '\0') + bin;
    const Loaded l = LoadText(glb, ".glb");
    ASSERT_TRUE(l.error);
    EXPECT_EQ(l.error->code, DiagCode::kBadScene);
    EXPECT_NE(l.error->message.find("not a glTF file Kiln reads (tinygltf failed:"),
              std::string::npos)
        << l.error->message;
}

// A buffer uri naming a directory was read as a file of its "size": std::bad_alloc.
TEST(GltfHardening, BufferUrisMustNameRegularFiles) {
    const fs::path dir = ScratchDir() / "a_directory";
    fs::create_directories(dir);
    json g = Triangle();
    g["buffers"][0]["uri"] = "a_directory";
    Loaded l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("is a directory, not a regular file"), std::string::npos)
        << l.error->message;
    // glTF uris are relative: a link beside the file stands for a device a uri could reach.
    std::error_code ec;
    fs::remove(ScratchDir() / "zero_link", ec);
    fs::create_symlink("/dev/zero", ScratchDir() / "zero_link");
    g["buffers"][0]["uri"] = "zero_link";
    l = Load(g);
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("is a character device"), std::string::npos)
        << l.error->message;
}

TEST(GltfHardening, AScenePathThatIsNotARegularFileIsAnError) {
    Loaded l = LoadFile(ScratchDir());
    ASSERT_TRUE(l.error);
    EXPECT_EQ(l.error->code, DiagCode::kBadScene);
    EXPECT_NE(l.error->message.find("is a directory"), std::string::npos) << l.error->message;
    l = LoadFile("/dev/zero");
    ASSERT_TRUE(l.error);
    EXPECT_NE(l.error->message.find("is a character device"), std::string::npos)
        << l.error->message;
}

// A PNG whose header declares 100000 x 100000 pixels would ask for 40 GB: Kiln's image reader
// refuses it from the header (kiln/runtime/image.h), and the scene loads with the default texture
// in its place and a K0013 warning that says why.
TEST(GltfHardening, ImagesDeclaringTooManyPixelsAreNotDecoded) {
    auto be32 = [](uint32_t x) {
        std::string s;
        for (int i = 3; i >= 0; --i)
            s += char(x >> (8 * i));
        return s;
    };
    // Signature, then an IHDR chunk: stb_image reads the size before any CRC or data.
    const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + be32(13) + "IHDR" + be32(100000) +
                            be32(100000) + std::string("\x08\x06\0\0\0", 5) + be32(0) + be32(0) +
                            "IEND" + be32(0);
    std::ofstream(ScratchDir() / "bomb.png", std::ios::binary) << png;
    json g = Triangle();
    g["images"] = {{{"uri", "bomb.png"}}};
    const Loaded l = Load(g);
    ASSERT_FALSE(l.error) << l.error->message;
    ASSERT_EQ(l.scene.images.size(), 1u);
    EXPECT_TRUE(l.scene.images[0].rgba8.empty());
    bool warned = false;
    for (const Diagnostic& d : l.warnings.all()) {
        warned = warned || (d.code == DiagCode::kTextureFallback &&
                            d.message.find("the image is 100000x100000") != std::string::npos);
    }
    EXPECT_TRUE(warned);
}

// A sidecar that named /dev/zero as a material file read without end.
TEST(GltfHardening, SidecarsAreBoundedRegularFiles) {
    runtime::Scene scene;
    Status e = runtime::LoadMaterialSidecar("/dev/zero", scene);
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().message.find("is a character device"), std::string::npos)
        << e.error().message;
    const fs::path deep = ScratchDir() / "deep.kiln.json";
    std::ofstream(deep) << "{\"description\": " << std::string(5000, '[') << std::string(5000, ']')
                        << "}";
    e = runtime::LoadMaterialSidecar(deep.string(), scene);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, DiagCode::kBadScene);
    // The .material reader's bounded JSON parser, with the position where it stopped.
    EXPECT_NE(e.error().message.find("deep.kiln.json:1:"), std::string::npos) << e.error().message;
    EXPECT_NE(e.error().message.find("nesting deeper than 64 levels"), std::string::npos)
        << e.error().message;
}

}  // namespace
}  // namespace kiln::test
