// Preprocess sharing (driver/preprocess.cpp): stage programs whose assembled texts are equal
// (variants differing only in a fragment-only keyword, for the vertex stage) are preprocessed
// once, and a variant's fragment stage takes its vertex preprocess when nothing tests the stage;
// the pack is what preprocessing each would give, and a failing preprocess is still reported for
// every variant it fails in.
#include <gtest/gtest.h>

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

// 6 variants: BIG changes the vertex stage; RED and BLUE only the fragment stage.
std::string Shader(const std::string& vertex_extra = "") {
    return "Shader \"Test/Shared\" {\n"
           "    SubShader { Pass {\n"
           "            CGPROGRAM\n"
           "            #pragma vertex vert\n"
           "            #pragma fragment frag\n"
           "            #pragma multi_compile _ BIG\n"
           "            #pragma multi_compile_fragment _ RED BLUE\n" +
           vertex_extra +
           "            float4 vert(float4 p : POSITION) : SV_POSITION {\n"
           "            #ifdef BIG\n"
           "                p.xyz *= 2;\n"
           "            #endif\n"
           "                return p;\n"
           "            }\n"
           "            float4 frag() : SV_Target {\n"
           "            #if defined(RED)\n"
           "                return float4(1, 0, 0, 1);\n"
           "            #elif defined(BLUE)\n"
           "                return float4(0, 0, 1, 1);\n"
           "            #endif\n"
           "                return 1;\n"
           "            }\n"
           "            ENDCG\n"
           "    } }\n"
           "}\n";
}

TEST(PreprocessSharing, AFragmentOnlyKeywordDoesNotPreprocessTheVertexStageAgain) {
    ScratchDir dir;
    CompileOptions options;
    const CompileRun run = Compile({dir.Write("shared.shader", Shader())}, options);
    ASSERT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(run.out.stats.variants, 6u);
    EXPECT_EQ(run.out.stats.stage_programs, 12u);
    // Vertex: 2 distinct texts (BIG or not) for 6 variants: 4 shared. Every fragment text
    // differs; those without RED or BLUE may also take their vertex preprocess (when theirs is
    // the first of its text): 2 more at most.
    EXPECT_GE(run.out.stats.shared_preprocesses, 4u);
    EXPECT_LE(run.out.stats.shared_preprocesses, 6u);
    EXPECT_EQ(run.out.stats.unique_programs, 5u);  // vertex 2, fragment 3 (BIG is vertex-only)
    EXPECT_EQ(run.out.stats.glslang_compiles, 5u);
}

// RED and BLUE in both stages here: every vertex text differs, and each variant's fragment text
// is its vertex text but for the stage's #define, so one preprocess serves both stages. A comment
// that names SHADER_STAGE_VERTEX turns that off (the text might test the stage); the packs agree.
TEST(PreprocessSharing, AVariantsTwoStagesShareOnePreprocessWhenNothingTestsTheStage) {
    ScratchDir dir;
    CompileOptions options;
    std::string text = Shader();
    text.replace(text.find("multi_compile_fragment"), 22, "multi_compile");
    const CompileRun paired = Compile({dir.Write("paired.shader", text)}, options);
    ASSERT_TRUE(paired.out.ok) << Brief(paired.diags);
    EXPECT_EQ(paired.out.stats.variants, 6u);
    EXPECT_EQ(paired.out.stats.shared_preprocesses, 6u);

    const std::string marked = text.replace(text.find("CGPROGRAM"), 9,
                                            "CGPROGRAM\n            // not SHADER_STAGE_VERTEX");
    const CompileRun alone = Compile({dir.Write("paired.shader", marked)}, options);
    ASSERT_TRUE(alone.out.ok) << Brief(alone.diags);
    EXPECT_EQ(alone.out.stats.shared_preprocesses, 0u);
    EXPECT_EQ(alone.out.stats.unique_programs, paired.out.stats.unique_programs);
    EXPECT_EQ(alone.out.pack, paired.out.pack);
}

TEST(PreprocessSharing, AFailingSharedPreprocessIsReportedForEveryVariant) {
    ScratchDir dir;
    CompileOptions options;
    const CompileRun run =
        Compile({dir.Write("fails.shader", Shader("            #if defined(BIG) && "
                                                  "defined(SHADER_STAGE_VERTEX)\n"
                                                  "            #error big vertex\n"
                                                  "            #endif\n"))},
                options);
    EXPECT_FALSE(run.out.ok);
    const std::string brief = Brief(run.diags);
    EXPECT_NE(brief.find("big vertex"), std::string::npos) << brief;
    EXPECT_NE(brief.find("3 of 6 variants"), std::string::npos) << brief;
}

// Streaming: a program is compiled by the thread that preprocessed it, as soon as it is. The
// pack and the messages are what compiling after the whole phase gives (keep_programs turns
// streaming off, as the kept texts must outlive the phase), whichever variant got there first.
TEST(PreprocessSharing, StreamedCompilesGiveThePackAndMessagesOfAPhaseAfterPhaseCompile) {
    ScratchDir dir;
    std::string text = Shader();
    text.replace(text.find("multi_compile_fragment"), 22, "multi_compile");
    const std::string path = dir.Write("streamed.shader", text);
    for (unsigned jobs : {1u, 2u, 4u}) {
        CompileOptions streamed, phased;
        streamed.jobs = phased.jobs = jobs;
        phased.keep_programs = true;
        const CompileRun a = Compile({path}, streamed);
        const CompileRun b = Compile({path}, phased);
        ASSERT_TRUE(a.out.ok) << Brief(a.diags);
        EXPECT_EQ(a.out.pack, b.out.pack) << jobs;
        EXPECT_EQ(a.out.stats.glslang_compiles, b.out.stats.glslang_compiles);
        EXPECT_EQ(a.out.stats.unique_programs, b.out.stats.unique_programs);
        EXPECT_GT(a.out.stats.work_ms.preprocess, 0);
        EXPECT_GT(a.out.stats.work_ms.compile, 0);
    }
    // An error that RED and BLUE share (one program, two tasks) and one of BIG's own: the same
    // messages at the same places either way.
    std::string broken = text;
    broken.replace(broken.find("return float4(1, 0, 0, 1);"), 26, "return missing_red(1);");
    broken.replace(broken.find("return float4(0, 0, 1, 1);"), 26, "return missing_red(1);");
    broken.replace(broken.find("p.xyz *= 2;"), 11, "p.xyz *= missing_big;");
    const std::string bad = dir.Write("broken.shader", broken);
    for (unsigned jobs : {1u, 4u}) {
        CompileOptions streamed, phased;
        streamed.jobs = phased.jobs = jobs;
        phased.keep_programs = true;
        const CompileRun a = Compile({bad}, streamed);
        const CompileRun b = Compile({bad}, phased);
        EXPECT_FALSE(a.out.ok);
        EXPECT_NE(Brief(a.diags).find("missing_red"), std::string::npos) << Brief(a.diags);
        EXPECT_NE(Brief(a.diags).find("missing_big"), std::string::npos) << Brief(a.diags);
        EXPECT_EQ(Brief(a.diags), Brief(b.diags)) << jobs;
    }
}

}  // namespace
}  // namespace kiln::test
