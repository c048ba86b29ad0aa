#include "hlsl/output_memo.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/glslang_stage.h"
#include "hlsl/blank_inclusions.h"
#include "hlsl/file_cache.h"
#include "hlsl/inactive_text.h"
#include "hlsl/includer.h"
#include "support/compile_support.h"

namespace kiln::hlsl {
namespace {

using test::ScratchDir;

// What preprocessing one program with the worker's plan did with the memo of `files`.
struct Outcome {
    size_t replayed = 0;
    size_t recorded = 0;
};

// Preprocesses `main` as the worker does (a plan with its needless directives dropped and its
// plain lines spliced, the memo of `files` kept from program to program) and checks glslang's
// output, made whole, against its preprocessing of the program as it is.
Outcome Preprocessed(const ScratchDir& dir, FileCache& files, const std::string& main) {
    const IncludePaths paths{{dir.path()}, "", 0};
    const std::string name = dir.path() + "/main.hlsl";
    FileCache fresh;
    Includer plain(paths, fresh);
    const frontend::StageOutput want =
        frontend::Preprocess(pack::Stage::kFragment, main, name, plain);
    EXPECT_TRUE(want.ok && want.info_log.empty()) << want.info_log;
    PlanOptions options;
    options.drop_needless = true;
    options.splice = true;
    Includer planned(paths, files);
    const InactiveTextPlan plan = PlanInactiveText(main, name, planned, files, options);
    EXPECT_TRUE(plan.complete);
    planned.UsePlan(&plan);
    frontend::StageOutput got =
        frontend::Preprocess(pack::Stage::kFragment, plan.main_text, name, planned);
    EXPECT_TRUE(got.ok && got.info_log.empty()) << got.info_log;
    EXPECT_TRUE(MakeWhole(got.text, plan, &files.output_memo())) << main;
    EXPECT_EQ(want.text, got.text) << main;
    // Every file is among those the compile read, replayed or not.
    EXPECT_EQ(planned.Served(), plain.Served());
    Outcome o;
    for (const OutputMark& m : plan.outputs)
        ++(m.output ? o.replayed : o.recorded);
    return o;
}

// A tree of includes whose code uses macros defined before it, in it and after it, in a file
// that ends without a line break, and a #pragma.
void WriteTree(ScratchDir& dir) {
    dir.Write("leaf.h",
              "#ifndef LEAF_H\n#define LEAF_H\n"
              "#define SCALE(x) ((x) * FACTOR)\n"
              "float leaf(float v) { return SCALE(WRAP(v)) + OFFSET; }\n"
              "#pragma pack_matrix(row_major)\n"
              "#endif");  // no line break at the end
    dir.Write("mid.h",
              "#include \"leaf.h\"\n"
              "#ifdef USE_TWO\n#define MID 2.0\n#else\n#define MID 1.0\n#endif\n"
              "float mid(float v) { return leaf(v) * MID; }\n"
              "  float indented = mid(1.0) + leaf(2.0) + 3.0;\n");
    dir.Write("top.h", "#include \"mid.h\"\nfloat top(float v) { return mid(v) + TOP_BIAS; }\n");
}

std::string Program(const std::string& before, const std::string& after = "") {
    return before + "#include \"top.h\"\nfloat4 main() : SV_Target { return top(MID) + " +
           "SCALE(2.0); }\n" + after;
}

// The macros the tree's code expands, defined before it.
std::string Defines(const std::string& factor = "#define FACTOR 2.0\n",
                    const std::string& top_bias = "#define TOP_BIAS 1.0\n",
                    const std::string& wrap = "#define WRAP(a) a\n") {
    return factor + "#define OFFSET 0.5\n" + top_bias + wrap;
}

TEST(OutputMemo, ReplaysAnIncludeGlslangReadBeforeWithTheSameMacros) {
    ScratchDir dir;
    WriteTree(dir);
    FileCache files;
    const std::string main = Program(Defines());
    // The first program walks the files, the second takes the walk from the plan memo and
    // records glslang's output for it, the ones after replay it.
    Outcome o = Preprocessed(dir, files, main);
    EXPECT_EQ(o.replayed + o.recorded, 0u);
    o = Preprocessed(dir, files, main);
    EXPECT_EQ(o.recorded, 1u);
    EXPECT_EQ(o.replayed, 0u);
    for (int i = 0; i < 2; ++i) {
        o = Preprocessed(dir, files, main);
        EXPECT_EQ(o.replayed, 1u);
    }
    // What it defines is read after it as before (MID, SCALE), also where the program goes on
    // differently after the #include.
    o = Preprocessed(dir, files, main + "float more = MID + SCALE(MID);\n");
    EXPECT_EQ(o.replayed, 1u);
}

TEST(OutputMemo, DoesNotReplayWhereAMacroItReadsDiffers) {
    ScratchDir dir;
    WriteTree(dir);
    FileCache files;
    const std::string first = Program(Defines());
    for (int i = 0; i < 3; ++i)
        Preprocessed(dir, files, first);
    // Another value of a macro a nested file's code expands (through SCALE's body, defined in the
    // walk), of one the top file expands, a function-like macro of the same body with other
    // parameters, and a macro defined as another (twice, the other's value differing): each a
    // new output.
    const std::vector<std::string> others = {
        Program(Defines("#define FACTOR 3.0\n")),
        Program(Defines("#define FACTOR 2.0\n", "#define TOP_BIAS 2.0\n")),
        Program(Defines("#define FACTOR 2.0\n", "#define TOP_BIAS 1.0\n", "#define WRAP(b) a\n")),
        Program(Defines("#define F2 2.0\n#define FACTOR F2\n")),
        Program(Defines("#define F2 4.0\n#define FACTOR F2\n")),
    };
    for (const std::string& main : others)
        EXPECT_EQ(Preprocessed(dir, files, main).replayed, 0u) << main;
    // A macro the walk does not name may differ: the output is replayed.
    EXPECT_EQ(Preprocessed(dir, files, "#define UNRELATED 7\n" + first).replayed, 1u);
    // Branches decided otherwise are another walk.
    const std::string two = Program("#define USE_TWO\n" + Defines());
    for (int i = 0; i < 3; ++i)
        Preprocessed(dir, files, two);
    EXPECT_EQ(Preprocessed(dir, files, two).replayed, 1u);
}

TEST(OutputMemo, DoesNotRememberWhatDependsOnWhereItIsRead) {
    ScratchDir dir;
    dir.Write("file.h", "float f = 1.0 + 2.0 + 3.0;\nstatic const int from = __FILE__;\n");
    dir.Write("line.h", "float g = 1.0 + 2.0 + 3.0;\n#line 40\nfloat h = 1.0 + 2.0 + 3.0;\n");
    // Its first token is on its first line: glslang spaces it by the token before the #include.
    dir.Write("first.h", "float k = 1.0 + 2.0 + 3.0;\n#define FIRST_H\n");
    FileCache files;
    // file.h and line.h are not even marked; first.h is marked to be recorded from the second
    // program on (where the plan memo takes its walk again), and never kept: the token before it,
    // `;` in one program and `}` in the other, spaces its first otherwise.
    for (int i = 0; i < 6; ++i) {
        const std::string main = std::string("#include \"file.h\"\n#include \"line.h\"\n") +
                                 (i % 2 ? "float x = 1.0;\n" : "float y[2] = {1.0, 2.0}\n") +
                                 "#include \"first.h\"\nfloat4 main() : SV_Target { return f; }\n";
        const Outcome o = Preprocessed(dir, files, main);
        EXPECT_EQ(o.replayed, 0u);
        EXPECT_EQ(o.recorded, i == 0 ? 0u : 1u) << i;
    }
}

TEST(OutputMemo, MarkedNamesAreGivenBack) {
    EXPECT_EQ(UnmarkedName(OutputMarkName(12, "/a/b.h")), "/a/b.h");
    EXPECT_EQ(UnmarkedName("/a/b.h"), "/a/b.h");
    // An output without the marks a plan expects is not made whole.
    OutputMark m;
    m.inclusion = 3;
    m.count = 1;
    std::string text = "#line 1 \"/a/b.h\"\nfloat x;\n";
    EXPECT_FALSE(RestoreOutputs(text, {m}, nullptr));
    EXPECT_EQ(text, "#line 1 \"/a/b.h\"\nfloat x;\n");
    text = "#line 1 \"" + OutputMarkName(3, "/a/b.h") + "\"\nfloat x;\n#line 2 \"main\"\n";
    EXPECT_TRUE(RestoreOutputs(text, {m}, nullptr));
    EXPECT_EQ(text, "#line 1 \"/a/b.h\"\nfloat x;\n#line 2 \"main\"\n");
}

}  // namespace
}  // namespace kiln::hlsl
