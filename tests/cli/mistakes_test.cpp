// The usual mistakes of a new user, one row each (inputs in tests/cli/mistakes/): every one exits
// non-zero with a stable code, the position of the mistake and, where a name is involved, the
// closest valid name; the same in --diagnostics-format=json; and no output file is left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

struct Mistake {
    const char* name;
    // {D}: tests/cli/mistakes, {L}: tests/lecture, {T}: a scratch folder holding spot.kpack.
    const char* args;
    int exit_code;
    const char* code;        // "K4014"
    const char* where;       // "file:line:col" or "file" as printed ("" for the command line)
    const char* suggestion;  // a substring of the message: the closest name, the valid values
};

void PrintTo(const Mistake& m, std::ostream* os) {
    *os << m.name;
}

const Mistake kMistakes[] = {
    // Entry points: glslang would emit an empty stage and exit 0.
    {"fragment entry typo", "compile {D}/fragment_entry.shader -o {T}/out.kpack", 1, "K4014",
     "fragment_entry.shader:17:30", "did you mean 'frag'?"},
    {"vertex entry typo", "compile {D}/vertex_entry.shader -o {T}/out.kpack", 1, "K4014",
     "vertex_entry.shader:16:28", "did you mean 'vert'?"},
    // Keywords that nothing declares.
    {"compile --keywords typo",
     "compile {D}/base.shader --keywords SHADOWS_SCREEM -o {T}/out.kpack", 1, "K4015", "",
     "did you mean 'SHADOWS_SCREEN'?"},
    {"extract --keywords typo",
     "extract {T}/spot.kpack --shader Lecture/SpotLight --pass ForwardAdd --keywords SPOTT "
     "--stage frag -o {T}/out.spv",
     1, "K4015", "spot.kpack", "did you mean 'SPOT'?"},
    // Variant pragmas and LightMode tags spelled almost right.
    {"shortcut pragma typo", "compile {D}/pragma_typo.shader -o {T}/out.kpack", 1, "K4016",
     "pragma_typo.shader:18:13", "did you mean 'multi_compile_fwdbase'?"},
    {"LightMode typo", "compile {D}/lightmode_typo.shader -o {T}/out.kpack", 1, "K3014",
     "lightmode_typo.shader:12:20", "did you mean 'ForwardBase'?"},
    // Positions and names in HLSL.
    {"missing semicolon", "compile {D}/missing_semicolon.shader -o {T}/out.kpack", 1, "K5001",
     "missing_semicolon.shader:25:47", "expected ';' at the end of this line"},
    {"missing include", "compile {D}/missing_include.shader -o {T}/out.kpack", 1, "K5001",
     "missing_include.shader:20:23", "cannot find include file 'Lighting2.cginc'"},
    {"undeclared property", "compile {D}/undeclared_property.shader -o {T}/out.kpack", 1, "K5001",
     "undeclared_property.shader:25:36", "did you mean '_Smoothness'?"},
    {"unknown identifier", "compile {D}/unknown_identifier.shader -o {T}/out.kpack", 1, "K5001",
     "unknown_identifier.shader:25:28", "did you mean '_Tint'?"},
    {"stray brace", "compile {D}/stray_brace.shader -o {T}/out.kpack", 1, "K5001",
     "stray_brace.shader:22:13", "syntax error"},
    // ShaderLab.
    {"command typo", "compile {D}/command_typo.shader -o {T}/out.kpack", 1, "K2004",
     "command_typo.shader:14:13", "did you mean 'ZWrite'?"},
    {"blend factor typo", "compile {D}/blend_typo.shader -o {T}/out.kpack", 1, "K2005",
     "blend_typo.shader:13:28",
     "SrcAlphaSaturate, OneMinusSrcAlpha or a [property] reference; did you mean "
     "'OneMinusSrcAlpha'?"},
    // Pack names.
    {"extract shader typo",
     "extract {T}/spot.kpack --shader Lecture/SpotLigth --pass ForwardAdd --stage frag "
     "-o {T}/out.spv",
     1, "K0005", "spot.kpack", "did you mean 'Lecture/SpotLight'?"},
    {"extract pass typo",
     "extract {T}/spot.kpack --shader Lecture/SpotLight --pass ForwardAd --stage frag "
     "-o {T}/out.spv",
     1, "K0005", "spot.kpack", "did you mean 'ForwardAdd'?"},
    {"missing pack", "render {D}/triangle.gltf --pack {T}/none.kpack -o {T}/out.png", 1, "K0001",
     "", "none.kpack"},
    // Scenes and render options.
    {"nothing to draw", "render {D}/nothing_to_draw.gltf -o {T}/out.png", 1, "K0007",
     "nothing_to_draw.gltf", "nothing to draw"},
    {"node cycle", "render {D}/node_cycle.gltf -o {T}/out.png", 1, "K0007", "node_cycle.gltf",
     "node 0 is a scene root and a child of node 2 'loop'"},
    {"default scene out of range", "render {D}/bad_default_scene.gltf -o {T}/out.png", 1, "K0007",
     "bad_default_scene.gltf", "the default scene 5 does not exist (the file has 1 scenes)"},
    {"negative camera", "render {D}/triangle.gltf --camera -1 -o {T}/out.png", 2, "K0003", "",
     "expected a camera index from 0, or auto"},
    {"camera out of range", "render {D}/triangle.gltf --camera 3 -o {T}/out.png", 1, "K0007", "",
     "camera 3 does not exist (the scene has 1"},
    {"OCIO view typo", "render {D}/triangle.gltf --view Standrad -o {T}/out.png", 1, "K0009", "",
     "did you mean 'Standard'? (views: Standard, Raw)"},
    {"missing sky image", "render {D}/triangle.gltf --sky {T}/none.hdr -o {T}/out.png", 1, "K0007",
     "none.hdr", "no such sky image"},
    {"missing sky image as ambient",
     "render {D}/triangle.gltf --ambient {T}/none.hdr -o {T}/out.png", 1, "K0007", "none.hdr",
     "no such sky image"},
    {"sky and ambient",
     "render {D}/triangle.gltf --sky {T}/none.hdr --ambient 1,1,1 -o {T}/out.png", 1, "K0007", "",
     "--ambient and --sky both set the ambient light; give one"},
    {"procedural sky colours", "render {D}/triangle.gltf --ambient sky:1,1,1 -o {T}/out.png", 2,
     "K0003", "", "expected sky or sky:ZENITH:HORIZON:GROUND of R,G,B each"},
    // Two outputs of one command on one file.
    {"depfile is the pack", "compile {D}/base.shader -o {T}/x.kpack -MF {T}/x.kpack", 1, "K0002",
     "x.kpack", "x.kpack' are one file; give each output its own"},
    {"exr is the png", "render {D}/triangle.gltf -o {T}/x.png --exr {T}/./x.png", 1, "K0002", "",
     "/x.png' and --exr '"},
    {"pipeline cache is the png",
     "render {D}/triangle.gltf -o {T}/x.png --pipeline-cache {T}/x.png", 1, "K0002", "",
     "/x.png' and --pipeline-cache '"},
    // The command line.
    {"subcommand typo", "compil {D}/base.shader", 2, "K0003", "", "did you mean 'compile'?"},
    {"optimization level", "compile {D}/base.shader -O4 -o {T}/out.kpack", 2, "K0003", "",
     "expected -O0, -O or -Os"},
};

std::string Expand(std::string s, const std::string& scratch) {
    s = std::regex_replace(s, std::regex("\\{D\\}"), DataPath("cli/mistakes"));
    s = std::regex_replace(s, std::regex("\\{L\\}"), DataPath("lecture"));
    return std::regex_replace(s, std::regex("\\{T\\}"), scratch);
}

class MistakesTest : public ::testing::TestWithParam<Mistake> {
  protected:
    static void SetUpTestSuite() {
        scratch_ = testing::TempDir() + "/kiln_mistakes";
        fs::create_directories(scratch_);
    }
    // ctest runs every case in its own process: only the cases that read spot.kpack build it.
    static void BuildSpotPack() {
        const RunResult r = RunKiln(Expand(
            "compile {L}/11_SpotLight.shader -I {L} --no-cache -o {T}/spot.kpack", scratch_));
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    static std::string scratch_;
};
std::string MistakesTest::scratch_;

TEST_P(MistakesTest, GivesItsCodePositionAndSuggestionAndNoOutput) {
    const Mistake& m = GetParam();
    if (std::string(m.args).find("{T}/spot.kpack") != std::string::npos) {
        ASSERT_NO_FATAL_FAILURE(BuildSpotPack());
    }
    for (const char* out : {"out.kpack", "out.spv", "out.png"})
        fs::remove(scratch_ + "/" + out);
    const std::string args = Expand(m.args, scratch_) + " --no-cache";
    const bool compile = std::string(m.args).rfind("compile", 0) == 0;
    const RunResult text = RunKiln("--color=never " + (compile ? args : Expand(m.args, scratch_)));
    EXPECT_EQ(text.exit_code, m.exit_code) << text.err;
    const std::string where = std::string(m.where);
    const std::string head = where.empty() ? "kiln: error: " : where + ": error: ";
    const size_t at = where.empty() ? text.err.find(head) : text.err.find("/" + head);
    ASSERT_NE(at, std::string::npos) << "expected '" << head << "' in:\n" << text.err;
    const std::string line = text.err.substr(at, text.err.find('\n', at) - at);
    EXPECT_NE(line.find(std::string("[") + m.code + "]"), std::string::npos) << line;
    EXPECT_NE(line.find(m.suggestion), std::string::npos) << line;
    for (const char* out : {"out.kpack", "out.spv", "out.png"})
        EXPECT_FALSE(fs::exists(scratch_ + "/" + out)) << out << " written despite the error";

    // The same diagnostic as JSON, with the line and column.
    const RunResult json =
        RunKiln("--diagnostics-format=json " + (compile ? args : Expand(m.args, scratch_)));
    EXPECT_EQ(json.exit_code, m.exit_code);
    nlohmann::json diags;
    ASSERT_NO_THROW(diags = nlohmann::json::parse(json.err)) << json.err;
    bool found = false;
    for (const auto& d : diags) {
        if (d["code"] != m.code || d["severity"] != "error")
            continue;
        found = true;
        EXPECT_NE(d["message"].get<std::string>().find(m.suggestion), std::string::npos)
            << d["message"];
        std::smatch pos;
        if (std::regex_search(where, pos, std::regex(":(\\d+):(\\d+)$"))) {
            EXPECT_EQ(d["range"]["begin"]["line"], std::stoi(pos[1]));
            EXPECT_EQ(d["range"]["begin"]["column"], std::stoi(pos[2]));
        }
    }
    EXPECT_TRUE(found) << json.err;
}

INSTANTIATE_TEST_SUITE_P(Cli,
                         MistakesTest,
                         ::testing::ValuesIn(kMistakes),
                         [](const ::testing::TestParamInfo<Mistake>& row) {
                             std::string name = row.param.name;
                             for (char& c : name) {
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             }
                             return name;
                         });

TEST(Cli, BareKilnPrintsTheUsageAndExitsTwo) {
    const RunResult r = RunKiln("");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("Usage: kiln [OPTIONS] [SUBCOMMAND]"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("compile"), std::string::npos);
}

TEST(Cli, VersionNamesTheLibrariesPacksRecord) {
    for (const char* spelling : {"--version", "-V", "version"}) {
        const RunResult r = RunKiln(spelling);
        EXPECT_EQ(r.exit_code, 0) << spelling;
        EXPECT_TRUE(std::regex_search(
            r.out, std::regex("^kiln [0-9.]+; glslang [0-9.]+; SPIRV-Tools v?[0-9.]+; pack "
                              "format [0-9]+\\.[0-9]+\n$")))
            << spelling << ": " << r.out;
    }
}

// README and --help spell every option the same way, and the help shows no CLI11 internals.
TEST(Cli, HelpUsesReadmesSpellings) {
    const std::string readme = ReadFile(DataPath("../README.md"));
    const RunResult compile = RunKiln("compile --help");
    for (const char* spelling : {"-O0 | -O | -Os", "-MD", "-MF FILE", "--unity-version VERSION",
                                 "--max-variants N", "--all-features", "--keywords"}) {
        EXPECT_NE(compile.out.find(spelling), std::string::npos) << spelling;
    }
    EXPECT_NE(readme.find("[-O0|-O|-Os]"), std::string::npos);
    EXPECT_NE(readme.find("-MD -MF out.d"), std::string::npos);
    EXPECT_EQ(compile.out.find("--opt"), std::string::npos) << compile.out;
    const RunResult render = RunKiln("render --help");
    EXPECT_NE(render.out.find("--camera N|auto"), std::string::npos) << render.out;
    EXPECT_NE(readme.find("[--camera N|auto]"), std::string::npos);
    for (const char* internal : {"{false}", "UINT:INT", ":POSITIVE", "TEXT:VERSION"}) {
        EXPECT_EQ(render.out.find(internal), std::string::npos) << internal;
        EXPECT_EQ(compile.out.find(internal), std::string::npos) << internal;
    }
}

TEST(Cli, ColorFollowsTheFlagAndNoColor) {
    const std::string bad = DataPath("cli/mistakes/command_typo.shader");
    EXPECT_NE(RunKiln("--color=always parse -q " + bad).err.find("\033[1;31merror:"),
              std::string::npos);
    EXPECT_EQ(RunKiln("--color=never parse -q " + bad).err.find('\033'), std::string::npos);
    // Not a terminal (captured): auto means no colour.
    EXPECT_EQ(RunKiln("parse -q " + bad).err.find('\033'), std::string::npos);
}

}  // namespace
}  // namespace kiln::test
