// No input may crash, hang or read out of bounds: truncated files, bit flips, binary garbage,
// unterminated constructs and 10,000-deep nesting. Each test also checks that every diagnostic
// range lies inside the file.
#include <gtest/gtest.h>

#include <random>

#include "support/test_support.h"

namespace kiln::test {
namespace {

void ExpectRangesInside(const DiagnosticList& diags, size_t size) {
    for (const Diagnostic& d : diags.all()) {
        EXPECT_LE(d.range.begin.offset, d.range.end.offset) << d.message;
        EXPECT_LE(d.range.end.offset, size) << d.message;
        EXPECT_GE(d.range.begin.line, 1u);
        EXPECT_GE(d.range.begin.column, 1u);
    }
}

ParseOutcome ParseChecked(const std::string& text) {
    ParseOutcome out = ParseText(text);
    ExpectRangesInside(out.diags, text.size());
    return out;
}

TEST(Robustness, EveryTruncatedPrefixOfTheLectureShaders) {
    for (const char* f : {"lecture/07_PhysicallyBased.shader", "lecture/11_SpotLight.shader",
                          "lecture/12_Deferred.shader", "golden/parse/full_structure.shader"}) {
        const std::string text = ReadFile(DataPath(f));
        const size_t last_brace = text.rfind('}');
        for (size_t n = 0; n < text.size(); ++n) {
            ParseOutcome out = ParseChecked(text.substr(0, n));
            // A prefix that lacks the final '}' must be an error.
            if (n <= last_brace) {
                ASSERT_TRUE(out.diags.has_errors()) << f << " prefix " << n;
            }
        }
        EXPECT_FALSE(ParseChecked(text).diags.has_errors()) << f;
    }
}

TEST(Robustness, SingleByteCorruptionsOfAValidShader) {
    const std::string text = ReadFile(DataPath("golden/parse/full_structure.shader"));
    const char replacements[] = {'\0', '{', '}', '"', '[', '(', '/', '*', '\xff', '\n', 'x'};
    for (size_t i = 0; i < text.size(); ++i) {
        for (char r : replacements) {
            std::string mutated = text;
            mutated[i] = r;
            ParseChecked(mutated);
        }
    }
}

TEST(Robustness, RandomBinaryGarbage) {
    std::mt19937 rng(1234);
    for (int round = 0; round < 200; ++round) {
        std::string text(static_cast<size_t>(rng() % 4096), '\0');
        for (char& c : text) {
            c = static_cast<char>(rng() & 0xff);
        }
        if (round % 2 == 0) {
            text = "Shader \"g\" { SubShader { Pass { " + text;  // garbage inside a block
        }
        ParseOutcome out = ParseChecked(text);
        EXPECT_TRUE(out.diags.has_errors());  // no "Shader" keyword, or an unclosed block
    }
}

TEST(Robustness, TenThousandDeepCategoriesGiveOneClearError) {
    const size_t n = 10000;
    std::string text = "Shader \"x\" {\n";
    for (size_t i = 0; i < n; ++i) {
        text += "Category {\n";
    }
    text += std::string(n, '}') + "\n}\n";
    ParseOutcome out = ParseChecked(text);
    ASSERT_EQ(out.diags.all().size(), 1u) << Summarize(out.diags);
    EXPECT_EQ(out.diags.all()[0].code, DiagCode::kNestingTooDeep);
    EXPECT_EQ(out.diags.all()[0].range.begin.line, 65u);  // Shader + 63 Categories fit
}

TEST(Robustness, TenThousandDeepBracesAndBrackets) {
    const size_t n = 10000;
    for (const std::string& open : {std::string("{"), std::string("["), std::string("(")}) {
        ParseChecked("Shader \"x\" { Properties { " + std::string(n, open[0]));
        ParseChecked("Shader \"x\" { SubShader { Pass { Stencil " + std::string(n, open[0]));
        ParseChecked(std::string(n, open[0]));
    }
    // Unclosed deep nesting reports one unclosed-block error, not one per level.
    std::string text = "Shader \"x\" {\n";
    for (size_t i = 0; i < n; ++i) {
        text += "Category {\n";
    }
    ParseOutcome out = ParseChecked(text);
    EXPECT_EQ(out.diags.error_count(), 2u) << Summarize(out.diags);
}

TEST(Robustness, UnterminatedEverything) {
    for (const std::string& text :
         {std::string("Shader \"x"), std::string("Shader \"x\" { Properties { _A (\"a"),
          std::string("Shader \"x\" { /*"),
          std::string("Shader \"x\" { SubShader { Pass { CGPROGRAM"),
          std::string("Shader \"x\" { SubShader { Pass { HLSLPROGRAM ENDCG"),
          std::string("Shader \"x\" { Properties { [Header(abc"),
          std::string("Shader \"x\" { Properties { _R (\"r\", Range(0, "),
          std::string("Shader \"x\" { SubShader { Tags { \"a\" = "),
          std::string("Shader \"x\" { SubShader { Blend 1"),
          std::string("Shader \"x\" { Fallback")}) {
        ParseOutcome out = ParseChecked(text);
        EXPECT_TRUE(out.diags.has_errors()) << text;
    }
}

TEST(Robustness, StressFileOfOneMegabyteParsesCleanly) {
    const std::string text = MakeStressShader(1 << 20, 50);
    ASSERT_GE(text.size(), 1u << 20);
    ParseOutcome out = ParseChecked(text);
    EXPECT_TRUE(out.diags.all().empty()) << Summarize(out.diags);
    ASSERT_TRUE(out.shader);
    EXPECT_EQ(out.shader->properties.size(), 400u);
    // Walk down the 50 nested categories to the subshaders.
    const shaderlab::Category* cat =
        std::get<std::unique_ptr<shaderlab::Category>>(out.shader->subshaders.at(0)).get();
    for (int d = 1; d < 50; ++d) {
        cat = std::get<std::unique_ptr<shaderlab::Category>>(cat->children.at(0)).get();
    }
    ASSERT_GT(cat->children.size(), 100u);
    const auto& sub = std::get<shaderlab::SubShader>(cat->children[0]);
    EXPECT_EQ(sub.passes.size(), 4u);
}

}  // namespace
}  // namespace kiln::test
