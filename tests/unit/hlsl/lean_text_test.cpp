#include "hlsl/lean_text.h"

#include <string>

#include <gtest/gtest.h>

#include "frontend/glslang_stage.h"
#include "hlsl/file_cache.h"
#include "hlsl/includer.h"
#include "hlsl/pp_skeleton.h"

namespace kiln::hlsl {
namespace {

// The lean text (hlsl/lean_text.h) preprocesses as the text it was made from, and leaves out
// comment lines and what follows the last code of a line, where the next line starts as it did.
TEST(LeanText, LeavesOutCommentsGlslangReadsInVain) {
    const std::string text =
        "// a comment line\n"                 // 0: emptied
        "float4 a = 1; // trailing\n"         // 1: cut after ';'
        "float4 b = 2; /* closed */ \r\n"     // 2: cut after ';' (and its CR)
        "float4 c = 3; /* opens\n"            // 3: kept: the comment goes on
        "   still a comment\n"                // 4: emptied (inside it)
        "   ends */ float4 d = 4;\n"          // 5: kept: its first token's column
        "#define E 5 // a directive's own\n"  // 6: kept
        "float4 f = E; // continued \\\n"     // 7: kept: the comment takes line 8
        "float4 g = 6;\n"                     // 8
        "  /* a */ /* b */  \n"               // 9: emptied
        "float4 h = \"//\";\n"                // 10: a string, not a comment
        "// last, no line break";             // 11: emptied, a space stays
    const PpSkeleton skeleton = ScanSkeleton(text);
    ASSERT_TRUE(skeleton.safe);
    const LeanText lean = MakeLeanText(text, skeleton);
    ASSERT_EQ(lean.line_starts.size(), skeleton.line_starts.size());
    const auto line = [&](size_t l) {
        const size_t end =
            l + 1 < lean.line_starts.size() ? lean.line_starts[l + 1] - 1 : lean.text.size();
        return lean.text.substr(lean.line_starts[l], end - lean.line_starts[l]);
    };
    EXPECT_EQ(line(0), "");
    EXPECT_EQ(line(1), "float4 a = 1;");
    EXPECT_EQ(line(2), "float4 b = 2;");
    EXPECT_EQ(line(3), "float4 c = 3; /* opens");
    EXPECT_EQ(line(4), "");
    EXPECT_EQ(line(5), "   ends */ float4 d = 4;");
    EXPECT_EQ(line(6), "#define E 5 // a directive's own");
    EXPECT_EQ(line(7), "float4 f = E; // continued \\");
    EXPECT_EQ(line(9), "");
    EXPECT_EQ(line(10), "float4 h = \"//\";");
    EXPECT_EQ(line(11), " ");
    EXPECT_LT(lean.text.size(), text.size());
    // glslang's output and messages are the same.
    FileCache files;
    const IncludePaths paths{{}, "", 0};
    Includer a(paths, files), b(paths, files);
    const frontend::StageOutput want =
        frontend::Preprocess(pack::Stage::kFragment, text, "lean.hlsl", a);
    const frontend::StageOutput got =
        frontend::Preprocess(pack::Stage::kFragment, lean.text, "lean.hlsl", b);
    EXPECT_EQ(want.ok, got.ok);
    EXPECT_EQ(want.text, got.text);
    EXPECT_EQ(want.info_log, got.info_log);
}

}  // namespace
}  // namespace kiln::hlsl
