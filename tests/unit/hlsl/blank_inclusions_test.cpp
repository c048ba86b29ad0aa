#include "hlsl/blank_inclusions.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hlsl/inactive_text.h"
#include "support/compile_support.h"
#include "unit/hlsl/preprocess_alike.h"

namespace kiln::hlsl {
namespace {

using test::ScratchDir;

// The number of inclusions of `plan` served as one line break.
size_t ServedBlank(const InactiveTextPlan& plan) {
    size_t n = 0;
    for (uint32_t newlines : plan.blank_inclusions)
        n += newlines > 0;
    return n;
}

// Guarded files included again where glslang's output follows the return's #line differently:
// at a file's start and end, twice in a row, nested, before an indented line (glslang spaces the
// first token after its #line by the token before it), before a directive, and as a file's last
// line.
TEST(BlankInclusions, ServedAsOneLineBreakAndGivenBackAsGlslangPrintsThem) {
    ScratchDir dir;
    const std::string guarded =
        "#ifndef G_H\n#define G_H\n"
        "float g(float x) { return x + 1.0; }\n"
        "float h(float x) { return x * 2.0; }\n"
        "\n\n\n\n\n\n\n\n"
        "#endif\n";
    dir.Write("g.h", guarded);
    dir.Write("nest.h", "#include \"g.h\"\n  float n = g(1.0) + h(2.0) + 3.0;\n#include \"g.h\"\n");
    dir.Write("tail.h", "float t = 1.0 + 2.0 + 3.0;\n#include \"g.h\"\n");
    const std::string main =
        "#include \"g.h\"\n"
        "#include \"g.h\"\n"
        "#include \"g.h\"\n"
        "    float a = g(1.0) + h(2.0);\n"
        "#include \"g.h\"\n"
        "}\n"
        "#include \"g.h\"\n"
        "  float b = (a + 1.0) * 2.0;\n"
        "#include \"nest.h\"\n"
        "#include \"g.h\"\n"
        "#define M 1\n"
        "#include \"tail.h\"\n"
        "float c = M + 1.0 + 2.0;\n"
        "#include \"g.h\"\n";
    PlanOptions options;
    options.drop_needless = true;
    options.splice = true;
    {
        FileCache files;
        const IncludePaths paths{{dir.path()}, "", 0};
        Includer includer(paths, files);
        const frontend::StageOutput whole =
            frontend::Preprocess(pack::Stage::kFragment, main, dir.path() + "/main.hlsl", includer);
        ASSERT_TRUE(whole.ok && whole.info_log.empty()) << whole.info_log;
    }
    const InactiveTextPlan plan = test::ExpectSamePreprocessing(dir, main, options);
    ASSERT_TRUE(plan.complete);
    EXPECT_GT(plan.spliced_runs, 0u);
    // g.h whole once; blank six times from main, twice from nest.h and once from tail.h.
    EXPECT_EQ(ServedBlank(plan), 9u);
    for (size_t i = 0; i < plan.inclusions.size(); ++i) {
        if (i < plan.blank_inclusions.size() && plan.blank_inclusions[i] > 0) {
            EXPECT_EQ(plan.inclusions[i].text, "\n");
            EXPECT_EQ(plan.blank_inclusions[i], 13u);  // g.h's line breaks
        }
    }
    // Without splicing (a plan whose texts may spell the marker), everything is served as it is.
    PlanOptions plain = options;
    plain.splice = false;
    EXPECT_EQ(ServedBlank(test::ExpectSamePreprocessing(dir, main, plain)), 0u);
    // A file that spells the marker's prefix: no splice, so no blank inclusion either.
    dir.Write("marker.h", "float qKsPb0 = 1.0;\n");
    EXPECT_EQ(
        ServedBlank(test::ExpectSamePreprocessing(dir, "#include \"marker.h\"\n" + main, options)),
        0u);
}

TEST(BlankInclusions, OnlyLineBreaksOfAPrintablePathAreServedBlank) {
    EXPECT_TRUE(ServableAsBlank(std::string(8, '\n'), "/a/b.h"));
    EXPECT_FALSE(ServableAsBlank(std::string(7, '\n'), "/a/b.h"));  // too few to matter
    EXPECT_FALSE(ServableAsBlank(std::string(8, '\n') + " ", "/a/b.h"));
    EXPECT_FALSE(ServableAsBlank(" " + std::string(8, '\n'), "/a/b.h"));
    EXPECT_FALSE(ServableAsBlank(std::string(8, '\n'), "/a/\"b.h"));
    EXPECT_FALSE(ServableAsBlank(std::string(8, '\n'), "C:\\a\\b.h"));
}

TEST(BlankInclusionsRestore, RefusesMarkedNamesOutOfPlace) {
    const std::vector<uint32_t> newlines = {0, 3, 0, 2};
    const std::string one =
        "#line 1 \"" + BlankInclusionName(1, "/x/a.h") + "\"\n\n#line 4 \"m\"\n";
    const std::string three =
        "#line 1 \"" + BlankInclusionName(3, "/x/b.h") + "\"\n\n#line 9 \"m\"\n";
    std::string good = "int a;\n" + one + "int b;\n" + three + "int c;\n";
    ASSERT_TRUE(RestoreBlankInclusions(good, newlines));
    EXPECT_EQ(good,
              "int a;\n#line 1 \"/x/a.h\"\n\n\n\n#line 4 \"m\"\n"
              "int b;\n#line 1 \"/x/b.h\"\n\n\n#line 9 \"m\"\nint c;\n");
    std::string none = "int a;\n";
    EXPECT_TRUE(RestoreBlankInclusions(none, {0, 0}));
    EXPECT_EQ(none, "int a;\n");
    for (const std::string& bad : std::vector<std::string>{
             "int a;\n" + one,                                          // the second one missing
             three + one,                                               // out of order
             one + one + three,                                         // one twice
             "x " + one + three,                                        // not a #line
             "#line 1  " + one.substr(8) + three,                       // two spaces
             one.substr(0, one.size() - 13) + "\n\n#line 4\n" + three,  // two empty lines
             one.substr(0, one.size() - 13) + "int q;\n" + three,       // no return
         }) {
        std::string copy = bad;
        EXPECT_FALSE(RestoreBlankInclusions(copy, newlines)) << bad;
        EXPECT_EQ(copy, bad);
    }
}

}  // namespace
}  // namespace kiln::hlsl
