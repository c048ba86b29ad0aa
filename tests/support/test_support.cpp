#include "support/test_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>
#include <xxhash.h>

#include "kiln/pack/format.h"
#include "kiln/pack/seal.h"

namespace kiln::test {

::testing::AssertionResult OpenInto(std::span<const uint8_t> bytes, pack::Pack& out) {
    return Into(pack::Pack::Open(bytes), out);
}

::testing::AssertionResult MapInto(const std::string& path, pack::MappedFile& out) {
    return Into(pack::MappedFile::Map(path), out);
}

std::string ReadFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error("cannot read " + path);
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string FreshTempDir(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

void WriteFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::string DataPath(const std::string& relative) {
    return std::string(KILN_TEST_DATA_DIR) + "/" + relative;
}

void ResealPack(std::span<uint8_t> bytes) {
    pack::Seal(bytes);
}

RunResult RunKiln(const std::string& args) {
    return RunKilnWithin(args, 0);
}

RunResult RunKilnWithin(const std::string& args, int seconds) {
    return RunProgram(KILN_BINARY, args, seconds);
}

RunResult RunProgram(const std::string& binary, const std::string& args, int seconds) {
    // ctest runs tests in parallel: each test and call gets its own capture files.
    static int call = 0;
    const testing::TestInfo* test = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = test != nullptr ? test->name() : "suite_setup";
    std::replace(name.begin(), name.end(), '/', '_');  // parameterized tests: "Test/param"
    const std::string stem =
        testing::TempDir() + "/kiln_cli_" + name + "_" + std::to_string(call++);
    const std::string out_path = stem + ".out";
    const std::string err_path = stem + ".err";
    const std::string limit =
        seconds > 0 ? "timeout -s KILL " + std::to_string(seconds) + " " : std::string();
    const std::string cmd = limit + binary + " " + args + " >" + out_path + " 2>" + err_path;
    const int status = std::system(cmd.c_str());
    RunResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = ReadFile(out_path);
    r.err = ReadFile(err_path);
    return r;
}

ParseOutcome ParseText(const std::string& text, const std::string& name) {
    ParseOutcome out;
    const SourceFile file(name, text);
    out.shader = shaderlab::ParseAndCheck(file, out.diags);
    return out;
}

std::string Summarize(const DiagnosticList& diags) {
    std::string s;
    for (const Diagnostic& d : diags.all()) {
        s += FormatDiagCode(d.code) + " " + std::to_string(d.range.begin.line) + ":" +
             std::to_string(d.range.begin.column) + " " + std::string(SeverityName(d.severity)) +
             ": " + d.message + "\n";
        for (const DiagnosticNote& n : d.notes) {
            s += "  note " + std::to_string(n.range.begin.line) + ":" +
                 std::to_string(n.range.begin.column) + ": " + n.message + "\n";
        }
    }
    return s;
}

std::string MakeStressShader(size_t min_bytes, size_t depth) {
    std::string s = "// generated stress input\nShader \"Stress/Big\" {\n  Properties {\n";
    for (int i = 0; i < 200; ++i) {
        s += "    [HDR] _Color" + std::to_string(i) + " (\"Color " + std::to_string(i) +
             "\", Color) = (1, 0.5, 0.25, 1)\n";
        s += "    [Enum(One, 1, Zero, 0)] _Mode" + std::to_string(i) + " (\"Mode\", Float) = 1\n";
    }
    s += "  }\n";
    for (size_t d = 0; d < depth; ++d) {
        s += std::string(d * 2 + 2, ' ') + "Category { Cull Back\n";
    }
    int pass = 0;
    while (s.size() < min_bytes) {
        s += "  SubShader { Tags { \"RenderType\" = \"Opaque\" } LOD 200\n";
        for (int p = 0; p < 4; ++p, ++pass) {
            s += "    Pass { Name \"P" + std::to_string(pass) + "\"\n";
            s += "      Tags { \"LightMode\" = \"ForwardAdd\" }\n";
            s += "      Blend [_Mode0] One, One Zero\n      ZWrite Off ZTest LEqual\n";
            s += "      Stencil { Ref 1 Comp Always Pass Replace }\n";
            s += "      CGPROGRAM\n      #pragma vertex vert\n      #pragma fragment frag\n";
            s += "      #pragma multi_compile DIRECTIONAL POINT SPOT\n";
            for (int l = 0; l < 20; ++l) {
                s += "      float4 f" + std::to_string(l) +
                     "(float4 x) { return x * 2.0 + float4(1, 2, 3, 4); } // { not a brace }\n";
            }
            s += "      ENDCG\n    }\n";
        }
        s += "  }\n";
    }
    for (size_t d = depth; d > 0; --d) {
        s += std::string(d * 2, ' ') + "}\n";
    }
    s += "  Fallback Off\n}\n";
    return s;
}

}  // namespace kiln::test
