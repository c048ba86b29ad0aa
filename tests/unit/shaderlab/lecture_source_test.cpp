// The shaders in tests/lecture are assembled from the lecture (../shared/seed/lecture-06-light.txt)
// as a student would write them: every line of their fragment programs (and of CreateLight in
// LightShader.cginc) must appear in the lecture text, whitespace aside. Skips when ../shared is
// absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "support/test_support.h"

namespace kiln::test {
namespace {

std::string Normalize(const std::string& line) {
    std::string out;
    for (char c : line) {
        if (c == ' ' || c == '\t' || c == '\r') {
            if (!out.empty() && out.back() != ' ') {
                out += ' ';
            }
        } else {
            out += c;
        }
    }
    while (!out.empty() && out.back() == ' ') {
        out.pop_back();
    }
    return out;
}

// The lines of the function whose signature line contains `signature`, through its closing brace.
std::vector<std::string> FunctionLines(const std::string& text, const std::string& signature) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    int depth = 0;
    bool inside = false;
    while (std::getline(in, line)) {
        if (!inside && line.find(signature) == std::string::npos) {
            continue;
        }
        inside = true;
        lines.push_back(line);
        for (char c : line) {
            depth += c == '{' ? 1 : c == '}' ? -1 : 0;
        }
        if (depth == 0 && line.find('}') != std::string::npos) {
            break;
        }
    }
    return lines;
}

TEST(LectureSource, AssembledShadersUseTheLecturesCode) {
    const std::string lecture_path = std::string(KILN_SHARED_DIR) + "/seed/lecture-06-light.txt";
    if (!std::filesystem::exists(lecture_path)) {
        GTEST_SKIP() << "../shared is absent (" << lecture_path << "); lecture text not checked";
    }
    std::string lecture;
    {
        std::istringstream in(ReadFile(lecture_path));
        std::string line;
        while (std::getline(in, line)) {
            lecture += "\n" + Normalize(line) + "\n";
        }
    }
    const std::pair<const char*, const char*> functions[] = {
        {"01_Lambert.shader", "MyFragmentProgram("},
        {"02_LambertAmbient.shader", "MyFragmentProgram("},
        {"03_Phong.shader", "MyFragmentProgram("},
        {"04_DiffuseSpecular.shader", "MyFragmentProgram("},
        {"05_Textured.shader", "MyFragmentProgram("},
        {"05_Textured.shader", "MyVertexProgram("},
        {"06_EnergyConservation.shader", "MyFragmentProgram("},
        {"07_PhysicallyBased.shader", "MyFragmentProgram("},
        {"LightShader.cginc", "UnityLight CreateLight("},
    };
    size_t checked = 0;
    for (const auto& [file, signature] : functions) {
        const auto lines = FunctionLines(ReadFile(DataPath(std::string("lecture/") + file)), signature);
        ASSERT_GT(lines.size(), 3u) << file << " has no " << signature;
        for (const std::string& raw : lines) {
            std::string line = Normalize(raw);
            // The slides put some opening braces on the signature line and leave one out.
            if (line.size() > 1 && line.back() == '{') {
                line = Normalize(line.substr(0, line.size() - 1));
            }
            if (line.empty() || line == "{" || line == "}") {
                continue;
            }
            EXPECT_NE(lecture.find(line), std::string::npos)
                << file << ": line not in the lecture: " << line;
            ++checked;
        }
    }
    EXPECT_GT(checked, 80u);
}

}  // namespace
}  // namespace kiln::test
