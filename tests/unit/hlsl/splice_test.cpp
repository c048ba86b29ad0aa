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
#include "unit/hlsl/preprocess_alike.h"

namespace kiln::hlsl {
namespace {

using test::ScratchDir;

// Preprocesses `main` plain and planned with splicing; the spliced output made whole must be
// glslang's, text and messages. Returns the plan.
InactiveTextPlan ExpectSplicedAlike(const ScratchDir& dir, const std::string& main) {
    PlanOptions options;
    options.drop_needless = true;
    options.splice = true;
    return test::ExpectSamePreprocessing(dir, main, options);
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
              "#define E\n"                                    // 3
              "#define EE E E\n"                               // 4
              "float a = (1.5f + 2) * b[3];\n"                 // 5: short
              "    float c = HALF(2); // a comment\n"          // 6: short (lean: no comment)
              "HALF c2 = HALF(2) + 1 + HALF;\n"                // 7: short, around the macros
              "float d = CALL(1 +\n"                           // 8: whole
              "   2) + e;\n"                                   // 9: whole: an argument
              "float f = 1 + TAIL\n"                           // 10: whole
              "(3) + 4 + 5;\n"                                 // 11: whole: TAIL's argument
              "x . y :: z <<= 1 >>= 2 && 3 || 4 ^^ 5 != 6;\n"  // 12: short
              "int g = 0x1Fu + 10u, h = .5, i = 1e-3f;\n"      // 13: short
              "int j = 1 /* a comment */ + k;\n"               // 14: whole: a comment
              "\ta ( b ) [ c ] ; , d , (e);\n"                 // 15: short
              "int l = \"s\" + m;\n"                           // 16: whole: a string
              "int n = EE + p;\n"                              // 17: whole: may expand to none
              "f(x, y);\n"                                     // 18: short
              "q = r;\n"                                       // 19: short
              "};\n"                                           // 20: whole: 2 tokens
              "(HALF) (HALF) x;\n");                           // 21: short, between the macros
    const InactiveTextPlan plan = ExpectSplicedAlike(dir, "#include \"lib.h\"\nfloat z = 1 + 2;\n");
    ASSERT_EQ(plan.inclusions.size(), 1u);
    ASSERT_TRUE(plan.complete);
    const std::string& text = plan.inclusions[0].text;
    for (size_t line : {5, 6, 7, 12, 13, 15, 18, 19, 21})
        EXPECT_TRUE(ServedShort(text, line)) << line << "\n" << text;
    for (size_t line : {8, 9, 10, 11, 14, 16, 17, 20})
        EXPECT_FALSE(ServedShort(text, line)) << line << "\n" << text;
    EXPECT_EQ(plan.spliced_runs, 12u);  // two on lines 6, 7 and 21
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
        EXPECT_EQ(plan.spliced_runs, 0u) << file;
    }
    // A file that spells the marker's prefix is served whole.
    dir.Write("marker.h", "float a = b + c + d;\nfloat qKsP1x1 = 1 + 2;\n");
    EXPECT_EQ(ExpectSplicedAlike(dir, "#include \"marker.h\"\n").spliced_runs, 0u);
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
    auto choice = std::make_shared<const SpliceChoice>(
        ChooseSpliceRuns(*file, MacroWords(*file, {}, {}, {})));
    ASSERT_EQ(choice->runs.size(), 1u);  // `= b + c`, between `a` and `;`
    const std::vector<std::shared_ptr<const SpliceChoice>> files = {choice};
    std::string good = "a qKsP0x0;\n";  // as glslang prints `a qKsP0x0 ;`
    EXPECT_TRUE(Unsplice(good, files));
    EXPECT_EQ(good, "a = b + c;\n");
    for (const std::string bad : {"aqKsP0x0;\n", "a qKsP0x0 ;\n", "a  qKsP0x0;\n", "a qKsP1x0;\n",
                                  "a qKsP0x1;\n", "a qKsP0x0; a qKsP0x0;\n", "a qKsP0x0y;\n",
                                  "a qKsPx0;\n", "qKsP0x0;\n", "a qKsP0x0\n", "( qKsP0x0;\n"}) {
        std::string copy = bad;
        EXPECT_FALSE(Unsplice(copy, files)) << bad;
        EXPECT_EQ(copy, bad);
    }
}

}  // namespace
}  // namespace kiln::hlsl
