#include "shaderlab/program_scan.h"

#include <gtest/gtest.h>

namespace kiln::test {
namespace {

using namespace kiln::shaderlab;

TEST(ProgramScan, FindsPragmasWithPositions) {
    // The body starts at line 10, column 14 of the .shader file (right after CGPROGRAM).
    const std::string body =
        "\n  #pragma vertex vert\n#  pragma   multi_compile  _ POINT\tSPOT\n"
        "  // #pragma fragment commented_out\n  /* #pragma x\n  #pragma y */ #pragma "
        "after_comment\n"
        "  #pragma target 3.0 // trailing comment\n  #pragmaX no\n  #include \"x\"\n";
    const auto pragmas = ScanPragmas(body, SourceLoc{500, 10, 14});
    // A comment counts as whitespace, so a directive may follow one (as in the C preprocessor).
    ASSERT_EQ(pragmas.size(), 4u);
    EXPECT_EQ(pragmas[0].name, "vertex");
    EXPECT_EQ(pragmas[0].range.begin.line, 11u);
    EXPECT_EQ(pragmas[0].range.begin.column, 3u);
    ASSERT_EQ(pragmas[0].args.size(), 1u);
    EXPECT_EQ(pragmas[0].args[0].text, "vert");
    EXPECT_EQ(pragmas[0].args[0].range.begin.column, 18u);
    EXPECT_EQ(pragmas[1].name, "multi_compile");
    ASSERT_EQ(pragmas[1].args.size(), 3u);
    EXPECT_EQ(pragmas[1].args[0].text, "_");
    EXPECT_EQ(pragmas[1].args[2].text, "SPOT");
    EXPECT_EQ(pragmas[1].args[2].range.begin.line, 12u);
    EXPECT_EQ(pragmas[2].name, "after_comment");
    EXPECT_EQ(pragmas[2].range.begin.line, 15u);
    EXPECT_EQ(pragmas[3].name, "target");
    ASSERT_EQ(pragmas[3].args.size(), 1u);
    EXPECT_EQ(pragmas[3].args[0].text, "3.0");
    EXPECT_EQ(pragmas[3].range.begin.line, 16u);
}

TEST(ProgramScan, FirstLineColumnsStartAfterTheMarker) {
    const auto pragmas = ScanPragmas(" #pragma vertex v", SourceLoc{0, 3, 10});
    ASSERT_EQ(pragmas.size(), 1u);
    EXPECT_EQ(pragmas[0].range.begin.line, 3u);
    EXPECT_EQ(pragmas[0].range.begin.column, 11u);
}

TEST(ProgramScan, EmptyAndDegenerateBodies) {
    EXPECT_TRUE(ScanPragmas("", SourceLoc{}).empty());
    EXPECT_TRUE(ScanPragmas("#pragma", SourceLoc{}).empty());
    EXPECT_TRUE(ScanPragmas("#", SourceLoc{}).empty());
    EXPECT_TRUE(ScanPragmas("/* unterminated #pragma x", SourceLoc{}).empty());
    EXPECT_TRUE(ScanPragmas("\"unterminated\n", SourceLoc{}).empty());
}

}  // namespace
}  // namespace kiln::test
