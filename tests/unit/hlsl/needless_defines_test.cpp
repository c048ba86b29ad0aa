#include "hlsl/needless_defines.h"

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hlsl/pp_skeleton.h"

namespace kiln::hlsl {
namespace {

std::vector<std::shared_ptr<const PpSkeleton>> Files(const std::vector<std::string>& texts) {
    std::vector<std::shared_ptr<const PpSkeleton>> out;
    for (const std::string& t : texts)
        out.push_back(std::make_shared<const PpSkeleton>(ScanSkeleton(t)));
    return out;
}

// The names of `names` that `main` leaves needless, space-separated.
std::string Needless(const IncludedDefines& included,
                     const std::string& main,
                     const std::vector<std::string>& names) {
    const PpSkeleton skeleton = ScanSkeleton(main);
    const NeedlessDefines needless(included, skeleton);
    std::string out;
    for (const std::string& name : names) {
        if (needless.Needless(name))
            out += (out.empty() ? "" : " ") + name;
    }
    return out;
}

TEST(NeedlessDefines, NamesSpelledOnlyInTheirOwnDefinesOrInThoseOfNeedlessOnes) {
    const IncludedDefines included = MakeIncludedDefines(Files({
        "#define ALONE 1\n"
        "#define TOP MID + 1\n"
        "#define MID 2 // MID\n"
        "#define USED 3\n"
        "#if defined(FEATURE)\n#define ALT 1\n#else\n#define ALT 0\n#endif\n"
        "#define FEATURE_TEST defined(FEATURE)\n",
        "float f = USED;\n#undef GONE\n#define GONE 1\n#define __RESERVED 1\n#define GL_X 1\n",
    }));
    const std::vector<std::string> names = {"ALONE",   "TOP",         "MID",        "USED",
                                            "ALT",     "GONE",        "__RESERVED", "GL_X",
                                            "FEATURE", "FEATURE_TEST"};
    // Two alternative #defines of ALT are both its own; a comment is not a spelling; an #undef
    // and code are; glslang's own names are never left out; FEATURE is no #define's name.
    EXPECT_EQ(Needless(included, "float m;\n", names), "ALONE TOP MID ALT FEATURE_TEST");
    // The program's text names TOP, so its body is read: MID is needed too.
    EXPECT_EQ(Needless(included, "float m = TOP;\n", names), "ALONE ALT FEATURE_TEST");
    // A name in a comment of the program's text is no spelling.
    EXPECT_EQ(Needless(included, "float m; // TOP\n", names), "ALONE TOP MID ALT FEATURE_TEST");
}

TEST(NeedlessDefines, KeptWhereAPasteMayMakeTheName) {
    // `sampler##t` makes names that start "sampler"; no other paste is written.
    const IncludedDefines literal = MakeIncludedDefines(Files({
        "#define TEX(t) Texture2D t; SamplerState sampler##t\n"
        "#define samplerMain 1\n#define sample 2\n#define CHAINED(a) x##a##b\n",
    }));
    EXPECT_TRUE(literal.pieces_known);
    const std::vector<std::string> names = {"TEX", "samplerMain", "sample", "CHAINED", "xy"};
    EXPECT_EQ(Needless(literal, "TEX(Main)\n", names), "sample CHAINED");  // TEX is named
    EXPECT_EQ(Needless(literal, "float m;\n", names), "TEX sample CHAINED");
    // The program's own paste of a parameter may make any name: nothing is left out.
    EXPECT_EQ(Needless(literal, "#define CAT(a, b) a##b\nint v = CAT(sam, ple);\n", names), "");
    // A paste of the files whose first piece is a parameter: a name is kept where a proper
    // prefix of it is a word of the files or of the program.
    const IncludedDefines any = MakeIncludedDefines(Files({
        "#define CAT(a, b) a##b\n#define FOOBAR 1\n#define QQQ 2\n#define CATX 3\n",
    }));
    EXPECT_FALSE(any.pieces_known);
    const std::vector<std::string> more = {"FOOBAR", "QQQ", "CATX"};
    EXPECT_EQ(Needless(any, "float m;\n", more), "FOOBAR QQQ");  // CAT begins CATX
    EXPECT_EQ(Needless(any, "int v = CAT(FOO, BAR);\n", more), "QQQ");
}

TEST(NeedlessDefines, KeepTakesWhatTheMacroNamesToo) {
    const IncludedDefines included =
        MakeIncludedDefines(Files({"#define A B\n#define B C\n#define C 1\n#define D 2\n"}));
    const PpSkeleton main = ScanSkeleton("float m;\n");
    NeedlessDefines needless(included, main);
    EXPECT_TRUE(needless.Needless("A"));
    needless.Keep("B");
    EXPECT_TRUE(needless.Needless("A"));
    EXPECT_FALSE(needless.Needless("B"));
    EXPECT_FALSE(needless.Needless("C"));
    EXPECT_TRUE(needless.Needless("D"));
}

}  // namespace
}  // namespace kiln::hlsl
