// The kiln CLI as a user and a build system see it: exit codes, output formats, diagnostics.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <future>

#include <nlohmann/json.hpp>

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

std::string WriteTemp(const std::string& name, const std::string& text) {
    const std::string path = testing::TempDir() + "/kiln_cli_" + name;
    WriteFile(path, text);
    return path;
}

TEST(Cli, ParsePrintsTheTreeAndExitsZero) {
    const RunResult r = RunKiln("parse " + DataPath("lecture/11_SpotLight.shader"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Shader \"Lecture/SpotLight\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("#pragma multi_compile DIRECTIONAL POINT SPOT"), std::string::npos);
    EXPECT_EQ(r.err, "");
}

TEST(Cli, ParseJsonIsValidAndVersioned) {
    const RunResult r = RunKiln("parse --json " + DataPath("lecture/01_Lambert.shader") + " " +
                                DataPath("lecture/12_Deferred.shader"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["kiln_ast_version"], 1);
    ASSERT_EQ(j["files"].size(), 2u);
    EXPECT_EQ(j["files"][1]["ast"]["name"], "Lecture/Deferred");
    EXPECT_EQ(j["files"][1]["ast"]["programs"][0]["kind"], "CGINCLUDE");
}

TEST(Cli, ErrorsAreCompilerStyleWithCaretAndExitOne) {
    const std::string path =
        WriteTemp("bad.shader", "Shader \"x\" {\n  SubShader {\n    Cull Sideways\n  }\n}\n");
    const RunResult r = RunKiln("parse -q " + path);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find(path + ":3:10: error: invalid value 'Sideways' for 'Cull'; expected Off, "
                                "Front, Back or a [property] reference [K2005]\n"
                                " 3 |     Cull Sideways\n"
                                "   |          ^~~~~~~~\n"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.out, "");
}

TEST(Cli, JsonDiagnostics) {
    const std::string path = WriteTemp("bad2.shader", "Shader \"x\" {\n  Pass { }\n}\n");
    const RunResult r = RunKiln("--diagnostics-format=json parse -q " + path);
    EXPECT_EQ(r.exit_code, 1);
    const auto j = nlohmann::json::parse(r.err);
    ASSERT_EQ(j.size(), 1u);
    EXPECT_EQ(j[0]["code"], "K2016");
    EXPECT_EQ(j[0]["file"], path);
    EXPECT_EQ(j[0]["range"]["begin"]["line"], 2);
    EXPECT_EQ(j[0]["range"]["begin"]["column"], 3);
}

TEST(Cli, WarningsAloneExitZero) {
    const std::string path =
        WriteTemp("warn.shader", "Shader \"x\" { SubShader { Pass { Fog { Density 1 } } } }\n");
    const RunResult r = RunKiln("parse -q " + path);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.err.find("warning: fixed-function 'Fog' settings are ignored"), std::string::npos)
        << r.err;
}

TEST(Cli, ErrorsFromSeveralFilesInOneRun) {
    const std::string a = WriteTemp("a.shader", "Shader \"a\" { SubShader { Cull No } }");
    const std::string b = WriteTemp("b.shader", "Shader \"b\" { SubShader { ZWrite No } }");
    const RunResult r = RunKiln("parse -q " + a + " " + b);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find(a + ":1:31: error"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(b + ":1:33: error"), std::string::npos) << r.err;
}

TEST(Cli, MissingFileIsAnInputError) {
    const RunResult r = RunKiln("parse /nonexistent/missing.shader");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("error: cannot open '/nonexistent/missing.shader'"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("[K0001]"), std::string::npos);
}

TEST(Cli, UsageErrorsExitTwo) {
    EXPECT_EQ(RunKiln("").exit_code, 2);
    EXPECT_EQ(RunKiln("frobnicate").exit_code, 2);
    EXPECT_EQ(RunKiln("parse").exit_code, 2);
    EXPECT_EQ(RunKiln("parse --no-such-flag x.shader").exit_code, 2);
    EXPECT_EQ(RunKiln("--diagnostics-format=xml parse x.shader").exit_code, 2);
    EXPECT_EQ(RunKiln("--help").exit_code, 0);
}

TEST(Cli, CompileWritesPackAndDepfileListingEveryFileRead) {
    const std::string dir = testing::TempDir() + "/kiln_cli_compile";
    std::filesystem::create_directories(dir);
    const std::string pack = dir + "/out.kpack";
    const RunResult r = RunKiln("compile " + DataPath("data/compile/multi_light.shader") + " -o " +
                                pack + " -MD -MF " + dir + "/out.d -O -j 2 --no-cache --stats");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("variants 3, stage programs 6, unique programs 3"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("aliased variants 1"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ms: load "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("peak memory: kiln "), std::string::npos) << r.out;
    const std::string dep = ReadFile(dir + "/out.d");
    const std::string shader =
        std::filesystem::canonical(DataPath("data/compile/multi_light.shader"));
    const std::string include = std::filesystem::canonical(DataPath("data/compile/light.cginc"));
    // A CGPROGRAM includes Unity's three implicit files first, here from Kiln's templates.
    std::string implicit;
    for (const char* f :
         {"HLSLSupport.cginc", "UnityShaderUtilities.cginc", "UnityShaderVariables.cginc"}) {
        implicit +=
            std::filesystem::canonical(kiln::DefaultTemplatesDir() + "/" + f).string() + " \\\n  ";
    }
    EXPECT_EQ(dep, pack + ": \\\n  " + implicit + include + " \\\n  " + shader + "\n");
    EXPECT_TRUE(std::filesystem::exists(pack));

    const RunResult info = RunKiln("info " + pack);
    EXPECT_EQ(info.exit_code, 0) << info.err;
    // light.cginc lights POINT and SPOT alike: SPOT is an alias of POINT, two variants stored.
    EXPECT_NE(info.out.find("pass \"FORWARD_DELTA\" (LightMode ForwardAdd): 2 variants "
                            "[DIRECTIONAL POINT SPOT=POINT]"),
              std::string::npos)
        << info.out;
    const RunResult json = RunKiln("info --json " + pack);
    ASSERT_EQ(json.exit_code, 0);
    const nlohmann::json pass = nlohmann::json::parse(json.out)["shaders"][0]["passes"][0];
    EXPECT_EQ(pass["variants"].size(), 2u);
    EXPECT_EQ(pass["keyword_sets"][0]["aliases"], (nlohmann::json{{"SPOT", "POINT"}}));

    const RunResult ex = RunKiln("extract " + pack +
                                 " --shader Test/MultiLight --pass ForwardAdd --keywords SPOT "
                                 "--stage frag -o " +
                                 dir + "/spot.spv");
    EXPECT_EQ(ex.exit_code, 0) << ex.err;
    EXPECT_GT(std::filesystem::file_size(dir + "/spot.spv"), 100u);
    const RunResult missing =
        RunKiln("extract " + pack + " --shader Test/MultiLight --pass NOPE --stage vert -o x.spv");
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.err.find("has no pass \"NOPE\""), std::string::npos);
}

TEST(Cli, CompileErrorsLeaveNoOutputAndExitOne) {
    const std::string dir = testing::TempDir() + "/kiln_cli_compile_err";
    std::filesystem::create_directories(dir);
    const std::string bad = WriteTemp(
        "bad_hlsl.shader",
        "Shader \"B\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex v\n#pragma fragment f\n"
        "float4 v() : SV_POSITION { return oops; }\nfloat4 f() : SV_Target { return 1; }\n"
        "ENDCG\n} } }\n");
    const RunResult r = RunKiln("compile " + bad + " -o " + dir + "/bad.kpack --no-cache");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("bad_hlsl.shader:5:35: error: unknown variable 'oops' [K5001]"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/bad.kpack"));
    const RunResult many = RunKiln("compile " + DataPath("data/compile/multi_light.shader") +
                                   " -o " + dir + "/x.kpack --max-variants 2 --no-cache");
    EXPECT_EQ(many.exit_code, 1);
    EXPECT_NE(many.err.find("3 = 3 variants in pass \"FORWARD_DELTA\", over the limit of 2"),
              std::string::npos)
        << many.err;
}

TEST(Cli, InfoRejectsDamagedPacks) {
    const std::string good = testing::TempDir() + "/kiln_cli_good.kpack";
    ASSERT_EQ(RunKiln("compile " + DataPath("data/compile/multi_light.shader") + " -o " + good +
                      " --no-cache")
                  .exit_code,
              0);
    std::string bytes = ReadFile(good);
    const std::string truncated = WriteTemp("trunc.kpack", bytes.substr(0, bytes.size() / 2));
    RunResult r = RunKiln("info " + truncated);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("pack is truncated"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("[K0018]"), std::string::npos) << r.err;
    bytes[bytes.size() / 2] ^= 0x10;
    const std::string flipped = WriteTemp("flip.kpack", bytes);
    r = RunKiln("info " + flipped);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("checksum does not match"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("[K0021]"), std::string::npos) << r.err;
    r = RunKiln("info " + DataPath("data/compile/light.cginc"));
    EXPECT_NE(r.err.find("not a kiln pack"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("[K0019]"), std::string::npos) << r.err;
}

// The runtime's warnings reach the user as diagnostics with their own codes, about the file they
// concern, and do not fail the render.
TEST(Cli, RenderWarningsHaveCodesAndNameTheScene) {
    const std::string scene = DataPath("cli/mistakes/triangle.gltf");
    const std::string out = testing::TempDir() + "/kiln_cli_warning.png";
    RunResult r = RunKiln("render " + scene + " --width 32 --height 24 -o " + out);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find(scene + ": warning: the scene has no KHR_lights_punctual lights"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("[K0014]"), std::string::npos) << r.err;
    r = RunKiln("render " + scene + " --width 32 --height 24 --no-default-light -o " + out);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("K0014"), std::string::npos) << r.err;
}

TEST(Cli, VariantsReportsDedup) {
    const RunResult r = RunKiln("variants " + DataPath("data/compile/multi_light.shader"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("3 permutations, 3 variants; unique programs: vertex 1, fragment 2"),
              std::string::npos)
        << r.out;
}

TEST(Cli, NewWritesEachScaffoldThatThenCompilesAndRefusesToOverwrite) {
    ScratchDir dir;
    for (const std::string t : {"lit", "unlit", "pbs", "multilight"}) {
        const std::string out = dir.path() + "/" + t + ".shader";
        const RunResult r = RunKiln("new --template " + t + " Game/My" + t + " -o " + out);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(ReadFile(out).find("Shader \"Game/My" + t + "\""), std::string::npos);
        const RunResult c = RunKiln("compile " + out + " -o " + dir.path() + "/" + t + ".kpack");
        EXPECT_EQ(c.exit_code, 0) << c.err;
        EXPECT_EQ(c.err, "") << "scaffolds compile without warnings";
        const RunResult again = RunKiln("new --template " + t + " Game/My" + t + " -o " + out);
        EXPECT_EQ(again.exit_code, 1);
        EXPECT_NE(again.err.find("file exists; pass --force to overwrite"), std::string::npos);
    }
    EXPECT_EQ(RunKiln("new --template fancy X -o " + dir.path() + "/x.shader").exit_code, 2);
}

TEST(Cli, ValidateReportsMaterialErrorsAtTheirPositions) {
    ScratchDir dir;
    const std::string pack = dir.path() + "/m.kpack";
    ASSERT_EQ(
        RunKiln("compile " + DataPath("../materials/Lambert.shader") + " -o " + pack).exit_code, 0);
    const std::string good = dir.Write("good.material",
                                       "{\"shader\": \"Kiln/Lambert\", \"properties\": "
                                       "{\"_Color\": [1, 0, 0]}}\n");
    EXPECT_EQ(RunKiln("validate --pack " + pack + " " + good).exit_code, 0);
    const std::string bad = dir.Write("bad.material",
                                      "{\n  \"shader\": \"Kiln/Lambert\",\n  \"properties\": "
                                      "{\"_Colour\": [1, 0, 0]}\n}\n");
    const RunResult r = RunKiln("validate --pack " + pack + " " + bad);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("bad.material:3:18: error: shader 'Kiln/Lambert' has no property "
                         "'_Colour' [K6007]"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("note: did you mean '_Color'"), std::string::npos) << r.err;
}

TEST(Cli, VariantsReportsExpansionErrorsWithoutCrashing) {
    // Used to segfault: analysis mode merged job diagnostics when no job had been made.
    const std::string kernel = WriteTemp("kernel.shader", R"(Shader "T/G" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex v
    #pragma kernel g
    #pragma fragment f
    ENDCG
} } })");
    RunResult r = RunKiln("variants " + kernel);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("[K4002]"), std::string::npos) << r.err;
    const std::string many = WriteTemp("many.shader", R"(Shader "T/M" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex v
    #pragma fragment f
    #pragma multi_compile A B C
    #pragma multi_compile _ D
    float4 v(float4 p : POSITION) : SV_POSITION { return p; }
    float4 f() : SV_Target { return 1; }
    ENDCG
} } })");
    r = RunKiln("variants --max-variants 4 " + many);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("3 x 2 = 6 variants"), std::string::npos) << r.err;
    r = RunKiln("variants --json --max-variants 4 " + many);
    EXPECT_EQ(r.exit_code, 1) << r.err;
}

TEST(Cli, MaterialsChooseTheShaderFeatureCombinations) {
    const std::string shader = WriteTemp("features.shader", R"(Shader "T/F" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex v
    #pragma fragment f
    #pragma shader_feature _A
    #pragma shader_feature _B
    #pragma multi_compile X Y
    float4 v(float4 p : POSITION) : SV_POSITION { return p; }
    float4 f() : SV_Target {
        float4 c = 0;
    #ifdef _A
        c.r = 1;
    #endif
    #ifdef _B
        c.g = 1;
    #endif
    #ifdef Y
        c.b = 1;
    #endif
        return c;
    }
    ENDCG
} } })");
    const std::string material =
        WriteTemp("features_ab.material",
                  R"({"kiln_material": 1, "shader": "T/F", "keywords": ["_A", "_B"]})");
    const std::string pack = testing::TempDir() + "/kiln_cli_features.kpack";
    auto variants = [&](const std::string& flags) {
        const RunResult r = RunKiln("compile " + shader + " -o " + pack + " --no-cache " + flags);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const RunResult info = RunKiln("info --json " + pack);
        return nlohmann::json::parse(info.out)["shaders"][0]["passes"][0]["variants"].size();
    };
    EXPECT_EQ(variants(""), 2u);                         // all-off x {X, Y}
    EXPECT_EQ(variants("--materials " + material), 4u);  // + _A _B
    EXPECT_EQ(variants("--keywords _B"), 4u);            // + _B
    EXPECT_EQ(variants("--all-features"), 8u);
    const RunResult bad = RunKiln("compile " + shader + " -o " + pack + " --materials " +
                                  WriteTemp("broken.material", "{\"shader\": 3}"));
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("broken.material:1:"), std::string::npos) << bad.err;
}

// --stats=json: the counts, each phase's milliseconds and peak memory as one object. A cold
// compile spends time in every phase, the phases add up to at most the total, and the workers
// (which ran glslang) are counted once they have ended; a warm one compiles nothing.
TEST(Cli, StatsAsJsonTimeEveryPhaseAndCountTheCache) {
    const std::string dir = testing::TempDir() + "/kiln_cli_stats";
    std::filesystem::remove_all(dir);
    const std::string cmd = "compile " + DataPath("data/compile/multi_light.shader") + " -o " +
                            dir + "/out.kpack --cache-dir " + dir + "/cache --stats=json";
    const RunResult cold = RunKiln(cmd);
    ASSERT_EQ(cold.exit_code, 0) << cold.err;
    const nlohmann::json c = nlohmann::json::parse(cold.out);
    EXPECT_EQ(c["variants"], 3);
    EXPECT_EQ(c["glslang_compiles"], 3);
    EXPECT_EQ(c["cache_hits"], 0);
    double sum = 0;
    for (const char* phase : {"load", "expand", "preprocess", "compile", "finish", "emit"}) {
        EXPECT_GT(c["ms"][phase].get<double>(), 0.0) << phase;
        sum += c["ms"][phase].get<double>();
    }
    EXPECT_LE(sum, c["ms"]["total"].get<double>());
    EXPECT_GT(c["peak_rss_kib"].get<uint64_t>(), 0u);
    EXPECT_GT(c["peak_worker_rss_kib"].get<uint64_t>(), 0u);
    const RunResult warm = RunKiln(cmd);
    ASSERT_EQ(warm.exit_code, 0) << warm.err;
    const nlohmann::json w = nlohmann::json::parse(warm.out);
    EXPECT_EQ(w["glslang_compiles"], 0);
    EXPECT_EQ(w["cache_hits"], 3);
    EXPECT_EQ(RunKiln(cmd + " --stats=xml").exit_code, 2);
    std::filesystem::remove_all(dir);
}

// Several kiln processes may share a cache: two cold compiles of one shader at once each write
// their own file of modules and the last rename wins, so both packs are right and a third compile
// takes every module from the cache.
TEST(Cli, TwoCompilesAtOnceShareACache) {
    const std::string dir = testing::TempDir() + "/kiln_cli_shared_cache";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string shader = DataPath("data/compile/multi_light.shader");
    const RunResult clean = RunKiln("compile " + shader + " -o " + dir + "/clean.kpack --no-cache");
    ASSERT_EQ(clean.exit_code, 0) << clean.err;
    auto compile = [&](const std::string& out) {
        return RunKiln("compile " + shader + " -o " + dir + "/" + out + " --cache-dir " + dir +
                       "/cache --stats=json");
    };
    auto a = std::async(std::launch::async, compile, "a.kpack");
    auto b = std::async(std::launch::async, compile, "b.kpack");
    const RunResult ra = a.get(), rb = b.get();
    ASSERT_EQ(ra.exit_code, 0) << ra.err;
    ASSERT_EQ(rb.exit_code, 0) << rb.err;
    EXPECT_EQ(ReadFile(dir + "/a.kpack"), ReadFile(dir + "/clean.kpack"));
    EXPECT_EQ(ReadFile(dir + "/b.kpack"), ReadFile(dir + "/clean.kpack"));
    size_t temporaries = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir + "/cache")) {
        temporaries += e.path().string().find(".tmp.") != std::string::npos;
        if (e.path().extension() == ".kpack")
            std::filesystem::remove(e.path());  // so that the modules are read
    }
    EXPECT_EQ(temporaries, 0u);
    const RunResult c = compile("c.kpack");
    ASSERT_EQ(c.exit_code, 0) << c.err;
    EXPECT_EQ(nlohmann::json::parse(c.out)["glslang_compiles"], 0);
    EXPECT_EQ(ReadFile(dir + "/c.kpack"), ReadFile(dir + "/clean.kpack"));
    std::filesystem::remove_all(dir);
}

TEST(Cli, UnityVersionMustBeAVersion) {
    // Accepted spellings get past the command line (the missing file is an input error).
    for (const char* v : {"2022.3", "2019.4.40", "202230"}) {
        EXPECT_EQ(
            RunKiln(std::string("compile /nonexistent.shader -o x.kpack --unity-version ") + v)
                .exit_code,
            1)
            << v;
    }
    EXPECT_EQ(RunKiln("compile /nonexistent.shader -o x.kpack --unity-version 2022.").exit_code, 2);
    const RunResult r = RunKiln("compile x.shader -o x.kpack --unity-version latest");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("2022.3"), std::string::npos) << r.err;
}

// A kiln copied away from its share/kiln folder says what it is missing, once, instead of one
// "cannot find include file" per program.
TEST(Cli, KilnWithoutItsTemplatesSaysWhereItLooked) {
    ScratchDir dir;
    std::filesystem::create_directories(dir.path() + "/bin");
    std::filesystem::copy_file(KILN_BINARY, dir.path() + "/bin/kiln");
    const std::string err = dir.path() + "/err.txt";
    const std::string cmd = "env -u KILN_TEMPLATES_DIR " + dir.path() + "/bin/kiln compile " +
                            DataPath("data/compile/multi_light.shader") + " -o " + dir.path() +
                            "/out.kpack 2>" + err;
    const int status = std::system(cmd.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1);
    EXPECT_EQ(ReadFile(err),
              "kiln: error: cannot find Kiln's templates (UnityCG.cginc and the other built-in "
              "includes): not in ../share/kiln/templates beside the program; set "
              "KILN_TEMPLATES_DIR or --templates-dir [K0001]\n");
    EXPECT_FALSE(std::filesystem::exists(dir.path() + "/out.kpack"));
}

// kiln itself links no renderer: `kiln render` is kiln-render beside it, and without it the
// command says so (K0025) instead of failing to start for a missing libvulkan.
TEST(Cli, RenderRunsKilnRenderBesideKilnAndSaysWhenItIsMissing) {
    ScratchDir dir;
    std::filesystem::copy_file(KILN_BINARY, dir.path() + "/kiln");
    const std::string err = dir.path() + "/err.txt";
    const std::string cmd = dir.path() + "/kiln --diagnostics-format=json render " +
                            DataPath("cli/mistakes/triangle.gltf") + " -o " + dir.path() +
                            "/out.png 2>" + err;
    const int status = std::system(cmd.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1);
    const std::string text = ReadFile(err);
    EXPECT_NE(text.find("\"code\": \"K0025\""), std::string::npos) << text;
    EXPECT_NE(text.find(dir.path() + "/kiln-render"), std::string::npos) << text;
    EXPECT_FALSE(std::filesystem::exists(dir.path() + "/out.png"));
}

// Unity resolves `#include "Assets/..."` from the project's root folder. Kiln finds the root
// above the Assets folder the shader is in; a shader outside one gets a note naming
// --project-root, and with it compiles.
TEST(Cli, AssetsIncludesResolveFromTheProjectRoot) {
    const std::string root = FreshTempDir("project_root");
    const std::string shader = R"(Shader "T/Project" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex v
    #pragma fragment f
    #include "Assets/Shared/Common.cginc"
    float4 v(float4 p : POSITION) : SV_POSITION { return p; }
    float4 f() : SV_Target { return SharedColour(); }
    ENDCG
} } })";
    std::filesystem::create_directories(root + "/Project/Assets/Shared");
    std::filesystem::create_directories(root + "/Project/Assets/Shaders");
    WriteFile(root + "/Project/Assets/Shared/Common.cginc",
              "float4 SharedColour() { return float4(1, 0, 0, 1); }\n");
    WriteFile(root + "/Project/Assets/Shaders/in.shader", shader);
    WriteFile(root + "/out.shader", shader);
    RunResult r =
        RunKiln("compile " + root + "/Project/Assets/Shaders/in.shader -o " + root + "/in.kpack");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = RunKiln("compile " + root + "/out.shader -o " + root + "/out.kpack");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("cannot find include file 'Assets/Shared/Common.cginc'"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("otherwise pass --project-root DIR"), std::string::npos) << r.err;
    r = RunKiln("compile " + root + "/out.shader --project-root " + root + "/Project -o " + root +
                "/out.kpack");
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

}  // namespace
}  // namespace kiln::test
