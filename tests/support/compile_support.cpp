#include "support/compile_support.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_support.h"

namespace kiln::test {
namespace fs = std::filesystem;

ScratchDir::ScratchDir() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    path_ = (fs::path(testing::TempDir()) / "kiln_scratch" /
             (std::string(info->test_suite_name()) + "." + info->name()))
                .string();
    fs::remove_all(path_);
    fs::create_directories(path_);
}

std::string ScratchDir::Write(const std::string& name, const std::string& text) const {
    const fs::path p = fs::path(path_) / name;
    fs::create_directories(p.parent_path());
    WriteFile(p.string(), text);
    return p.string();
}

CompileRun Compile(const std::vector<std::string>& files, CompileOptions options) {
    CompileRun run;
    run.out = CompileShaders(files, options, run.diags);
    return run;
}

std::string Brief(const DiagnosticList& diags) {
    std::string s;
    for (const Diagnostic& d : diags.all()) {
        s += fs::path(d.file).filename().string() + ":" + std::to_string(d.range.begin.line) + ":" +
             std::to_string(d.range.begin.column) + " " + FormatDiagCode(d.code) + " " + d.message +
             "\n";
        for (const DiagnosticNote& n : d.notes)
            s += "  note: " + n.message + "\n";
    }
    return s;
}

std::string PassShader(const std::string& pragmas,
                       const std::string& extra_code,
                       const std::string& include) {
    return "Shader \"Test/Pass\" {\n"
           "    Properties { _Tint (\"Tint\", Color) = (1, 1, 1, 1) }\n"
           "    SubShader {\n"
           "        Pass {\n"
           "            Name \"FORWARD\"\n"
           "            CGPROGRAM\n"
           "            #pragma vertex vert\n"
           "            #pragma fragment frag\n" +
           pragmas + "\n" + include +
           "\n"
           "            float4 _Tint;\n"
           "            float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n" +
           extra_code +
           "            float4 frag() : SV_Target { return _Tint; }\n"
           "            ENDCG\n"
           "        }\n"
           "    }\n"
           "}\n";
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return text;
}

}  // namespace kiln::test
