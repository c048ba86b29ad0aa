// Every glTF sample in ../shared/gltf-samples gets a pack of the shipped materials stripped to
// what it looks up, verified by replaying the scene against it (--verify-scene). The kept and
// left-out counts go to the test log. Skipped when ../shared is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

std::string Samples() {
    return std::string(KILN_SHARED_DIR) + "/gltf-samples";
}

// The sample's .gltf (else .glb) under its glTF folder.
std::string SceneOf(const fs::path& sample) {
    std::string glb;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(sample / "glTF", ec)) {
        if (e.path().extension() == ".gltf")
            return e.path().string();
        if (e.path().extension() == ".glb")
            glb = e.path().string();
    }
    return glb;
}

std::string ShippedShaders() {
    std::string all;
    for (const char* s :
         {"Unlit", "Lambert", "LambertAmbient", "BlinnPhong", "BlinnPhongTextured",
          "EnergyConserving", "Standard", "StandardMetallic", "MultiLight", "Deferred"})
        all += DataPath("../materials/") + s + ".shader ";
    return all;
}

TEST(GltfSamplesStrip, EverySampleGetsAVerifiedStrippedPack) {
    if (!fs::exists(Samples()))
        GTEST_SKIP() << Samples() << " is absent: the glTF samples are not checked";
    ScratchDir dir;
    std::vector<fs::path> folders;
    for (const auto& e : fs::directory_iterator(Samples())) {
        if (e.is_directory() && e.path().filename().string()[0] != '_')
            folders.push_back(e.path());
    }
    std::sort(folders.begin(), folders.end());  // a stable log
    size_t samples = 0;
    for (const fs::path& folder : folders) {
        const std::string name = folder.filename().string();
        const std::string scene = SceneOf(folder);
        ASSERT_FALSE(scene.empty()) << name;
        const std::string out = dir.path() + "/" + name + ".kpack";
        const RunResult r =
            RunKiln("compile " + ShippedShaders() + "-o " + out + " --cache-dir " + dir.path() +
                    "/cache --scene " + scene + " --verify-scene --explain-json");
        ASSERT_EQ(r.exit_code, 0) << name << ":\n" << r.err;
        const nlohmann::json explain = nlohmann::json::parse(r.out);
        const uint64_t kept = explain["kept_variants"], declared = explain["declared_combinations"];
        std::printf("%-28s kept %2llu of %llu variants, %zu shaders left out, %llu bytes\n",
                    name.c_str(), static_cast<unsigned long long>(kept),
                    static_cast<unsigned long long>(declared), explain["shaders_left_out"].size(),
                    static_cast<unsigned long long>(explain["pack_bytes"]));
        EXPECT_GE(kept, 1u) << name;
        EXPECT_LT(kept, declared) << name;
        ++samples;
        if (name != "LightsPunctualLamp")
            continue;
        // Five point lights: the additive pass keeps POINT variants, never SPOT or DIRECTIONAL.
        bool point = false;
        for (const auto& pass : explain["passes"]) {
            for (const auto& v : pass["kept"]) {
                const auto& k = v["keywords"];
                point = point || std::find(k.begin(), k.end(), "POINT") != k.end();
                EXPECT_EQ(std::find(k.begin(), k.end(), "SPOT"), k.end()) << v.dump();
                EXPECT_EQ(std::find(k.begin(), k.end(), "DIRECTIONAL"), k.end()) << v.dump();
            }
        }
        EXPECT_TRUE(point) << explain.dump(1);

        // A needed variant removed by hand (skip_variants POINT in a copy of the shader): the
        // verification fails and names it.
        std::string text = ReadFile(DataPath("../materials/StandardMetallic.shader"));
        const std::string anchor = "#pragma multi_compile_fwdadd_fullshadows";
        ASSERT_NE(text.find(anchor), std::string::npos);
        text.replace(text.find(anchor), anchor.size(), anchor + " \n#pragma skip_variants POINT");
        const std::string copy = dir.Write("edited/StandardMetallic.shader", text);
        const RunResult broken = RunKiln("compile " + copy + " -I " + DataPath("../materials") +
                                         " -o " + out + ".broken --cache-dir " + dir.path() +
                                         "/cache --scene " + scene + " --verify-scene");
        EXPECT_EQ(broken.exit_code, 1) << broken.err;
        EXPECT_NE(broken.err.find("[K4019]"), std::string::npos) << broken.err;
        EXPECT_NE(broken.err.find("'POINT _NORMALMAP"), std::string::npos) << broken.err;
        EXPECT_FALSE(fs::exists(out + ".broken"));
    }
    EXPECT_GE(samples, 20u);
}

}  // namespace
}  // namespace kiln::test
