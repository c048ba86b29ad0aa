// Every surface shader of the compatibility corpora (Unity's built-ins of three LTS lines and the
// tutorial corpus, in ../shared; skipped when absent) read by the generator's first steps: its
// `#pragma surface` lines (surface/directive.h), its Input struct (surface/input_struct.h) and its
// lighting model's forward function (surface/lighting_model.h), with the files it includes and,
// for Unity's built-in models, Lighting.cginc and UnityPBSLighting.cginc of Unity's CGIncludes and
// of Kiln's layer (246 directives; with Kiln's layer, all but the SpeedTree shaders').
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "shaderlab/program_scan.h"
#include "support/test_support.h"
#include "surface/directive.h"
#include "surface/input_struct.h"
#include "surface/lighting_model.h"

namespace kiln::surface {
namespace {

namespace fs = std::filesystem;

std::string ReadText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The file's text with the files it includes (beside it or in `cgincludes`) before it,
// recursively.
std::string WithIncludes(const fs::path& file,
                         const fs::path& cgincludes,
                         std::set<fs::path>& seen) {
    if (!seen.insert(file).second)
        return "";
    const std::string text = ReadText(file);
    static const std::regex include(R"re(#include\s+"([^"]+)")re");
    std::string before;
    for (std::sregex_iterator it(text.begin(), text.end(), include), end; it != end; ++it) {
        for (const fs::path& dir : {file.parent_path(), cgincludes}) {
            if (fs::exists(dir / (*it)[1].str())) {
                before += WithIncludes(dir / (*it)[1].str(), cgincludes, seen);
                break;
            }
        }
    }
    return before + text;
}

struct Counts {
    size_t lines = 0;
    std::vector<std::string> unread, no_input, no_lighting;
};

// Each `#pragma surface` of `shader`, against the includes of `cgincludes`.
void ReadShader(const fs::path& shader, const fs::path& cgincludes, Counts& counts) {
    const std::string own = ReadText(shader);
    for (const shaderlab::Pragma& p : shaderlab::ScanPragmas(own, {0, 1, 1})) {
        if (p.name != "surface")
            continue;
        ++counts.lines;
        DiagnosticList diags;
        const std::optional<SurfaceDirective> d = ParseSurfaceDirective(p, shader.string(), diags);
        if (!d) {
            counts.unread.push_back(shader.string() + ": " + test::Summarize(diags));
            continue;
        }
        std::set<fs::path> seen;
        std::string text = WithIncludes(shader, cgincludes, seen);
        if (!FindInputStruct(text, d->function.text))
            counts.no_input.push_back(shader.string() + " (" + d->function.text + ")");
        if (d->BuiltinLighting()) {
            for (const char* file : {"Lighting.cginc", "UnityPBSLighting.cginc"})
                text += WithIncludes(cgincludes / file, cgincludes, seen);
        }
        if (!FindLightingModel(text, d->lighting.text).Forward())
            counts.no_lighting.push_back(shader.string() + " (" + d->lighting.text + ")");
    }
}

TEST(SurfaceCorpus, EverySurfaceShaderHasItsDirectiveInputAndLightingModelRead) {
    const fs::path shared(KILN_SHARED_DIR);
    const fs::path templates = fs::path(KILN_TEST_DATA_DIR) / ".." / "templates";
    Counts unity, kiln;
    for (const char* corpus : {"unity-builtin-2022.3", "unity-builtin-2018.4",
                               "unity-builtin-6000.0", "ronja-tutorials"}) {
        const fs::path root = shared / corpus;
        if (!fs::exists(root))
            continue;
        const fs::path cgincludes =
            fs::exists(root / "Shaders" / "CGIncludes")
                ? root / "Shaders" / "CGIncludes"
                : shared / "unity-builtin-2022.3" / "Shaders" / "CGIncludes";
        for (const auto& entry : fs::recursive_directory_iterator(root)) {
            if (entry.is_regular_file() && entry.path().extension() == ".shader") {
                ReadShader(entry.path(), cgincludes, unity);
                ReadShader(entry.path(), templates, kiln);
            }
        }
    }
    if (unity.lines == 0)
        GTEST_SKIP() << shared << " holds no corpus (../shared not checked out)";
    EXPECT_GT(unity.lines, 200u);
    // Kiln's layer has no SpeedTree*.cginc yet (where the SpeedTree shaders' Input structs and
    // their SpeedTreeSubsurface model live): those, and only those, are not found with it.
    const auto speedtree_only = [](std::vector<std::string>& v) {
        v.erase(std::remove_if(v.begin(), v.end(),
                               [](const std::string& s) {
                                   return s.find("/Nature/SpeedTree") != std::string::npos;
                               }),
                v.end());
    };
    EXPECT_EQ(kiln.no_input.size(), 18u);  // 6 directives of 3 shaders, in 3 versions
    EXPECT_EQ(kiln.no_lighting.size(), 3u);
    speedtree_only(kiln.no_input);
    speedtree_only(kiln.no_lighting);
    for (const Counts* c : {&unity, &kiln}) {
        const char* mode = c == &unity ? "Unity's CGIncludes" : "Kiln's layer";
        EXPECT_TRUE(c->unread.empty()) << mode << ": " << c->unread.size() << " of " << c->lines
                                       << " directives unread, first " << c->unread.front();
        EXPECT_TRUE(c->no_input.empty())
            << mode << ": " << c->no_input.size() << " of " << c->lines
            << " without their Input struct, first " << c->no_input.front();
        EXPECT_TRUE(c->no_lighting.empty())
            << mode << ": " << c->no_lighting.size() << " of " << c->lines
            << " without a forward lighting function, first " << c->no_lighting.front();
    }
}

}  // namespace
}  // namespace kiln::surface
