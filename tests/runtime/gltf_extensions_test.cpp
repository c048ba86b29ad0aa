// glTF extensions and the features Kiln does not draw: a required extension Kiln does not
// support is an error naming it (K0030), also where tinygltf cannot parse the file without it
// (Draco); an optional one, skins, animations and morph targets are one warning each (K0016);
// the extensions Kiln reads are read.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "kiln/runtime/scene.h"
#include "runtime/gltf_files.h"

namespace kiln::test {
namespace {

using nlohmann::json;

size_t Occurrences(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

TEST(GltfExtensions, ARequiredUnsupportedExtensionIsAnErrorNamingIt) {
    json gltf = Triangle();
    gltf["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
    gltf["extensionsRequired"] = {"KHR_materials_pbrSpecularGlossiness"};
    const Loaded l = Load(gltf);
    ASSERT_TRUE(l.error);
    EXPECT_EQ(l.error->code, DiagCode::kUnsupportedExtension);
    EXPECT_NE(l.error->message.find("requires extension 'KHR_materials_pbrSpecularGlossiness' "
                                    "(the specular-glossiness material workflow)"),
              std::string::npos)
        << l.error->message;
}

TEST(GltfExtensions, ADracoFileNamesDracoNotTheAccessorTinygltfFailsOn) {
    // Draco's accessors have no bufferView: the data is in the extension's compressed view.
    json gltf = Triangle();
    gltf["accessors"][0].erase("bufferView");
    gltf["meshes"][0]["primitives"][0]["extensions"] = {
        {"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
    gltf["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    gltf["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    const Loaded l = Load(gltf);
    ASSERT_TRUE(l.error);
    EXPECT_EQ(l.error->code, DiagCode::kUnsupportedExtension);
    EXPECT_NE(l.error->message.find("'KHR_draco_mesh_compression' (Draco mesh compression)"),
              std::string::npos)
        << l.error->message;
}

TEST(GltfExtensions, AnUnknownRequiredExtensionIsNamedToo) {
    json gltf = Triangle();
    gltf["extensionsRequired"] = {"KHR_lights_punctual", "VENDOR_future_thing"};
    const Loaded l = Load(gltf);
    ASSERT_TRUE(l.error);
    EXPECT_EQ(l.error->code, DiagCode::kUnsupportedExtension);
    EXPECT_NE(l.error->message.find("'VENDOR_future_thing', which Kiln does not support"),
              std::string::npos)
        << l.error->message;
}

TEST(GltfExtensions, SupportedRequiredExtensionsLoad) {
    json gltf = Triangle();
    gltf["extensionsUsed"] = {"KHR_materials_unlit", "KHR_texture_transform",
                              "KHR_mesh_quantization"};
    gltf["extensionsRequired"] = gltf["extensionsUsed"];
    gltf["materials"] = {{{"extensions", {{"KHR_materials_unlit", json::object()}}}}};
    gltf["meshes"][0]["primitives"][0]["material"] = 0;
    const Loaded l = Load(gltf);
    ASSERT_FALSE(l.error) << l.error->message;
    EXPECT_EQ(AllWarnings(l), "");
    ASSERT_EQ(l.scene.materials.size(), 1u);
    EXPECT_TRUE(l.scene.materials[0].unlit);
}

TEST(GltfExtensions, EachIgnoredOptionalFeatureIsOneWarning) {
    json gltf = Triangle();
    gltf["extensionsUsed"] = {"KHR_materials_transmission", "EXT_mesh_gpu_instancing",
                              "KHR_materials_clearcoat"};
    gltf["materials"] = {
        {{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}},
        {{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 0.5}}}}}}};
    gltf["skins"] = {{{"joints", {0}}}};
    gltf["animations"] = json::array();  // an empty list: nothing to warn about
    const Loaded l = Load(gltf);
    ASSERT_FALSE(l.error) << l.error->message;
    const std::string all = AllWarnings(l);
    EXPECT_EQ(Occurrences(all, "KHR_materials_transmission"), 1u) << all;
    EXPECT_EQ(Occurrences(all, "'EXT_mesh_gpu_instancing' (GPU instancing"), 1u) << all;
    EXPECT_EQ(Occurrences(all, "KHR_materials_clearcoat"), 1u) << all;
    EXPECT_EQ(Occurrences(all, "1 skin(s) ignored"), 1u) << all;
    EXPECT_EQ(Occurrences(all, "animation"), 0u) << all;
    EXPECT_EQ(l.warnings.all().size(), 4u) << all;
}

TEST(GltfExtensions, TextureTransformAndSamplersAreReadPerMap) {
    json gltf = Triangle();
    gltf["images"] = {{{"uri", "missing.png"}}};
    gltf["samplers"] = {{{"wrapS", 33648}, {"wrapT", 33071}}};
    gltf["textures"] = {{{"source", 0}, {"sampler", 0}}};
    gltf["materials"] = {{{"pbrMetallicRoughness",
                           {{"baseColorTexture",
                             {{"index", 0},
                              {"extensions",
                               {{"KHR_texture_transform",
                                 {{"offset", {0.25, 0.5}},
                                  {"rotation", 1.5},
                                  {"scale", {2, 3}},
                                  {"texCoord", 1}}}}}}}}},
                          {"emissiveTexture", {{"index", 0}, {"texCoord", 3}}}}};
    const Loaded l = Load(gltf);
    ASSERT_FALSE(l.error) << l.error->message;
    ASSERT_EQ(l.scene.materials.size(), 1u);
    const runtime::TextureRef& base = l.scene.materials[0].base_color_texture;
    EXPECT_EQ(base.wrap_s, runtime::TextureWrap::kMirroredRepeat);
    EXPECT_EQ(base.wrap_t, runtime::TextureWrap::kClampToEdge);
    EXPECT_EQ(base.offset, glm::vec2(0.25f, 0.5f));
    EXPECT_EQ(base.uv_scale, glm::vec2(2.0f, 3.0f));
    EXPECT_FLOAT_EQ(base.rotation, 1.5f);
    EXPECT_EQ(base.texcoord, 1);  // the transform's texCoord overrides the textureInfo's
    // TEXCOORD_3 does not exist in Kiln's vertex: TEXCOORD_0, with a warning naming the map.
    EXPECT_EQ(l.scene.materials[0].emissive_texture.texcoord, 0);
    EXPECT_NE(AllWarnings(l).find("emissiveTexture reads TEXCOORD_3"), std::string::npos)
        << AllWarnings(l);
}

TEST(GltfExtensions, StripsAndFansBecomeTriangleLists) {
    // A quad's corners 0 (-1, 0), 1 (1, 0), 2 (-1, 1), 3 (1, 1); as a strip 0 1 2 3, as a fan
    // 0 1 3 2. Strip triangle i is {i, i+1, i+2} for even i and {i, i+2, i+1} for odd i (the
    // winding kept); fan triangle i is {i+1, i+2, 0} (glTF 2.0, 3.7.2.1).
    const float corners[] = {-1, 0, 0, 1, 0, 0, -1, 1, 0, 1, 1, 0};
    const std::string positions(reinterpret_cast<const char*>(corners), sizeof corners);
    for (const auto& [mode, order, want] :
         {std::tuple{5, std::string{0, 1, 2, 3}, std::vector<uint32_t>{0, 1, 2, 1, 3, 2}},
          std::tuple{6, std::string{0, 1, 3, 2}, std::vector<uint32_t>{1, 3, 0, 3, 2, 0}}}) {
        json gltf = Triangle();
        gltf["buffers"] = {{{"byteLength", positions.size()}, {"uri", DataUri(positions)}},
                           {{"byteLength", order.size()}, {"uri", DataUri(order)}}};
        gltf["bufferViews"] = {{{"buffer", 0}, {"byteLength", positions.size()}},
                               {{"buffer", 1}, {"byteLength", order.size()}}};
        gltf["accessors"][0]["count"] = 4;
        gltf["accessors"].push_back(
            {{"bufferView", 1}, {"componentType", 5121}, {"count", 4}, {"type", "SCALAR"}});
        gltf["meshes"][0]["primitives"][0]["indices"] = 1;
        gltf["meshes"][0]["primitives"][0]["mode"] = mode;
        const Loaded l = Load(gltf);
        ASSERT_FALSE(l.error) << l.error->message;
        ASSERT_EQ(l.scene.meshes.size(), 1u);
        ASSERT_EQ(l.scene.meshes[0].primitives.size(), 1u);
        EXPECT_EQ(l.scene.meshes[0].primitives[0].indices, want) << "mode " << mode;
    }
}

}  // namespace
}  // namespace kiln::test
