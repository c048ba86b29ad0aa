// kiln watch: driven through edits of a shader and of its include, a syntax error and its fix, an
// include deleted and restored. Each build's line and pack are checked; a build with errors
// prints them and leaves the last good pack as it was. And kiln render --watch: a new pack and an
// edited material are drawn by the running renderer.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "support/test_support.h"

extern char** environ;

namespace kiln::test {
namespace {

constexpr const char* kInclude = R"(float3 Tint() { return float3(0.25, 0.5, 0.75); }
)";

std::string ShaderText(const std::string& value) {
    return R"(Shader "Test/Watched"
{
    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex Vertex
            #pragma fragment Fragment
            #include "tint.cginc"
            float4 Vertex(float4 p : POSITION) : SV_POSITION { return p; }
            float4 Fragment() : SV_Target { return float4(Tint() * )" +
           value + R"(, 1.0); }
            ENDCG
        }
    }
}
)";
}

class WatchTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = FreshTempDir("kiln_watch");
        WriteFile(dir_ + "/tint.cginc", kInclude);
        WriteFile(dir_ + "/w.shader", ShaderText("0.5"));
    }
    void TearDown() override {
        if (pid_ > 0) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
    }

    void Start(int builds) {
        Spawn({"watch", dir_ + "/w.shader", "-o", dir_ + "/w.kpack", "--no-cache", "--builds",
               std::to_string(builds)});
    }

    // Runs kiln with `args`, its output into out.txt and err.txt in the test's folder.
    void Spawn(const std::vector<std::string>& args) {
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 1, (dir_ + "/out.txt").c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_addopen(&actions, 2, (dir_ + "/err.txt").c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
        std::vector<const char*> argv = {KILN_BINARY};
        for (const std::string& a : args)
            argv.push_back(a.c_str());
        argv.push_back(nullptr);
        ASSERT_EQ(posix_spawn(&pid_, KILN_BINARY, &actions, nullptr,
                              const_cast<char**>(argv.data()), environ),
                  0);
        posix_spawn_file_actions_destroy(&actions);
    }

    // Waits (up to two minutes) for a whole line of the output that holds one of `needles`;
    // returns it.
    std::string Line(const std::vector<std::string>& needles) {
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (std::chrono::steady_clock::now() < until) {
            const std::string out = ReadFile(dir_ + "/out.txt");
            for (const std::string& needle : needles) {
                const size_t at = out.find(needle);
                const size_t end = at == std::string::npos ? at : out.find('\n', at);
                if (end != std::string::npos) {
                    const size_t begin = out.rfind('\n', at);
                    const size_t from = begin == std::string::npos ? 0 : begin + 1;
                    return out.substr(from, end - from);
                }
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        ADD_FAILURE() << "no line with '" << needles.front() << "'; output:\n"
                      << ReadFile(dir_ + "/out.txt") << ReadFile(dir_ + "/err.txt");
        return "";
    }

    // Build `n`'s line.
    std::string Build(int n) {
        const std::string build = "kiln watch: build " + std::to_string(n);
        return Line({build + ":", build + " failed"});
    }

    std::string Pack() const { return ReadFile(dir_ + "/w.kpack"); }

    std::string dir_;
    pid_t pid_ = -1;
};

TEST_F(WatchTest, RebuildsOnEveryChangeAndKeepsTheLastGoodPack) {
    Start(7);
    EXPECT_NE(Build(1).find("w.kpack written (1 variant)"), std::string::npos);
    const std::string first = Pack();
    ASSERT_FALSE(first.empty());

    // 2: the shader body, saved by renaming a new file over it (as editors do).
    WriteFile(dir_ + "/w.shader.new", ShaderText("0.75"));
    std::filesystem::rename(dir_ + "/w.shader.new", dir_ + "/w.shader");
    const std::string line2 = Build(2);
    EXPECT_NE(line2.find("written"), std::string::npos) << line2;
    EXPECT_NE(line2.find("after the change"), std::string::npos) << line2;
    const std::string second = Pack();
    EXPECT_TRUE(second != first);

    // 3: the include, written in place.
    WriteFile(dir_ + "/tint.cginc", "float3 Tint() { return float3(1.0, 0.5, 0.25); }\n");
    EXPECT_NE(Build(3).find("written"), std::string::npos);
    const std::string third = Pack();
    EXPECT_TRUE(third != second);

    // 4: a syntax error: reported at its line, the pack left as build 3 wrote it.
    WriteFile(dir_ + "/w.shader", ShaderText("0.75 +"));
    EXPECT_NE(Build(4).find("failed: " + dir_ + "/w.kpack kept (the last good pack)"),
              std::string::npos);
    EXPECT_NE(ReadFile(dir_ + "/err.txt").find("w.shader:12:"), std::string::npos)
        << ReadFile(dir_ + "/err.txt");
    EXPECT_TRUE(Pack() == third);

    // 5: fixed.
    WriteFile(dir_ + "/w.shader", ShaderText("0.5"));
    EXPECT_NE(Build(5).find("written"), std::string::npos);
    const std::string fifth = Pack();

    // 6 and 7: the include deleted (an error naming it; the pack kept), then restored.
    std::filesystem::remove(dir_ + "/tint.cginc");
    EXPECT_NE(Build(6).find("kept"), std::string::npos);
    EXPECT_NE(ReadFile(dir_ + "/err.txt").find("tint.cginc"), std::string::npos);
    EXPECT_TRUE(Pack() == fifth);
    WriteFile(dir_ + "/tint.cginc", "float3 Tint() { return float3(1.0, 0.5, 0.25); }\n");
    EXPECT_NE(Build(7).find("written"), std::string::npos);
    EXPECT_TRUE(Pack() == fifth) << "the same sources give the same pack";

    int status = 0;
    ASSERT_EQ(waitpid(pid_, &status, 0), pid_);
    pid_ = -1;
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

TEST(Watch, RefusesWhatCannotBeRewritten) {
    const RunResult to_stdout = RunKilnWithin("watch x.shader -o -", 30);
    EXPECT_EQ(to_stdout.exit_code, 2);
    EXPECT_NE(to_stdout.err.find("kiln watch rewrites a pack file"), std::string::npos);
    const RunResult preprocess = RunKilnWithin("watch x.shader -E -o x.txt", 30);
    EXPECT_EQ(preprocess.exit_code, 2);
}

// The centre pixel of a PNG, 8-bit RGB.
std::array<int, 3> Centre(const std::string& png) {
    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load(png.c_str(), &w, &h, &n, 3);
    if (pixels == nullptr)
        return {-1, -1, -1};
    const unsigned char* p = pixels + 3 * (size_t(h / 2) * size_t(w) + size_t(w / 2));
    const std::array<int, 3> out = {p[0], p[1], p[2]};
    stbi_image_free(pixels);
    return out;
}

// kiln render --watch on the Box sample drawn with Test/Reload (tests/runtime/data): the pack
// rebuilt from the edited shader is swapped in (one pipeline kept, one made again) and the
// image written again with the edit; a material edited is drawn too; the frame-debug page is
// told the new frame.
TEST_F(WatchTest, RenderDrawsEachNewPackAndMaterial) {
    const std::filesystem::path box =
        std::filesystem::path(KILN_SHARED_DIR) / "gltf-samples" / "Box" / "glTF" / "Box.gltf";
    if (!std::filesystem::exists(box))
        GTEST_SKIP() << box << " absent";
    const std::string pack = dir_ + "/p.kpack";
    RunResult r = RunKiln("compile " + DataPath("runtime/data/Reload.shader") + " -o " + pack);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    WriteFile(
        dir_ + "/m.material",
        R"({"kiln_material": 1, "shader": "Test/Reload", "properties": {"_Color": [0.2, 0.2, 0.2, 1]}})");
    WriteFile(dir_ + "/box.kiln.json",
              R"({"kiln_materials": 1, "materials": {"Red": ")" + dir_ + R"(/m.material"}})");
    const std::string png = dir_ + "/out.png";
    Spawn({"render", box.string(), "--pack", pack, "--materials", dir_ + "/box.kiln.json",
           "--width", "64", "--height", "48", "-o", png, "--frame-debug", dir_ + "/fd",
           "--validation", "--watch"});
    EXPECT_NE(Line({"out.png: 64x48"}).find("validation messages: 0"), std::string::npos);
    const std::array<int, 3> before = Centre(png);
    EXPECT_GT(before[2], before[0] + 40) << "pass 2 adds blue";
    EXPECT_NE(ReadFile(dir_ + "/fd/live.js").find("'1'"), std::string::npos);

    r = RunKiln("compile " + DataPath("runtime/data/ReloadEdited.shader") + " -o " + dir_ +
                "/edited.kpack");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::filesystem::rename(dir_ + "/edited.kpack", pack);
    EXPECT_NE(Line({"p.kpack: replaced"}).find("1 pipelines kept, 1 to make again"),
              std::string::npos);
    Line({"frame 2 drawn"});
    const std::array<int, 3> after = Centre(png);
    EXPECT_GT(after[0], after[2] + 40) << "pass 2 now adds red";
    EXPECT_NE(ReadFile(dir_ + "/fd/live.js").find("'2'"), std::string::npos);
    EXPECT_NE(ReadFile(dir_ + "/fd/index.html").find("live.js"), std::string::npos);

    WriteFile(
        dir_ + "/m.material",
        R"({"kiln_material": 1, "shader": "Test/Reload", "properties": {"_Color": [0.6, 0.6, 0.6, 1]}})");
    Line({"frame 3 drawn"});
    EXPECT_GT(Centre(png)[1], after[1] + 40) << "the brighter grey";
}

}  // namespace
}  // namespace kiln::test
