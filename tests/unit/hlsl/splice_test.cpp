#include "hlsl/splice.h"

#include <string>

#include <gtest/gtest.h>

#include "frontend/glslang_stage.h"
#include "hlsl/file_cache.h"
#include "hlsl/inactive_text.h"
#include "hlsl/includer.h"
#include "hlsl/lean_text.h"
#include "hlsl/pp_skeleton.h"
#include "support/compile_support.h"

namespace kiln::hlsl {
namespace {

using test::ScratchDir;

// Preprocesses `main` plain and planned with splicing; the spliced output made whole must be
// glslang's, text and messages. Returns the plan.
InactiveTextPlan ExpectSplicedAlike(const ScratchDir& dir, const std::string& main) {
    FileCache files;
    const IncludePaths paths{{dir.path()}, "", 0};
    const std::string name = dir.path() + "/main.hlsl";
    Includer plain(paths, files);
    const frontend::StageOutput want =
        frontend::Preprocess(pack::Stage::kFragment, main, name, plain);
    PlanOptions options;
    options.drop_needless = true;
    options.splice = true;
    Includer planned(paths, files);
    InactiveTextPlan plan = PlanInactiveText(main, name, planned, files, options);
    planned.UsePlan(&plan);
    frontend::StageOutput got =
        frontend::Preprocess(pack::Stage::kFragment, plan.main_text, name, planned);
    if (plan.spliced_lines > 0) {
        EXPECT_TRUE(Unsplice(got.text, plan.splices));
    }
    EXPECT_EQ(want.ok, got.ok);
    EXPECT_EQ(want.text, got.text) << main;
    EXPECT_EQ(want.info_log, got.info_log);
    return plan;
}

// Whether physical line `line` of `text` was served short.
bool ServedShort(const std::string& text, size_t line) {
    size_t at = 0;
    for (size_t l = 0; l < line && at != std::string::npos; ++l)
        at = text.find('\n', at) + 1;
    const size_t end = text.find('\n', at);
    return text.substr(at, end - at).find(kSpliceMarker) != std::string::npos;
}

TEST(Splice, ServesPlainLinesShortAndGivesThemBackAsGlslangPrintsThem) {
    ScratchDir dir;
    // (Numbers glslang reads otherwise than they are spelled, as `1.xx` or `08`, make the whole
    // file one the plan does not model: hlsl/pp_skeleton.h.)
    dir.Write("lib.h",
              "#define HALF float\n"                           // 0
              "#define CALL(x) x\n"                            // 1
              "#define TAIL CALL\n"                            // 2
              "float a = (1.5f + 2) * b[3];\n"                 // 3: short
              "    float c = HALF(2); // a macro\n"            // 4: whole
              "float d = CALL(1 +\n"                           // 5: whole
              "   2) + e;\n"                                   // 6: whole: an argument
              "float f = 1 + TAIL\n"                           // 7: whole
              "(3) + 4 + 5;\n"                                 // 8: whole: TAIL's argument
              "x . y :: z <<= 1 >>= 2 && 3 || 4 ^^ 5 != 6;\n"  // 9: short
              "int g = 0x1Fu + 10u, h = .5, i = 1e-3f;\n"      // 10: short
              "int j = 1 /* a comment */ + k;\n"               // 11: whole: a comment
              "\ta ( b ) [ c ] ; , d , (e);\n"                 // 12: short
              "int l = \"s\" + m;\n"                           // 13: whole: a string
              "int n = p;\n"                                   // 14: short
              "f(x, y);\n"                                     // 15: short
              "q = r;\n"                                       // 16: short
              "};\n");                                         // 17: whole: 2 tokens
    const InactiveTextPlan plan = ExpectSplicedAlike(dir, "#include \"lib.h\"\nfloat z = 1 + 2;\n");
    ASSERT_EQ(plan.inclusions.size(), 1u);
    ASSERT_TRUE(plan.complete);
    const std::string& text = plan.inclusions[0].text;
    for (size_t line : {3, 9, 10, 12, 14, 15, 16})
        EXPECT_TRUE(ServedShort(text, line)) << line << "\n" << text;
    for (size_t line : {4, 5, 6, 7, 8, 11, 13, 17})
        EXPECT_FALSE(ServedShort(text, line)) << line << "\n" << text;
    EXPECT_EQ(plan.spliced_lines, 7u);
    // The main text is served as it is.
    EXPECT_EQ(plan.main_text.find(kSpliceMarker), std::string::npos);
}

TEST(Splice, AMacroCallThatMayRunOverADirectiveStopsIt) {
    ScratchDir dir;
    dir.Write("open.h",
              "#define CALL(x) x\n"
              "float a = b + c + d;\n"
              "float e = CALL(1,\n"
              "#if 1\n"
              "  2) + f + g;\n"
              "#endif\n");
    dir.Write("ends.h", "#define CALL(x) x\nfloat a = b + c + d;\nfloat e = 1 + CALL\n");
    for (const char* file : {"open.h", "ends.h"}) {
        FileCache files;
        const IncludePaths paths{{dir.path()}, "", 0};
        Includer includer(paths, files);
        PlanOptions options;
        options.splice = true;
        const InactiveTextPlan plan =
            PlanInactiveText(std::string("#include \"") + file + "\"\n", dir.path() + "/main.hlsl",
                             includer, files, options);
        EXPECT_TRUE(plan.complete) << file;
        EXPECT_EQ(plan.spliced_lines, 0u) << file;
    }
    // A file that spells the marker's prefix is served whole.
    dir.Write("marker.h", "float a = b + c + d;\nfloat qKsP1x1 = 1 + 2;\n");
    EXPECT_EQ(ExpectSplicedAlike(dir, "#include \"marker.h\"\n").spliced_lines, 0u);
}

TEST(Splice, FindsWhereAMacroMayLeaveAMacrosNameLast) {
    EXPECT_TRUE(EndOfDefine("F(x) x").calls);
    EXPECT_TRUE(EndOfDefine("P a##b").calls);
    EXPECT_TRUE(EndOfDefine("O G(").calls);
    const DefineEnd word = EndOfDefine("T  CALL  ");
    EXPECT_FALSE(word.calls);
    EXPECT_EQ(word.last_word, "CALL");
    EXPECT_EQ(EndOfDefine("S };").last_word, "");
    EXPECT_EQ(EndOfDefine("N 1").last_word, "");
    EXPECT_EQ(EndOfDefine("E").last_word, "");
}

TEST(Splice, UnspliceRefusesMarkersOutOfPlace) {
    const std::string text = "a = b + c;\n";
    const PpSkeleton skeleton = ScanSkeleton(text);
    auto lean = std::make_shared<const LeanText>(MakeLeanText(text, skeleton));
    const std::shared_ptr<const SpliceFile> file = ScanSpliceFile(lean, skeleton);
    ASSERT_TRUE(file->usable);
    ASSERT_EQ(file->lines[0].kind, SpliceFile::Kind::kPlain);
    const std::vector<std::shared_ptr<const SpliceFile>> files = {file};
    std::string good = "a qKsP0x0;\n";  // no space before `;`
    EXPECT_TRUE(Unsplice(good, files));
    EXPECT_EQ(good, "a = b + c;\n");
    for (const std::string bad :
         {"aqKsP0x0;\n", "a qKsP0x0 ;\n", "a  qKsP0x0;\n", "a qKsP1x0;\n", "a qKsP0x1;\n",
          "a qKsP0x0; a qKsP0x0;\n", "a qKsP0x0y;\n", "a qKsPx0;\n"}) {
        std::string copy = bad;
        EXPECT_FALSE(Unsplice(copy, files)) << bad;
        EXPECT_EQ(copy, bad);
    }
}

}  // namespace
}  // namespace kiln::hlsl
