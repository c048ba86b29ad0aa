#include "hlsl/plan_memo.h"

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hlsl/file_cache.h"
#include "hlsl/inactive_text.h"
#include "hlsl/includer.h"
#include "support/compile_support.h"
#include "unit/hlsl/random_program.h"

namespace kiln::hlsl {
namespace {

using test::ScratchDir;

// Everything a plan gives glslang and the worker, compared.
void ExpectSamePlan(const InactiveTextPlan& want, const InactiveTextPlan& got) {
    EXPECT_EQ(want.main_text, got.main_text);
    ASSERT_EQ(want.inclusions.size(), got.inclusions.size());
    for (size_t i = 0; i < want.inclusions.size(); ++i) {
        EXPECT_EQ(want.inclusions[i].path, got.inclusions[i].path) << i;
        EXPECT_EQ(want.inclusions[i].text, got.inclusions[i].text) << i;
    }
    EXPECT_EQ(want.complete, got.complete);
    EXPECT_EQ(want.blanked_lines, got.blanked_lines);
    EXPECT_EQ(want.maybe_branches, got.maybe_branches);
    EXPECT_EQ(want.unknown_only_in_conditions, got.unknown_only_in_conditions);
    EXPECT_EQ(want.spliced_runs, got.spliced_runs);
}

// The plan of `main` with `files` (whose memo may hold earlier walks), checked against the plan
// made without the memo.
InactiveTextPlan PlanChecked(const ScratchDir& dir,
                             FileCache& files,
                             const std::string& main,
                             const PlanOptions& options = {}) {
    const IncludePaths paths{{dir.path()}, "", 0};
    const std::string name = dir.path() + "/main.hlsl";
    Includer includer(paths, files);
    InactiveTextPlan got = PlanInactiveText(main, name, includer, files, options);
    PlanOptions walked = options;
    walked.remember = false;
    FileCache fresh;
    Includer alone(paths, fresh);
    const InactiveTextPlan want = PlanInactiveText(main, name, alone, fresh, walked);
    EXPECT_EQ(want.remembered_walks, 0u);
    ExpectSamePlan(want, got);
    return got;
}

TEST(PlanMemo, ReplaysAWalkThatWouldReadWhatAnEarlierOneRead) {
    ScratchDir dir;
    dir.Write("a.h", "#ifdef K\n#define A 1\n#else\n#define A 2\n#endif\n#include \"b.h\"\n");
    dir.Write("b.h", "#if A == 1\nfloat one;\n#else\nfloat two;\n#endif\n#define B A\n");
    FileCache files;
    const std::string use = "#include \"a.h\"\nfloat b = B;\n";
    EXPECT_EQ(PlanChecked(dir, files, "#define K\n" + use).remembered_walks, 0u);
    // A name a.h does not read: a.h's walk is taken whole (b.h's with it).
    EXPECT_EQ(PlanChecked(dir, files, "#define K\n#define OTHER 3\n" + use).remembered_walks, 1u);
    // K undefined: a.h reads it as it was not, and so b.h reads A as 2.
    EXPECT_EQ(PlanChecked(dir, files, use).remembered_walks, 0u);
    // K defined to another body: a.h's walk is not taken (a body can matter where #if reads
    // it), but b.h's is, as A is 1 again.
    EXPECT_EQ(PlanChecked(dir, files, "#define K 7\n" + use).remembered_walks, 1u);
    // b.h alone, with A as a.h left it: not taken, as b.h is read from another depth (which
    // Includer::kMaxDepth makes part of what a walk depends on).
    EXPECT_EQ(PlanChecked(dir, files, "#define A 1\n#include \"b.h\"\n").remembered_walks, 0u);
    // Each is remembered: the three again, all taken.
    for (const std::string& main : {"#define K\n" + use, use, "#define K 7\n" + use})
        EXPECT_EQ(PlanChecked(dir, files, main).remembered_walks, 1u) << main;
}

TEST(PlanMemo, AFileThatChangedIsWalkedAgain) {
    ScratchDir dir;
    dir.Write("a.h", "#include \"b.h\"\n#ifdef FROM_B\nfloat from_b;\n#endif\n");
    dir.Write("b.h", "#define FROM_B 1\n");
    FileCache files;
    const std::string main = "#include \"a.h\"\n";
    PlanChecked(dir, files, main);
    EXPECT_EQ(PlanChecked(dir, files, main).remembered_walks, 1u);
    // The cache serves b.h's new text (as a worker's does when the client's file changed).
    files.Put(std::make_shared<const SourceFile>(dir.path() + "/b.h", "#define NOT_FROM_B 1\n"));
    const IncludePaths paths{{dir.path()}, "", 0};
    Includer includer(paths, files);
    const InactiveTextPlan plan =
        PlanInactiveText(main, dir.path() + "/main.hlsl", includer, files, {});
    EXPECT_EQ(plan.remembered_walks, 0u);
    ASSERT_EQ(plan.inclusions.size(), 2u);
    EXPECT_EQ(plan.inclusions[0].text.find("from_b;"), std::string::npos);  // blanked now
}

TEST(PlanMemo, AWalkThatStoppedStopsThePlanWhenTaken) {
    ScratchDir dir;
    dir.Write("a.h", "#if FN(1)\n#include \"b.h\"\n#endif\nfloat after;\n");
    dir.Write("b.h", "float b;\n");
    FileCache files;
    const std::string use = "#define FN(x) x\n#include \"a.h\"\n#define LATER 1\n";
    EXPECT_FALSE(PlanChecked(dir, files, use).complete);
    const InactiveTextPlan again = PlanChecked(dir, files, "#define OTHER 1\n" + use);
    EXPECT_EQ(again.remembered_walks, 1u);
    EXPECT_FALSE(again.complete);
}

TEST(PlanMemo, AWalkKeepsWhatItFoundWhateverThePlanHadFound) {
    ScratchDir dir;
    dir.Write("first.h", "int a = E;\n");
    dir.Write("f.h", "int b = E;\n");
    PlanOptions e;
    e.unknown = {"E"};
    FileCache files;
    // f.h is walked where the plan had found E named outside a condition already.
    EXPECT_FALSE(PlanChecked(dir, files, "#include \"first.h\"\n#include \"f.h\"\n", e)
                     .unknown_only_in_conditions);
    const InactiveTextPlan alone = PlanChecked(dir, files, "#include \"f.h\"\n", e);
    EXPECT_EQ(alone.remembered_walks, 1u);
    EXPECT_FALSE(alone.unknown_only_in_conditions);
}

TEST(PlanMemo, RandomProgramsPlanAsWithoutIt) {
    size_t remembered = 0;
    for (uint32_t seed = 1; seed <= 150; ++seed) {
        ScratchDir dir;
        test::RandomProgram g(seed);
        g.WriteIncludes(dir);
        const std::string body = "#define FN(x) x\n" + g.File(0, 4);
        PlanOptions options;
        options.drop_needless = true;
        options.splice = true;
        PlanOptions e = options;
        e.unknown = {"E"};
        FileCache files;
        // Variants of one program, as a pass's keywords make them.
        for (const char* first :
             {"", "#define A 1\n", "#define B 2\n", "#define A 1\n#define B 2\n", "#define C\n", "",
              "#define A 1\n"}) {
            remembered += PlanChecked(dir, files, first + body, options).remembered_walks;
            PlanChecked(dir, files, first + body, e);
        }
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "seed " << seed;
            break;
        }
    }
    EXPECT_GT(remembered, 300u);
}

}  // namespace
}  // namespace kiln::hlsl
