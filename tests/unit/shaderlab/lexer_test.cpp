#include "shaderlab/lexer.h"

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace kiln::test {
namespace {

using namespace kiln::shaderlab;

std::vector<Token> LexText(const std::string& text, DiagnosticList& diags) {
    static std::vector<std::unique_ptr<SourceFile>> keep;  // tokens point into the file
    keep.push_back(std::make_unique<SourceFile>("lex.shader", text));
    return Lex(*keep.back(), diags);
}

TEST(Lexer, TokenKindsAndPositions) {
    DiagnosticList diags;
    const auto t = LexText("Shader \"a b\" {\n  _X (\"d\", 2DArray) = -1.5e2, [ ] +\n}", diags);
    EXPECT_TRUE(diags.all().empty());
    const std::vector<TokenKind> kinds = {
        TokenKind::kIdentifier, TokenKind::kString,   TokenKind::kLBrace,   TokenKind::kIdentifier,
        TokenKind::kLParen,     TokenKind::kString,   TokenKind::kComma,    TokenKind::kIdentifier,
        TokenKind::kRParen,     TokenKind::kEquals,   TokenKind::kMinus,    TokenKind::kNumber,
        TokenKind::kComma,      TokenKind::kLBracket, TokenKind::kRBracket, TokenKind::kPlus,
        TokenKind::kRBrace,     TokenKind::kEof};
    ASSERT_EQ(t.size(), kinds.size());
    for (size_t i = 0; i < kinds.size(); ++i) {
        EXPECT_EQ(t[i].kind, kinds[i]) << i;
    }
    EXPECT_EQ(t[1].text, "a b");
    EXPECT_EQ(t[7].text, "2DArray");
    EXPECT_EQ(t[11].text, "1.5e2");
    EXPECT_EQ(t[3].range.begin.line, 2u);
    EXPECT_EQ(t[3].range.begin.column, 3u);
    EXPECT_EQ(t[3].range.end.column, 5u);
    EXPECT_EQ(t[16].range.begin.line, 3u);
}

TEST(Lexer, NumbersVersusTextureTypeNames) {
    DiagnosticList diags;
    const auto t = LexText("2D 3D 2 .5 1. 1e3 1e", diags);
    EXPECT_EQ(t[0].kind, TokenKind::kIdentifier);
    EXPECT_EQ(t[1].kind, TokenKind::kIdentifier);
    EXPECT_EQ(t[2].kind, TokenKind::kNumber);
    EXPECT_EQ(t[3].text, ".5");
    EXPECT_EQ(t[4].text, "1.");
    EXPECT_EQ(t[5].text, "1e3");
    EXPECT_EQ(t[6].kind, TokenKind::kIdentifier);  // "1e" is no number
}

TEST(Lexer, CommentsAreSkipped) {
    DiagnosticList diags;
    const auto t = LexText("a // b c\n/* d\n e */ f /**/ g", diags);
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[1].text, "f");
    EXPECT_EQ(t[1].range.begin.line, 3u);
    EXPECT_EQ(t[2].text, "g");
}

TEST(Lexer, StringEscapes) {
    DiagnosticList diags;
    const auto t = LexText(R"("a \"quoted\" \\ b")", diags);
    EXPECT_TRUE(diags.all().empty());
    EXPECT_EQ(t[0].kind, TokenKind::kString);
    EXPECT_EQ(t[0].text, R"(a \"quoted\" \\ b)");
}

TEST(Lexer, ProgramBlocksOfEveryKind) {
    DiagnosticList diags;
    const auto t = LexText(
        "CGPROGRAM a ENDCG CGINCLUDE b ENDCG HLSLPROGRAM c ENDHLSL HLSLINCLUDE d ENDHLSL "
        "GLSLPROGRAM e ENDGLSL GLSLINCLUDE f ENDGLSL",
        diags);
    EXPECT_TRUE(diags.all().empty());
    ASSERT_EQ(t.size(), 7u);
    const ProgramKind kinds[] = {ProgramKind::kCgProgram,   ProgramKind::kCgInclude,
                                 ProgramKind::kHlslProgram, ProgramKind::kHlslInclude,
                                 ProgramKind::kGlslProgram, ProgramKind::kGlslInclude};
    for (size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(t[i].kind, TokenKind::kProgram);
        EXPECT_EQ(t[i].program_kind, kinds[i]);
        EXPECT_EQ(t[i].text, std::string(" ") + char('a' + i) + " ");
    }
}

TEST(Lexer, ProgramEndIsAWholeWord) {
    DiagnosticList diags;
    const auto t = LexText("CGPROGRAM MY_ENDCG ENDCGX\nENDCG", diags);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].text, " MY_ENDCG ENDCGX\n");
}

TEST(Lexer, GarbageBecomesFewUnknownTokens) {
    DiagnosticList diags;
    const auto t = LexText(std::string("\x01\x02\xff\xfe @#$ a") + '\0' + "b", diags);
    ASSERT_GE(t.size(), 3u);
    EXPECT_EQ(t[0].kind, TokenKind::kUnknown);
    EXPECT_EQ(t[0].text.size(), 4u);
    EXPECT_TRUE(diags.all().empty());  // reported by the parser only where it meets them
}

TEST(Lexer, UnterminatedConstructs) {
    {
        DiagnosticList diags;
        const auto t = LexText("\"abc\nx", diags);
        ASSERT_EQ(diags.all().size(), 1u);
        EXPECT_EQ(diags.all()[0].code, DiagCode::kUnterminatedString);
        EXPECT_EQ(t[0].text, "abc");
        EXPECT_EQ(t[1].text, "x");  // lexing resumes on the next line
    }
    {
        DiagnosticList diags;
        LexText("a /* b", diags);
        ASSERT_EQ(diags.all().size(), 1u);
        EXPECT_EQ(diags.all()[0].code, DiagCode::kUnterminatedComment);
        EXPECT_EQ(diags.all()[0].range.begin.column, 3u);
    }
    {
        DiagnosticList diags;
        const auto t = LexText("x\n  HLSLPROGRAM body", diags);
        ASSERT_EQ(diags.all().size(), 1u);
        EXPECT_EQ(diags.all()[0].code, DiagCode::kUnterminatedProgramBlock);
        EXPECT_EQ(diags.all()[0].range.begin.line, 2u);
        EXPECT_EQ(t[1].text, " body");
    }
}

TEST(Lexer, Utf8ByteOrderMarkIsSkipped) {
    DiagnosticList diags;
    const auto t = LexText("\xEF\xBB\xBFShader \"a\" { }", diags);
    EXPECT_TRUE(diags.all().empty());
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(t[0].text, "Shader");
    EXPECT_EQ(t[0].range.begin.offset, 3u);
    EXPECT_EQ(t[0].range.begin.line, 1u);
}

}  // namespace
}  // namespace kiln::test
