// A surface shader's Input struct (surface/input_struct.h): the manual's conventions, and every
// surface shader of the compatibility corpora.
#include "surface/input_struct.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "shaderlab/program_scan.h"
#include "support/test_support.h"
#include "surface/directive.h"

namespace kiln::surface {
namespace {

namespace fs = std::filesystem;

TEST(SurfaceInput, MembersAreReadByUnitysConventions) {
    const std::string text = R"(
        sampler2D _MainTex;
        struct Input {
            float2 uv_MainTex, uv_BumpMap;  // two declarators
            float2 uv2_Detail;
            float3 viewDir;
            /* float3 commented; */
            float4 screenPos;
            float3 worldPos;
            float3 worldRefl;
            float4 color : COLOR;
            float3 customColor;
            float facing : VFACE;
            INTERNAL_DATA
        };
        void surf(in Input IN, inout SurfaceOutput o) { o.Albedo = 1; }
    )";
    const std::optional<InputStruct> in = FindInputStruct(text, "surf");
    ASSERT_TRUE(in);
    EXPECT_EQ(in->name, "Input");
    EXPECT_TRUE(in->internal_data);
    std::vector<std::string> seen;
    for (const InputMember& m : in->members)
        seen.push_back(m.name + "=" + InputKindName(m.kind));
    EXPECT_EQ(seen,
              (std::vector<std::string>{
                  "uv_MainTex=uv_<texture>", "uv_BumpMap=uv_<texture>", "uv2_Detail=uv_<texture>",
                  "viewDir=viewDir", "screenPos=screenPos", "worldPos=worldPos",
                  "worldRefl=worldRefl", "color=COLOR", "customColor=custom", "facing=VFACE"}));
    EXPECT_EQ(in->members[0].texture, "MainTex");
    EXPECT_EQ(in->members[2].uv_set, 1);
    EXPECT_EQ(in->members[2].texture, "Detail");
    EXPECT_EQ(text.substr(in->members[7].offset, 5), "color");
    EXPECT_TRUE(in->Reads(InputKind::kWorldRefl));
    EXPECT_FALSE(in->Reads(InputKind::kWorldNormal));
}

TEST(SurfaceInput, TheStructIsTheSurfaceFunctionsFirstParameter) {
    const std::string text = R"(
        struct Input { float2 uv_MainTex; };
        struct Other { float3 worldNormal; };
        void vert(inout appdata_full v, out Other o) { o = (Other)0; }
        void surfAlt(Other IN, inout SurfaceOutputStandard o) {}
        void surf(Input IN, inout SurfaceOutputStandard o) { surfAlt((Other)0, o); }
    )";
    EXPECT_EQ(FindInputStruct(text, "surf")->members.front().name, "uv_MainTex");
    EXPECT_EQ(FindInputStruct(text, "surfAlt")->name, "Other");
    EXPECT_FALSE(FindInputStruct(text, "surface"));  // no such function
    EXPECT_FALSE(FindInputStruct("void surf(Missing IN, inout SurfaceOutput o) {}", "surf"));
}

std::string ReadText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The shader's text with the files it includes (beside it or in the corpus's CGIncludes)
// before it, recursively: what the Input struct may be declared in.
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

// Every surface shader of the corpora: its directive names a function whose Input struct is
// found, with what it includes.
TEST(SurfaceInput, EverySurfaceShaderOfTheCorporaHasItsInputFound) {
    const fs::path shared(KILN_SHARED_DIR);
    size_t shaders = 0;
    std::vector<std::string> missing;
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
            if (!entry.is_regular_file() || entry.path().extension() != ".shader")
                continue;
            const std::string own = ReadText(entry.path());
            for (const shaderlab::Pragma& p : shaderlab::ScanPragmas(own, {0, 1, 1})) {
                if (p.name != "surface")
                    continue;
                DiagnosticList diags;
                const auto directive = ParseSurfaceDirective(p, entry.path().string(), diags);
                ASSERT_TRUE(directive) << entry.path();
                std::set<fs::path> seen;
                ++shaders;
                if (!FindInputStruct(WithIncludes(entry.path(), cgincludes, seen),
                                     directive->function.text))
                    missing.push_back(entry.path().string() + " (" + directive->function.text +
                                      ")");
            }
        }
    }
    if (shaders == 0)
        GTEST_SKIP() << shared << " holds no corpus (../shared not checked out)";
    EXPECT_TRUE(missing.empty()) << missing.size() << " of " << shaders << ", first "
                                 << missing.front();
    EXPECT_GT(shaders, 200u);
}

}  // namespace
}  // namespace kiln::surface
