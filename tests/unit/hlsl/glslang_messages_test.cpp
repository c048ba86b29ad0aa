#include "frontend/glslang_messages.h"

#include <gtest/gtest.h>

namespace kiln::frontend {
namespace {

TEST(GlslangMessages, ParsesLocationsTokensAndDropsCascades) {
    const std::string log =
        "ERROR: dir/a b.shader:12: 'x' : undeclared identifier \n"
        "ERROR: dir/a b.shader:12: '' : compilation terminated \n"
        "ERROR: inc.cginc:3: ';' : Expected \n"
        "inc.cginc(3): error at column 7, HLSL parsing failed.\n"
        "ERROR: 3 compilation errors.  No code generated.\n"
        "WARNING: c.shader:1: 'w' : something odd\n";
    auto msgs = ParseInfoLog(log);
    ASSERT_EQ(msgs.size(), 3u);
    EXPECT_EQ(msgs[0].file, "dir/a b.shader");
    EXPECT_EQ(msgs[0].line, 12u);
    EXPECT_EQ(msgs[0].token, "x");
    EXPECT_EQ(msgs[1].file, "inc.cginc");
    EXPECT_EQ(msgs[1].column, 7u);
    EXPECT_EQ(msgs[2].severity, Severity::kWarning);
}

// A stray top-level '}' gets only the column line: once dropped, it left no diagnostic and the
// compile ended in an internal compiler error.
TEST(GlslangMessages, AColumnLineWithoutItsErrorIsTheError) {
    auto msgs = ParseInfoLog(
        "s.shader(22): error at column 13, HLSL parsing failed.\n"
        "ERROR: 1 compilation errors.  No code generated.\n");
    ASSERT_EQ(msgs.size(), 1u);
    EXPECT_EQ(msgs[0].file, "s.shader");
    EXPECT_EQ(msgs[0].line, 22u);
    EXPECT_EQ(msgs[0].column, 13u);
    EXPECT_EQ(msgs[0].severity, Severity::kError);
    EXPECT_EQ(RewordMessage(msgs[0].token, msgs[0].text), "syntax error");
}

TEST(GlslangMessages, RewordsIntoHouseStyle) {
    EXPECT_EQ(RewordMessage(";", "Expected"), "expected ';'");
    EXPECT_EQ(RewordMessage("foo", "undeclared identifier"), "undeclared identifier 'foo'");
    EXPECT_EQ(
        RewordMessage(
            "=", " cannot convert from ' const float'  to ' temp 4-component vector of float'"),
        "cannot convert from 'float' to 'float4'");
    EXPECT_EQ(RewordMessage("=",
                            "cannot convert from ' temp 3-component vector of float' to ' "
                            "temp 4-component vector of float'"),
              "cannot convert from 'float3' to 'float4'");
    EXPECT_EQ(
        RewordMessage("f", "no matching overloaded function found: uniform 4X4 matrix of float"),
        "no matching overloaded function found: uniform 4X4 matrix of float 'f'");
    EXPECT_EQ(RewordMessage("", "Missing entry point."), "missing entry point");
}

TEST(GlslangMessages, ColumnFromTheTokenOnTheLine) {
    auto file = std::make_shared<const SourceFile>("f.shader", "a\n  float4 c = undefined_name;\n");
    GlslangMessage m;
    m.file = "f.shader";
    m.line = 2;
    m.token = "undefined_name";
    m.text = "unknown variable";
    Diagnostic d = ToDiagnostic(m, [&](const std::string&) { return file; });
    EXPECT_EQ(d.range.begin.line, 2u);
    EXPECT_EQ(d.range.begin.column, 14u);
    EXPECT_EQ(d.range.end.column, 28u);
    EXPECT_EQ(d.message, "unknown variable 'undefined_name'");
    m.line = 99;  // past the end: no crash, position kept
    d = ToDiagnostic(m, [&](const std::string&) { return file; });
    EXPECT_EQ(d.range.begin.line, 99u);
}

}  // namespace
}  // namespace kiln::frontend
