// The pre-checks before glslang: the limits hold at exactly their value, one past them is an error
// at the place in the .shader file, and comments, strings and self-referential macros do not
// count.
#include <gtest/gtest.h>

#include "hlsl/precheck.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

// Runs the pre-checks over the program of a one-pass shader whose CGPROGRAM body is `body`.
std::string Check(const std::string& body, hlsl::PrecheckLimits limits = {}) {
    const std::string text =
        "Shader \"P\" { SubShader { Pass {\nCGPROGRAM\n" + body + "\nENDCG\n} } }\n";
    ParseOutcome parsed = ParseText(text, "p.shader");
    EXPECT_TRUE(parsed.shader) << Summarize(parsed.diags);
    if (!parsed.shader)
        return "";
    const SourceFile file("p.shader", text);
    const auto& sub = std::get<shaderlab::SubShader>(parsed.shader->subshaders.at(0));
    const auto& block = std::get<shaderlab::Pass>(sub.passes.at(0)).programs.at(0);
    DiagnosticList diags;
    hlsl::Prechecker checker(file, limits, diags);
    checker.CheckPass({&block});
    checker.CheckPass({&block});  // a block shared by a second pass is reported once
    return Summarize(diags);
}

std::string Repeat(const std::string& s, size_t n) {
    std::string out;
    for (size_t i = 0; i < n; ++i)
        out += s;
    return out;
}

TEST(Precheck, NestingUpToTheLimitPassesAndOneMoreIsAnErrorAtThatBracket) {
    hlsl::PrecheckLimits limits;
    limits.max_nesting = 8;
    EXPECT_EQ(Check("float f() { return " + Repeat("(", 7) + "1" + Repeat(")", 7) + "; }", limits),
              "");
    const std::string s =
        Check("float f() { return " + Repeat("(", 8) + "1" + Repeat(")", 8) + "; }", limits);
    EXPECT_NE(s.find("K5012 3:27 error: brackets nested more than 8 deep"), std::string::npos) << s;
    EXPECT_EQ(s.find("K5012", s.find("K5012") + 1), std::string::npos) << "reported once: " << s;
}

TEST(Precheck, BracketsInCommentsStringsAndDirectivesOfOtherLinesDoNotCount) {
    hlsl::PrecheckLimits limits;
    limits.max_nesting = 4;
    EXPECT_EQ(Check("// " + Repeat("(", 50) + "\n/* " + Repeat("{", 50) + " */\n#define S \"" +
                        Repeat("[", 50) + "\"\nfloat f() { return 1; }",
                    limits),
              "");
    // A directive's brackets start from zero and do not carry into the program text.
    EXPECT_EQ(Check("#if ((((1))))\n#endif\nfloat f() { return (((1))); }", limits), "");
    EXPECT_NE(Check("#if (((((1)))))\n#endif\n", limits).find("K5012 3:9"), std::string::npos);
}

TEST(Precheck, ConditionalsNestedPastTheLimitAreAnError) {
    hlsl::PrecheckLimits limits;
    limits.max_nesting = 3;
    EXPECT_EQ(Check(Repeat("#ifdef A\n", 3) + Repeat("#endif\n", 3), limits), "");
    const std::string s = Check(Repeat("#ifdef A\n", 4) + Repeat("#endif\n", 4), limits);
    EXPECT_NE(s.find("K5012 6:1 error: #if directives nested more than 3 deep"), std::string::npos)
        << s;
}

TEST(Precheck, AnExpressionOfTooManyOperatorsIsAnErrorAtItsStart) {
    hlsl::PrecheckLimits limits;
    limits.max_operators = 100;
    std::string terms = "p";
    for (int i = 0; i < 100; ++i)
        terms += "+p";
    EXPECT_EQ(Check("float f(float p) { return " + terms + "; }", limits), "");
    const std::string s = Check("float f(float p) { return " + terms + "*p; }", limits);
    EXPECT_NE(s.find("K5014 3:20 error: an expression with more than 100 operators"),
              std::string::npos)
        << s;
    // Statements and initializer elements each start again.
    std::string list;
    for (int i = 0; i < 300; ++i)
        list += "a+b, ";
    EXPECT_EQ(Check("static const float t[] = { " + list + "0 };", limits), "");
}

TEST(Precheck, AMacroThatDoublesEveryLevelIsAnErrorAtItsUseWithANoteAtItsDefinition) {
    std::string defs = "#define L0(i) (i)\n";
    for (int k = 1; k <= 30; ++k) {
        defs += "#define L" + std::to_string(k) + "(i) (L" + std::to_string(k - 1) + "(i-1)+L" +
                std::to_string(k - 1) + "(i-1))\n";
    }
    EXPECT_EQ(Check(defs + "float f() { return L10(1); }"), "") << "about 16000 tokens";
    const std::string s = Check(defs + "float f() { return L30(1); }");
    EXPECT_NE(s.find("K5013 34:20 error: macro 'L30' expands to about"), std::string::npos) << s;
    EXPECT_NE(s.find("note 33:9: 'L30' is defined here"), std::string::npos) << s;
    // Used in an #if condition it expands too; after #undef it is gone.
    EXPECT_NE(Check(defs + "#if L30(1)\n#endif").find("K5013"), std::string::npos);
    EXPECT_EQ(Check(defs + "#undef L30\nfloat f() { return L30(1); }"), "");
}

TEST(Precheck, SelfReferenceAndLongChainsOfMacrosAreFine) {
    // The C preprocessor does not re-expand a macro inside itself.
    EXPECT_EQ(Check("#define L(i) (L(i-1)+L(i-1))\n#define A B\n#define B A\n"
                    "float f() { return L(1) + A; }"),
              "");
    // 100,000 macros each naming the one before: linear, and no recursion that could overflow.
    std::string chain = "#define M0 1\n";
    for (int k = 1; k < 100000; ++k)
        chain += "#define M" + std::to_string(k) + " M" + std::to_string(k - 1) + "\n";
    EXPECT_EQ(Check(chain + "float f() { return M99999; }"), "");
}

}  // namespace
}  // namespace kiln::test
