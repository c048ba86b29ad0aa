// Malformed inputs: each must produce its first error with an exact code, line and column, and
// the parser must still return (no crash, no hang).
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace kiln::test {
namespace {

// Snippets are placed so that their first character is at line 3 (Properties, SubShader level)
// or line 4 (Pass level), column 1.
std::string InProperties(const std::string& s) {
    return "Shader \"x\" {\nProperties {\n" + s + "\n}\n}\n";
}
std::string InSubShader(const std::string& s) {
    return "Shader \"x\" {\nSubShader {\n" + s + "\n}\n}\n";
}
std::string InPass(const std::string& s) {
    return "Shader \"x\" {\nSubShader {\nPass {\n" + s + "\n}\n}\n}\n";
}

struct ErrorCase {
    const char* name;
    std::string source;
    DiagCode code;
    uint32_t line;
    uint32_t column;
};

std::vector<ErrorCase> Cases() {
    return {
        {"empty_file", "", DiagCode::kExpectedShader, 1, 1},
        {"not_a_shader", "Material { }", DiagCode::kExpectedShader, 1, 1},
        {"missing_name", "Shader {\n}", DiagCode::kExpectedToken, 1, 8},
        {"missing_body", "Shader \"x\"", DiagCode::kExpectedToken, 1, 11},
        {"unclosed_shader", "Shader \"x\" {\n  SubShader { }\n", DiagCode::kUnclosedBlock, 3, 1},
        {"unterminated_string", "Shader \"x {\n}\n", DiagCode::kUnterminatedString, 1, 8},
        {"unterminated_comment", "Shader \"x\" { /* never closed\n", DiagCode::kUnterminatedComment,
         1, 14},
        {"unterminated_program", InPass("  CGPROGRAM\n  float4 x;"),
         DiagCode::kUnterminatedProgramBlock, 4, 3},
        {"stray_endcg", InPass("  ENDCG"), DiagCode::kStrayProgramEnd, 4, 3},
        {"unexpected_character", InPass("  @ Cull Back"), DiagCode::kUnexpectedCharacter, 4, 3},
        {"trailing_content", "Shader \"x\" { }\n}\n", DiagCode::kUnexpectedToken, 2, 1},
        {"unknown_property_type", InProperties("_A (\"A\", Colour) = (1, 1, 1, 1)"),
         DiagCode::kUnknownPropertyType, 3, 10},
        {"float_with_texture_default", InProperties("_A (\"A\", Float) = \"white\""),
         DiagCode::kBadPropertyDefault, 3, 19},
        {"color_with_two_components", InProperties("_A (\"A\", Color) = (1, 1)"),
         DiagCode::kBadPropertyDefault, 3, 19},
        {"texture_with_number_default", InProperties("_T (\"T\", 2D) = 1"),
         DiagCode::kBadPropertyDefault, 3, 16},
        {"range_missing_comma", InProperties("_A (\"A\", Range(0 1)) = 0"),
         DiagCode::kExpectedToken, 3, 18},
        {"property_missing_paren", InProperties("_A \"A\", Float) = 1"), DiagCode::kExpectedToken,
         3, 4},
        {"property_missing_default", InProperties("_A (\"A\", Float)\n_B (\"B\", Float) = 1"),
         DiagCode::kExpectedToken, 4, 1},
        {"toggle_two_args", InProperties("[Toggle(A, B)] _A (\"A\", Float) = 0"),
         DiagCode::kBadAttribute, 3, 1},
        {"power_slider_not_number", InProperties("[PowerSlider(abc)] _A (\"A\", Range(0, 1)) = 0"),
         DiagCode::kBadAttribute, 3, 1},
        {"enum_value_not_number", InProperties("[Enum(One, x)] _A (\"A\", Float) = 0"),
         DiagCode::kBadAttribute, 3, 1},
        {"duplicate_property", InProperties("_A (\"A\", Float) = 0\n_A (\"A2\", Float) = 1"),
         DiagCode::kDuplicateProperty, 4, 1},
        {"duplicate_properties_block", "Shader \"x\" {\nProperties { }\nProperties { }\n}\n",
         DiagCode::kDuplicateCommand, 3, 1},
        {"bad_cull_value", InPass("  Cull Sideways"), DiagCode::kInvalidValue, 4, 8},
        {"bad_ztest_value", InSubShader("ZTest Sometimes"), DiagCode::kInvalidValue, 3, 7},
        {"bad_blend_factor", InPass("  Blend One Two"), DiagCode::kInvalidValue, 4, 13},
        {"bad_render_target", InPass("  Blend 9 One One"), DiagCode::kBadRenderTarget, 4, 9},
        {"bad_color_mask", InPass("  ColorMask RGBR"), DiagCode::kInvalidValue, 4, 13},
        {"offset_missing_units", InPass("  Offset 1\n  Cull Back"), DiagCode::kExpectedToken, 5, 3},
        {"stencil_ref_out_of_range", InPass("  Stencil { Ref 256 }"), DiagCode::kInvalidValue, 4,
         17},
        {"stencil_unknown_key", InPass("  Stencil { Bogus 1 }"), DiagCode::kUnknownCommand, 4, 13},
        {"texture_property_as_state",
         "Shader \"x\" {\nProperties { _T (\"T\", 2D) = \"white\" {} }\nSubShader { Cull [_T] "
         "}\n}\n",
         DiagCode::kPropertyRefType, 3, 18},
        {"unknown_command", InSubShader("Pas { }"), DiagCode::kUnknownCommand, 3, 1},
        {"pass_at_shader_level", "Shader \"x\" {\n  Pass { }\n}\n", DiagCode::kMisplacedCommand, 2,
         3},
        {"name_in_subshader", InSubShader("Name \"X\""), DiagCode::kMisplacedCommand, 3, 1},
        {"negative_lod", InSubShader("LOD -1"), DiagCode::kExpectedToken, 3, 5},
        {"tag_missing_equals", InPass("  Tags { \"A\" \"B\" }"), DiagCode::kExpectedToken, 4, 14},
        {"fallback_number", "Shader \"x\" {\nFallback 12\n}\n", DiagCode::kExpectedToken, 2, 10},
        {"glsl_program", InPass("  GLSLPROGRAM\n  void main() {}\n  ENDGLSL"),
         DiagCode::kUnsupportedGlsl, 4, 3},
        {"surface_in_pass", InPass("CGPROGRAM\n  #pragma surface surf Lambert\nENDCG"),
         DiagCode::kBadSurfaceShader, 5, 3},
        {"program_outside_pass", InSubShader("CGPROGRAM\nENDCG"), DiagCode::kProgramOutsidePass, 3,
         1},
        {"two_programs_in_pass", InPass("CGPROGRAM\nENDCG\nHLSLPROGRAM\nENDHLSL"),
         DiagCode::kMultiplePrograms, 6, 1},
    };
}

void PrintTo(const ErrorCase& c, std::ostream* os) {
    *os << c.name;
}

class ParserErrorTest : public testing::TestWithParam<ErrorCase> {};

TEST_P(ParserErrorTest, ReportsFirstErrorAtExactPosition) {
    const ErrorCase& c = GetParam();
    ParseOutcome out = ParseText(c.source);
    ASSERT_TRUE(out.diags.has_errors()) << "no error for:\n" << c.source;
    const Diagnostic* first = nullptr;
    for (const Diagnostic& d : out.diags.all()) {
        if (d.severity == Severity::kError) {
            first = &d;
            break;
        }
    }
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(FormatDiagCode(first->code), FormatDiagCode(c.code)) << Summarize(out.diags);
    EXPECT_EQ(first->range.begin.line, c.line) << Summarize(out.diags);
    EXPECT_EQ(first->range.begin.column, c.column) << Summarize(out.diags);
    EXPECT_EQ(first->file, "test.shader");
    // Messages follow the house style: lower-case start, no trailing period.
    ASSERT_FALSE(first->message.empty());
    EXPECT_FALSE(first->message.front() >= 'A' && first->message.front() <= 'Z') << first->message;
    EXPECT_NE(first->message.back(), '.') << first->message;
}

INSTANTIATE_TEST_SUITE_P(Malformed,
                         ParserErrorTest,
                         testing::ValuesIn(Cases()),
                         [](const testing::TestParamInfo<ErrorCase>& param) {
                             return std::string(param.param.name);
                         });

TEST(ParserRecovery, ReportsSeveralIndependentErrorsInOneRun) {
    ParseOutcome out =
        ParseText(InPass("  Cull Sideways\n  ZWrite Maybe\n  Blend One Two\n"
                         "  Name \"OK\""));
    EXPECT_EQ(out.diags.error_count(), 3u) << Summarize(out.diags);
    ASSERT_TRUE(out.shader);
    // The valid command after the errors is still in the tree.
    const auto& sub = std::get<shaderlab::SubShader>(out.shader->subshaders.at(0));
    EXPECT_EQ(std::get<shaderlab::Pass>(sub.passes.at(0)).name, "OK");
}

TEST(ParserRecovery, UnclosedBlockNotePointsAtTheOpeningBrace) {
    ParseOutcome out = ParseText("Shader \"x\" {\n  SubShader {\n    Pass {\n");
    ASSERT_EQ(out.diags.error_count(), 1u) << Summarize(out.diags);
    const Diagnostic& d = out.diags.all()[0];
    EXPECT_EQ(d.code, DiagCode::kUnclosedBlock);
    EXPECT_NE(d.message.find("'Pass'"), std::string::npos);
    ASSERT_EQ(d.notes.size(), 1u);
    EXPECT_EQ(d.notes[0].range.begin.line, 3u);
    EXPECT_EQ(d.notes[0].range.begin.column, 10u);
}

TEST(ParserRecovery, FailedPropertyDoesNotCascadeIntoUndeclaredReferences) {
    ParseOutcome out = ParseText(
        "Shader \"x\" {\nProperties { _Src (\"S\", Flaot) = 1 }\nSubShader { Blend [_Src] One "
        "}\n}\n");
    EXPECT_EQ(out.diags.error_count(), 1u) << Summarize(out.diags);
    EXPECT_EQ(out.diags.all()[0].code, DiagCode::kUnknownPropertyType);
}

TEST(ParserRecovery, ErrorCountIsCapped) {
    std::string body;
    for (int i = 0; i < 500; ++i) {
        body += "  Cull Bad\n";
    }
    ParseOutcome out = ParseText(InPass(body));
    EXPECT_EQ(out.diags.all().back().code, DiagCode::kTooManyErrors);
    EXPECT_LE(out.diags.all().size(), DiagnosticList::kDefaultErrorLimit + 1);
}

}  // namespace
}  // namespace kiln::test
