// kiln watch: driven through edits of a shader and of its include, a syntax error and its fix, an
// include deleted and restored. Each build's line and pack are checked; a build with errors
// prints them and leaves the last good pack as it was.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

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
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 1, (dir_ + "/out.txt").c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_addopen(&actions, 2, (dir_ + "/err.txt").c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const std::string shader = dir_ + "/w.shader", pack = dir_ + "/w.kpack",
                          count = std::to_string(builds);
        const char* argv[] = {KILN_BINARY,  "watch",    shader.c_str(), "-o",   pack.c_str(),
                              "--no-cache", "--builds", count.c_str(),  nullptr};
        ASSERT_EQ(
            posix_spawn(&pid_, KILN_BINARY, &actions, nullptr, const_cast<char**>(argv), environ),
            0);
        posix_spawn_file_actions_destroy(&actions);
    }

    // Waits (up to a minute) for build `n`'s line and returns it.
    std::string Build(int n) {
        const std::string prefix = "kiln watch: build " + std::to_string(n);
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (std::chrono::steady_clock::now() < until) {
            const std::string out = ReadFile(dir_ + "/out.txt");
            const size_t at = out.find(prefix + ":");
            const size_t failed = out.find(prefix + " failed");
            const size_t found = std::min(at, failed);
            if (found != std::string::npos && out.find('\n', found) != std::string::npos)
                return out.substr(found, out.find('\n', found) - found);
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        ADD_FAILURE() << "no line for build " << n << "; output:\n"
                      << ReadFile(dir_ + "/out.txt") << ReadFile(dir_ + "/err.txt");
        return "";
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

}  // namespace
}  // namespace kiln::test
