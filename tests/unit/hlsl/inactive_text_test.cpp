#include "hlsl/inactive_text.h"

#include <random>

#include <gtest/gtest.h>

#include "frontend/glslang_stage.h"
#include "hlsl/pp_macros.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/splice.h"
#include "support/compile_support.h"
#include "unit/hlsl/preprocess_alike.h"
#include "unit/hlsl/random_program.h"

namespace kiln::hlsl {
namespace {

using test::ExpectSamePreprocessing;
using test::ScratchDir;

TEST(PpSkeleton, FindsDirectivesAsGlslangSplitsLines) {
    const PpSkeleton s = ScanSkeleton(
        "#if A\n"
        "x /* #endif\n"
        "#else */ y\n"
        "  #  define B \\\n"
        "    1 // two lines\n"
        "z \"/*\" w\n"
        "#elif defined(C) /* c */\n"
        "#endif");
    ASSERT_TRUE(s.safe);
    ASSERT_EQ(s.directives.size(), 4u);
    EXPECT_EQ(s.directives[0].kind, PpKind::kIf);
    EXPECT_EQ(s.directives[0].next, 2u);
    EXPECT_EQ(s.directives[1].kind, PpKind::kDefine);
    EXPECT_EQ(s.directives[1].first_line, 3u);
    EXPECT_EQ(s.directives[1].last_line, 4u);
    EXPECT_EQ(s.directives[1].rest, " B     1 ");
    EXPECT_EQ(s.directives[2].kind, PpKind::kElif);
    EXPECT_EQ(s.directives[2].rest, " defined(C)  ");
    EXPECT_EQ(s.directives[2].next, 3u);
    EXPECT_EQ(s.directives[3].kind, PpKind::kEndif);
    EXPECT_EQ(s.line_count, 8u);
}

TEST(PpSkeleton, WhatItCannotModelIsNotSafe) {
    EXPECT_FALSE(ScanSkeleton("#if A\n").safe);   // no #endif
    EXPECT_FALSE(ScanSkeleton("#endif\n").safe);  // no #if
    EXPECT_FALSE(ScanSkeleton("#if A\n#else\n#else\n#endif\n").safe);
    EXPECT_FALSE(ScanSkeleton("x /* never closed\n").safe);
    EXPECT_FALSE(ScanSkeleton("a\rb\n").safe);  // a lone CR
    EXPECT_FALSE(ScanSkeleton("/* c */ #define A\n").safe);
    EXPECT_FALSE(ScanSkeleton("#define A /* two\n lines */ 1\n").safe);
    EXPECT_FALSE(ScanSkeleton("x = \"a\\\"b\";\n").safe);              // an escape in a string
    EXPECT_FALSE(ScanSkeleton("#if A\n##if\n#endif\n").safe);          // glslang's `# #if` (fuzz)
    EXPECT_FALSE(ScanSkeleton("#if A\n#if\n#endif#\n#endif\n").safe);  // glslang checks (fuzz)
    EXPECT_FALSE(ScanSkeleton("#if A\n#else B\n#endif\n").safe);
    EXPECT_FALSE(ScanSkeleton("#ifdef A B\n#endif\n").safe);
    EXPECT_TRUE(ScanSkeleton("#ifdef A // a\n#else /* b */\n#endif  // A\n").safe);
    EXPECT_TRUE(ScanSkeleton("#if A\r\nx\r\n#endif\r\n").safe);
}

TEST(PpMacros, EvaluatesAsGlslangOrSaysItDoesNotKnow) {
    PpMacros m;
    ASSERT_TRUE(m.Define(" A 1"));
    ASSERT_TRUE(m.Define(" B A + 2"));
    ASSERT_TRUE(m.Define(" E"));
    ASSERT_TRUE(m.Define(" F(x) x"));
    EXPECT_EQ(m.If(" defined(A) && B == 3"), true);
    EXPECT_EQ(m.If(" defined A && !defined(Z)"), true);
    EXPECT_EQ(m.If(" Z"), false);  // an undefined name is 0
    EXPECT_EQ(m.If(" 1 + 2 * 3 == 7 && (1 << 4) == 0x10 && 010 == 8"), true);
    EXPECT_EQ(m.If(" -1 < 0 && ~0 == -1 && 7 % 4 == 3 && 7 / 2 == 3"), true);
    EXPECT_EQ(m.If(" 1 || 0 && 0"), true);
    EXPECT_EQ(m.Ifdef(" E"), true);
    EXPECT_EQ(m.Ifdef(" Z"), false);
    // Not known: function-like macros, an empty expansion, other literals, division by zero,
    // ternaries, names glslang defines itself, trailing tokens.
    for (const char* e :
         {" F(1)", " E", " 1.0", " 1u", " 1 / 0", " 1 ? 2 : 3", " GL_ES", " defined(__LINE__)",
          " VULKAN", " 1 2", " (1", " \"s\"", " 2147483647 + 1"}) {
        EXPECT_EQ(m.If(e), std::nullopt) << e;
    }
    EXPECT_EQ(m.Ifdef(" A B"), std::nullopt);
    m.Forget(" A");
    EXPECT_EQ(m.Lookup("A"), MacroState::kUnknown);
    EXPECT_EQ(m.If(" B"), std::nullopt);
    ASSERT_TRUE(m.Undef(" A"));
    EXPECT_EQ(m.Lookup("A"), MacroState::kUndefined);
    EXPECT_FALSE(m.Define(" GL_FOO 1"));
    EXPECT_FALSE(m.Define(" 1A"));
}

TEST(PpMacros, DecidesWithoutWhatItDoesNotKnowWhereAndAndOrDo) {
    PpMacros m;
    m.Pin("STAGE");
    ASSERT_TRUE(m.Define(" STAGE 1"));  // pinned: still not known
    ASSERT_TRUE(m.Define(" SAMPLE_SH (defined(SH) && !defined(ADD))"));
    EXPECT_EQ(m.Lookup("STAGE"), MacroState::kUnknown);
    EXPECT_EQ(m.If(" defined(MULTIVIEW) && defined(STAGE)"), false);
    EXPECT_EQ(m.If(" defined(STAGE) && 0"), false);
    EXPECT_EQ(m.If(" 1 || STAGE"), true);
    EXPECT_EQ(m.If(" defined(STAGE) || 0"), std::nullopt);
    EXPECT_EQ(m.If(" STAGE == 1"), std::nullopt);
    EXPECT_EQ(m.If(" !defined(STAGE)"), std::nullopt);
    EXPECT_EQ(m.If(" 0 && STAGE(1)"), std::nullopt);  // not an expression glslang takes
    // `defined` in a macro's body reads its operand from the body, as glslang does.
    EXPECT_EQ(m.If(" SAMPLE_SH"), false);
    ASSERT_TRUE(m.Define(" SH 1"));
    EXPECT_EQ(m.If(" SAMPLE_SH"), true);
    ASSERT_TRUE(m.Define(" D defined"));
    EXPECT_EQ(m.If(" D(SH)"), std::nullopt);
}

TEST(InactiveText, BlanksSkippedBranchesAndGuardedFilesWithoutChangingGlslangsOutput) {
    ScratchDir dir;
    dir.Write("guard.h",
              "#ifndef GUARD_H\n#define GUARD_H\n"
              "#if defined(FAST) || QUALITY > 2\nfloat fast_or_good;\n#elif QUALITY == 2\n"
              "float medium;\n#else\n#define LOW 1\nfloat low; /* a comment\n#endif\n*/\n#endif\n"
              "#endif\n");
    dir.Write("other.h", "#include \"guard.h\"\n#ifdef LOW\nfloat was_low;\n#endif\nint tail");
    const InactiveTextPlan plan = ExpectSamePreprocessing(
        dir,
        "#define QUALITY 2\n#include \"guard.h\"\n#include \"other.h\"\n#include \"guard.h\"\n"
        "#if QUALITY == 2\nfloat main_medium;\n#else\nfloat main_other;\n#endif\n");
    EXPECT_TRUE(plan.complete);
    ASSERT_EQ(plan.inclusions.size(), 4u);
    // The second and third inclusions of guard.h are blank but for their directive lines.
    EXPECT_EQ(plan.inclusions[2].text, "#ifndef GUARD_H\n" + std::string(11, '\n') + "#endif\n");
    EXPECT_EQ(plan.inclusions[3].text, plan.inclusions[2].text);
    EXPECT_EQ(plan.inclusions[0].text.find("fast_or_good"), std::string::npos);
    EXPECT_NE(plan.inclusions[0].text.find("medium"), std::string::npos);
    EXPECT_EQ(plan.main_text.find("main_other"), std::string::npos);
}

TEST(InactiveText, WhatItCannotEvaluateStaysAndAnIncludeItMayNotReadStopsIt) {
    ScratchDir dir;
    dir.Write("a.h", "float a;\n");
    dir.Write("b.h", "#if 0\nfloat b_never;\n#endif\nfloat b;\n");
    const InactiveTextPlan plan =
        ExpectSamePreprocessing(dir,
                                "#define F(x) x\n"
                                "#if F(1)\n#define MAYBE 1\nfloat f;\n#else\nfloat not_f;\n#endif\n"
                                "#if MAYBE\nfloat maybe;\n#endif\n"
                                "#if 0\nfloat never;\n#endif\n"
                                "#include \"a.h\"\n"
                                "#if F(0)\n#include \"b.h\"\n#endif\n"
                                "#if 0\nfloat never_after_stop;\n#endif\n");
    EXPECT_FALSE(plan.complete);
    EXPECT_EQ(plan.inclusions.size(), 1u);
    EXPECT_NE(plan.main_text.find("not_f"), std::string::npos);
    EXPECT_NE(plan.main_text.find("float maybe"), std::string::npos);
    EXPECT_EQ(plan.main_text.find("float never;"), std::string::npos);
    EXPECT_NE(plan.main_text.find("never_after_stop"), std::string::npos);
}

TEST(InactiveText, KeepsLineBreaksOfContinuedAndCrLfLinesAndTheLastCharacter) {
    ScratchDir dir;
    dir.Write("crlf.h", "#if 0\r\nfloat x; \\\r\nfloat y;\r\n#endif\r\nfloat z;\r\n");
    dir.Write("bom.h", "\xEF\xBB\xBF#if 0\nfloat b;\n#endif\nfloat c;\n");
    dir.Write("last.h", "#ifdef NOPE\nfloat n;\n#else\nfloat e;\n#endif");
    ExpectSamePreprocessing(dir,
                            "#include \"crlf.h\"\n#include \"last.h\"\n#include \"bom.h\"\n"
                            "#if 1\n#else\nfloat q = \\\n  1;\n#endif\nfloat w = __LINE__;\n");
}

TEST(InactiveText, BlanksDirectivesGlslangDoesNotNeed) {
    ScratchDir dir;
    dir.Write("lib.h",
              "#ifndef LIB_H\n#define LIB_H\n"
              "#define UNUSED 1\n#define TOP MID + 1\n#define MID 2\n#define USED 3\n"
              "#define BY_MAIN 4\n#define TEX(t) float t; float sampler##t\n#define samplerA 5\n"
              "#if defined(FEATURE)\n#define ALT 1\n#else\n#define ALT 0\n#endif\n"
              "float code = USED;\n#endif\n");
    dir.Write("twice.h", "#define TWICE 1\n");
    PlanOptions needless;
    needless.drop_needless = true;
    const std::string main =
        "#include \"lib.h\"\n#include \"lib.h\"\n#include \"twice.h\"\n#include \"twice.h\"\n"
        "#if BY_MAIN > 3\nfloat m = BY_MAIN;\n#endif\nTEX(A)\n#if FN(1)\n#endif\n";
    const InactiveTextPlan plan =
        ExpectSamePreprocessing(dir, "#define FN(x) x\n" + main, needless);
    ASSERT_TRUE(plan.complete);
    ASSERT_EQ(plan.inclusions.size(), 4u);
    // Left: the guard's #define (its #ifndef names it), what code or the main text names, the
    // name a paste may make, and a macro read twice; the decided conditionals' lines go.
    EXPECT_EQ(plan.inclusions[0].text,
              "\n#define LIB_H\n\n\n\n#define USED 3\n#define BY_MAIN 4\n"
              "#define TEX(t) float t; float sampler##t\n#define samplerA 5\n\n\n\n\n\n"
              "float code = USED;\n\n");
    EXPECT_EQ(plan.inclusions[1].text, std::string(16, '\n'));
    EXPECT_EQ(plan.inclusions[2].text, "#define TWICE 1\n");
    EXPECT_EQ(plan.inclusions[3].text, "#define TWICE 1\n");
    // The main text keeps its own #defines and the conditional the plan cannot decide.
    EXPECT_EQ(plan.main_text, "#define FN(x) x\n" + main.substr(0, main.find("#if")) +
                                  "\nfloat m = BY_MAIN;\n\nTEX(A)\n#if FN(1)\n#endif\n");
    // A #define in a branch the plan cannot decide counts as a read: glslang would compare the
    // two, and here reports that they differ.
    dir.Write("perhaps.h", "#if FN(1)\n#define PERHAPS 1\n#endif\n#define PERHAPS 2\n");
    const InactiveTextPlan perhaps =
        ExpectSamePreprocessing(dir, "#define FN(x) x\n#include \"perhaps.h\"\n", needless);
    ASSERT_EQ(perhaps.inclusions.size(), 1u);
    EXPECT_NE(perhaps.inclusions[0].text.find("#define PERHAPS 2"), std::string::npos);
    // Without the option nothing but skipped branches is blanked.
    const InactiveTextPlan plain = ExpectSamePreprocessing(dir, "#define FN(x) x\n" + main);
    EXPECT_NE(plain.inclusions[0].text.find("#define UNUSED 1"), std::string::npos);
    EXPECT_NE(plain.main_text.find("#if BY_MAIN > 3"), std::string::npos);
}

// Whether glslang's output is the same for both stages' sources, as the plan with the stage
// macros unknown says it is.
bool StagesAlike(const ScratchDir& dir, const std::string& body, bool& plan_says) {
    PlanOptions both;
    both.unknown = {"SHADER_STAGE_VERTEX", "SHADER_STAGE_FRAGMENT"};
    const std::string vertex = "#define SHADER_STAGE_VERTEX 1\n" + body;
    plan_says = ExpectSamePreprocessing(dir, vertex, both).OutputIgnoresUnknown();
    FileCache files;
    const IncludePaths paths{{dir.path()}, "", 0};
    Includer a(paths, files), b(paths, files);
    const std::string name = dir.path() + "/main.hlsl";
    return frontend::Preprocess(pack::Stage::kVertex, vertex, name, a).text ==
           frontend::Preprocess(pack::Stage::kFragment, "#define SHADER_STAGE_FRAGMENT 1\n" + body,
                                name, b)
               .text;
}

TEST(InactiveText, KnowsWhenTheOutputIsTheSameForBothStages) {
    ScratchDir dir;
    dir.Write("support.h",
              "#if defined(MULTIVIEW) && defined(SHADER_STAGE_VERTEX)\nfloat multiview;\n#endif\n"
              "#ifdef INSTANCING\n#ifdef SHADER_STAGE_VERTEX\nfloat v;\n#else\nfloat f;\n#endif\n"
              "#endif\nfloat common;\n");
    bool plan_says = false;
    EXPECT_TRUE(StagesAlike(dir, "#include \"support.h\"\n", plan_says));
    EXPECT_TRUE(plan_says);
    // A condition that reads the stage.
    EXPECT_FALSE(StagesAlike(dir, "#define INSTANCING 1\n#include \"support.h\"\n", plan_says));
    EXPECT_FALSE(plan_says);
    // Code that names it (expanded to 1 in one stage only).
    EXPECT_FALSE(
        StagesAlike(dir, "#include \"support.h\"\nint s = SHADER_STAGE_VERTEX;\n", plan_says));
    EXPECT_FALSE(plan_says);
    // A macro whose body names it.
    StagesAlike(dir, "#define IS_VERTEX SHADER_STAGE_VERTEX\n", plan_says);
    EXPECT_FALSE(plan_says);
    // A name pasted together from pieces (the first piece is a word of the text), and a paste
    // whose pieces cannot make it.
    EXPECT_FALSE(StagesAlike(dir, "#define CAT(a, b) a##b\nint s = CAT(SHADER_STAGE_, VERTEX);\n",
                             plan_says));
    EXPECT_FALSE(plan_says);
    EXPECT_TRUE(StagesAlike(dir, "#define SAMPLER(t) sampler##t\nint SAMPLER(A);\n", plan_says));
    EXPECT_TRUE(plan_says);
    // In a skipped branch and in a comment of a skipped branch: no matter.
    EXPECT_TRUE(StagesAlike(
        dir, "#if 0\nint s = SHADER_STAGE_VERTEX; // SHADER_STAGE_FRAGMENT\n#endif\n", plan_says));
    EXPECT_TRUE(plan_says);
}

TEST(InactiveText, RandomProgramsPreprocessAlike) {
    size_t blanked = 0, complete = 0, ignores = 0, stops = 0, spliced_runs = 0;
    for (uint32_t seed = 1; seed <= 300; ++seed) {
        ScratchDir dir;
        test::RandomProgram g(seed);
        g.WriteIncludes(dir);
        const std::string body = g.File(0, 4);
        const InactiveTextPlan plan = ExpectSamePreprocessing(dir, "#define FN(x) x\n" + body);
        PlanOptions needless;
        needless.drop_needless = true;
        ExpectSamePreprocessing(dir, "#define FN(x) x\n" + body, needless);
        PlanOptions spliced = needless;
        spliced.splice = true;
        spliced_runs +=
            ExpectSamePreprocessing(dir, "#define FN(x) x\n" + body, spliced).spliced_runs;
        // With E taken as unknown: where the plan says the output does not depend on E, glslang
        // gives the same text for sources that differ only in a first line defining E to 0, to
        // 1, or not at all.
        PlanOptions e;
        e.unknown = {"E"};
        const std::string rest = "#define FN(x) x\n" + body;
        const bool ignores_e =
            ExpectSamePreprocessing(dir, "#define E 1\n" + rest, e).OutputIgnoresUnknown();
        {
            // Stopping where E first matters gives the same answer.
            PlanOptions stop = e;
            stop.stop_when_unknown_matters = true;
            FileCache files;
            const IncludePaths paths{{dir.path()}, "", 0};
            Includer includer(paths, files);
            const InactiveTextPlan stopped = PlanInactiveText(
                "#define E 1\n" + rest, dir.path() + "/main.hlsl", includer, files, stop);
            EXPECT_EQ(stopped.OutputIgnoresUnknown(), ignores_e);
            stops += !stopped.complete;
        }
        if (ignores_e) {
            ++ignores;
            FileCache files;
            const IncludePaths paths{{dir.path()}, "", 0};
            std::vector<std::string> texts;
            for (const char* first : {"#define E 1\n", "#define E 0\n", "#define NOT_E 1\n"}) {
                Includer includer(paths, files);
                texts.push_back(frontend::Preprocess(pack::Stage::kFragment, first + rest,
                                                     dir.path() + "/main.hlsl", includer)
                                    .text);
            }
            EXPECT_EQ(texts[0], texts[1]);
            EXPECT_EQ(texts[0], texts[2]);
        }
        blanked += plan.blanked_lines;
        complete += plan.complete;
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "seed " << seed;
            break;
        }
    }
    // The generator gives the plan work to do: it blanks lines in most programs, and reaches the
    // end of many.
    EXPECT_GT(complete, 60u) << blanked;
    EXPECT_GT(ignores, 10u);
    EXPECT_GT(stops, 10u) << ignores;  // and stops early in some
    EXPECT_GT(blanked, 100000u) << complete;
    EXPECT_GT(spliced_runs, 100u);  // and serves plain lines short (hlsl/splice.h)
}

}  // namespace
}  // namespace kiln::hlsl
