#include "worker/preamble.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "hlsl/preamble.h"
#include "support/compile_support.h"
#include "unit/hlsl/random_program.h"

namespace kiln::worker {
namespace {

using test::ScratchDir;

struct Both {
    std::optional<frontend::StageOutput> shared;  // with the preamble, when it was used
    frontend::StageOutput plain;                  // glslang on the program as it is
    bool for_both = false;
};

// Preprocesses `source` (with the pinned keywords) with the shared preamble and as it is. Where
// the preamble was used, the two must be the same, text and messages.
Both PreprocessBothWays(const ScratchDir& dir,
                        hlsl::FileCache& files,
                        hlsl::PreambleCache& cache,
                        const std::string& source,
                        const std::vector<std::string>& pinned,
                        const std::string& second_entry = "") {
    Request r;
    r.kind = RequestKind::kPreprocess;
    r.stage = pack::Stage::kFragment;
    r.name = dir.path() + "/main.hlsl";
    r.source = source;
    r.include_dirs = {dir.path()};
    r.pinned = pinned;
    r.second_entry = second_entry;
    const hlsl::IncludePaths paths{r.include_dirs, "", 0};
    ExecuteContext context{files, {}, &cache};
    hlsl::Includer includer(paths, files);
    Both b;
    std::shared_ptr<const hlsl::Preamble> used;
    b.shared = PreprocessWithPreamble(r, context, includer, hlsl::ScanSkeleton(r.source),
                                      b.for_both, &used);
    hlsl::Includer plain(paths, files);
    b.plain = frontend::Preprocess(r.stage, source, r.name, plain);
    if (b.shared) {
        EXPECT_EQ(includer.Served(), plain.Served());  // for depfiles and the direct mode
        EXPECT_EQ(b.shared->ok, b.plain.ok);
        EXPECT_EQ(b.shared->text, b.plain.text) << source;
        EXPECT_EQ(b.shared->info_log, b.plain.info_log);
        // The prefix's tokens, made once, with the rest's are the whole text's.
        EXPECT_TRUE(used);
        if (!used)
            return b;
        EXPECT_EQ(b.shared->text.compare(0, used->output.size(), used->output), 0);
        const std::vector<hlsl::Token> joined =
            hlsl::TokenizeAfter(b.shared->text, used->output.size(), used->tokens);
        const std::vector<hlsl::Token> whole = hlsl::Tokenize(b.plain.text);
        EXPECT_EQ(joined.size(), whole.size());
        for (size_t i = 0; i < std::min(joined.size(), whole.size()); ++i) {
            EXPECT_TRUE(joined[i].begin == whole[i].begin && joined[i].end == whole[i].end &&
                        joined[i].ident == whole[i].ident && joined[i].text == whole[i].text)
                << i;
        }
    }
    return b;
}

std::string Variant(const std::string& keyword, const std::string& body) {
    return "#line 1 \"<prelude>\"\n#define SHADER_API_VULKAN 1\n#define " + keyword +
           " 1\n#line 1 \"main.hlsl\"\n" + body;
}

const char* const kLighting =
    "#ifndef LIGHTING_H\n#define LIGHTING_H\n#include \"common.h\"\n"
    "float3 Light(float3 n) { return n * SCALE; }\n"
    "#if SHADER_API_VULKAN\n#define FLIP(x) (-(x))\n#else\n#define FLIP(x) (x)\n#endif\n"
    "#endif\n";
const char* const kCommon = "#define SCALE 0.5\nstruct Common { float a; };\n";

TEST(Preamble, SharesTheIncludePrefixAndJoinsGlslangsOutputExactly) {
    ScratchDir dir;
    dir.Write("lighting.h", kLighting);
    dir.Write("common.h", kCommon);
    hlsl::FileCache files;
    hlsl::PreambleCache cache;
    const std::string body =
        "#pragma multi_compile K1 K2\n#include \"lighting.h\"\n#include \"common.h\"\n\n"
        "float4 frag() : SV_Target {\n#ifdef K1\n  return FLIP(SCALE);\n#else\n"
        "  return Light(float3(1, 2, 3)).x;\n#endif\n}\n";
    const Both k1 = PreprocessBothWays(dir, files, cache, Variant("K1", body), {"K1", "K2"});
    const Both k2 = PreprocessBothWays(dir, files, cache, Variant("K2", body), {"K1", "K2"});
    ASSERT_TRUE(k1.shared && k2.shared);
    EXPECT_NE(k1.plain.text, k2.plain.text);  // the keyword changes the rest of the program
    EXPECT_EQ(cache.size(), 1u);              // and both variants shared one preamble
    EXPECT_NE(k1.plain.text.find("(-(0.5))"), std::string::npos) << k1.plain.text;
    // The stage is not named after the cut: the output holds for both stages.
    const Both paired =
        PreprocessBothWays(dir, files, cache, Variant("K1", body), {"K1", "K2"}, "vert");
    ASSERT_TRUE(paired.shared);
    EXPECT_TRUE(paired.for_both);
}

TEST(Preamble, RefusesWhatItCannotProveAndTheCallerPreprocessesWhole) {
    ScratchDir dir;
    dir.Write("lighting.h", kLighting);
    dir.Write("common.h", kCommon);
    dir.Write("keyword.h", "#ifdef K1\nfloat k1;\n#endif\n");
    dir.Write("names.h", "#define USES_K K1\n");
    hlsl::FileCache files;
    hlsl::PreambleCache cache;
    auto shared = [&](const std::string& body) {
        return PreprocessBothWays(dir, files, cache, Variant("K1", body), {"K1", "K2"})
            .shared.has_value();
    };
    EXPECT_TRUE(shared("#include \"lighting.h\"\n\nfloat f;\n"));
    // An include that tests a keyword, or a macro that names one.
    EXPECT_FALSE(shared("#include \"keyword.h\"\n\nfloat f;\n"));
    EXPECT_FALSE(shared("#include \"names.h\"\n\nfloat f = USES_K;\n"));
    // Code on the line after the last include: glslang spaces it by the include's last token.
    EXPECT_FALSE(shared("#include \"lighting.h\"\nfloat f;\n"));
    // A #line after the cut, or nothing after it.
    EXPECT_FALSE(shared("#include \"lighting.h\"\n#line 40\nfloat f;\n"));
    EXPECT_FALSE(shared("#include \"lighting.h\""));
    // Any message: a redefinition after the cut (glslang's error) is left to the whole run.
    EXPECT_FALSE(shared("#include \"common.h\"\n\n#define SCALE 2\nfloat f;\n"));
    // No include at all.
    EXPECT_FALSE(shared("float f;\n"));
}

TEST(Preamble, AFileChangedSinceIsReadAgain) {
    ScratchDir dir;
    dir.Write("common.h", kCommon);
    hlsl::FileCache files;
    hlsl::PreambleCache cache;
    const std::string body = "#include \"common.h\"\n\nfloat f = SCALE;\n";
    ASSERT_TRUE(PreprocessBothWays(dir, files, cache, Variant("K1", body), {"K1"}).shared);
    // A FileCache that reads the file's new text makes a new preamble.
    dir.Write("common.h", "#define SCALE 2.0\n");
    hlsl::FileCache fresh;
    const Both b = PreprocessBothWays(dir, fresh, cache, Variant("K1", body), {"K1"});
    ASSERT_TRUE(b.shared);
    EXPECT_NE(b.shared->text.find("2.0"), std::string::npos);
}

TEST(Preamble, ReplaysOnlyTheMacrosTheRestCanExpand) {
    hlsl::Preamble p;
    hlsl::SetMacros(p, {{"A", " A B + 1"},
                        {"B", " B 2"},
                        {"C", " C 3"},
                        {"SAMPLE", " SAMPLE(t) sampler##t"},
                        {"samplerX", " samplerX 4"},
                        {"ST", " ST(n) n##_ST"},
                        {"Y_ST", " Y_ST 5"},
                        {"CAT", " CAT(a, b) a##b"}});
    EXPECT_EQ(hlsl::MacrosFor(p, "float f = A;"), "#define A B + 1\n#define B 2\n");
    EXPECT_EQ(hlsl::MacrosFor(p, "float x;"), "");
    // A pasted parameter makes a name that starts (or ends) with the name pasted to it.
    EXPECT_EQ(hlsl::MacrosFor(p, "SAMPLE(X)"),
              "#define SAMPLE(t) sampler##t\n#define samplerX 4\n");
    EXPECT_EQ(hlsl::MacrosFor(p, "ST(Y)"), "#define ST(n) n##_ST\n#define Y_ST 5\n");
    // Two parameters pasted, or a paste of the rest's own, may make any name: all of them.
    for (const char* rest : {"CAT(x, y)", "#define D(a) a##1\n"}) {
        const std::string all = hlsl::MacrosFor(p, rest);
        EXPECT_EQ(std::count(all.begin(), all.end(), '\n'), 8) << rest;
    }
}

// Random include trees (tests/unit/hlsl/random_program.h) with a shared tail that tests the
// keyword: wherever the preamble is used, glslang's output is the same as for the whole program.
TEST(Preamble, RandomProgramsJoinAlike) {
    size_t used = 0;
    for (uint32_t seed = 1; seed <= 200; ++seed) {
        ScratchDir dir;
        test::RandomProgram g(seed);
        g.WriteIncludes(dir);
        const std::string body = "#define FN(x) x\n" + g.File(0, 4) + "#include \"f3.h\"\n\n" +
                                 "float tail = B + FN(C);\n#if K1\nfloat k = D;\n#endif\n";
        hlsl::FileCache files;
        hlsl::PreambleCache cache;
        for (const char* keyword : {"K1", "K2"}) {
            const Both b =
                PreprocessBothWays(dir, files, cache, Variant(keyword, body), {"K1", "K2"});
            used += b.shared.has_value();
        }
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "seed " << seed;
            break;
        }
    }
    EXPECT_GT(used, 30u) << used;  // the generator gives the preamble work to do
}

}  // namespace
}  // namespace kiln::worker
