// glslang's preprocessing of a program as it is and as an inactive-text plan serves it, compared:
// the tests of the plan, its needless directives and its splicing (hlsl/inactive_text.h,
// hlsl/splice.h).
#ifndef KILN_TESTS_UNIT_HLSL_PREPROCESS_ALIKE_H_
#define KILN_TESTS_UNIT_HLSL_PREPROCESS_ALIKE_H_

#include <string>

#include <gtest/gtest.h>

#include "frontend/glslang_stage.h"
#include "hlsl/file_cache.h"
#include "hlsl/inactive_text.h"
#include "hlsl/includer.h"
#include "hlsl/splice.h"
#include "support/compile_support.h"

namespace kiln::test {

// glslang's preprocessing of `main` as it is, and with the plan's blanked texts: they must be
// the same, text and messages (with PlanOptions::drop_needless, only where the plan's gives no
// message). Returns the plan.
inline hlsl::InactiveTextPlan ExpectSamePreprocessing(const ScratchDir& dir,
                                                      const std::string& main,
                                                      const hlsl::PlanOptions& options = {}) {
    hlsl::FileCache files;
    const hlsl::IncludePaths paths{{dir.path()}, "", 0};
    const std::string name = dir.path() + "/main.hlsl";
    hlsl::Includer plain(paths, files);
    const frontend::StageOutput want =
        frontend::Preprocess(pack::Stage::kFragment, main, name, plain);
    hlsl::Includer planned(paths, files);
    hlsl::InactiveTextPlan plan = hlsl::PlanInactiveText(main, name, planned, files, options);
    planned.UsePlan(&plan);
    frontend::StageOutput got =
        frontend::Preprocess(pack::Stage::kFragment, plan.main_text, name, planned);
    if (options.drop_needless && (!got.ok || !got.info_log.empty())) {
        // The worker preprocesses the program again without PlanOptions::drop_needless.
        EXPECT_TRUE(!want.ok || !want.info_log.empty()) << got.info_log;
        return plan;
    }
    if (want.ok) {  // glslang stops at its first error, and asks for no more files
        EXPECT_EQ(planned.served_from_plan(), plan.inclusions.size());
    }
    if (options.splice) {  // hlsl/splice.h, hlsl/blank_inclusions.h
        EXPECT_TRUE(hlsl::MakeWhole(got.text, plan)) << main;
    }
    EXPECT_EQ(want.ok, got.ok);
    EXPECT_EQ(want.text, got.text) << main;
    EXPECT_EQ(want.info_log, got.info_log);
    return plan;
}

}  // namespace kiln::test

#endif  // KILN_TESTS_UNIT_HLSL_PREPROCESS_ALIKE_H_
