// libFuzzer target: the inactive-text plan against glslang itself. The bytes are a program's main
// text (its #includes resolve in Kiln's templates/); glslang must preprocess it alike as it is and
// with the plan's blanked texts, text and messages (and with the directives it needs not blanked
// too, PlanOptions::drop_needless, where that gives no message: the worker preprocesses a program
// with messages again without), and with the first byte's low bit set the plan
// also takes one macro as unknown and, where it says the output does not depend on it, glslang
// must give the same text for it defined to 0 and to 1. With its second bit set, two variants of
// the program (one keyword each) are preprocessed with the shared include prefix
// (worker/preamble.h) too, and wherever it is used the output must be glslang's for the whole
// program. A second plan, which takes its walks of #includes from the first's
// (hlsl/plan_memo.h), must be the plan made without them, and glslang's outputs for those walks,
// kept and replayed (hlsl/output_memo.h), must be the program's. Any difference aborts. The
// skeleton and #if evaluation run on every directive line too. The corpus (corpus/preprocess,
// templates/) is replayed by ctest in every build through fuzz_replay_main.cpp.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "frontend/glslang_stage.h"
#include "hlsl/inactive_text.h"
#include "hlsl/lean_text.h"
#include "hlsl/pp_macros.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/preamble.h"
#include "hlsl/splice.h"
#include "worker/preamble.h"

namespace {

using namespace kiln;

void Check(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "inactive_text_fuzz: %s\n", what);
        std::abort();
    }
}

bool SamePlan(const hlsl::InactiveTextPlan& a, const hlsl::InactiveTextPlan& b) {
    if (a.main_text != b.main_text || a.inclusions.size() != b.inclusions.size() ||
        a.complete != b.complete || a.blanked_lines != b.blanked_lines ||
        a.maybe_branches != b.maybe_branches ||
        a.unknown_only_in_conditions != b.unknown_only_in_conditions)
        return false;
    for (size_t i = 0; i < a.inclusions.size(); ++i) {
        if (a.inclusions[i].path != b.inclusions[i].path ||
            a.inclusions[i].text != b.inclusions[i].text)
            return false;
    }
    return true;
}

std::string Preprocess(const std::string& text, hlsl::Includer& includer) {
    return frontend::Preprocess(pack::Stage::kFragment, text, "main.hlsl", includer).text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const hlsl::PpSkeleton skeleton = hlsl::ScanSkeleton(text);
    hlsl::PpMacros macros;
    for (const hlsl::PpDirective& d : skeleton.directives) {
        (void)macros.If(d.rest);
        (void)macros.Ifdef(d.rest);
        if (d.kind == hlsl::PpKind::kDefine)
            (void)macros.Define(d.rest);
    }
    hlsl::FileCache files;
    const hlsl::IncludePaths paths{{}, KILN_TEMPLATES_DIR, 0};
    hlsl::Includer plain(paths, files);
    const frontend::StageOutput want =
        frontend::Preprocess(pack::Stage::kFragment, text, "main.hlsl", plain);
    hlsl::Includer planned(paths, files);
    const hlsl::InactiveTextPlan plan = hlsl::PlanInactiveText(text, "main.hlsl", planned, files);
    planned.UsePlan(&plan);
    const frontend::StageOutput got =
        frontend::Preprocess(pack::Stage::kFragment, plan.main_text, "main.hlsl", planned);
    Check(want.ok == got.ok && want.text == got.text && want.info_log == got.info_log,
          "blanking changed glslang's preprocessing");
    // The same program again takes its walks of #includes from the memo (hlsl/plan_memo.h): it
    // plans as a walk without the memo does.
    {
        hlsl::Includer again(paths, files);
        const hlsl::InactiveTextPlan remembered =
            hlsl::PlanInactiveText(text, "main.hlsl", again, files);
        hlsl::PlanOptions walked;
        walked.remember = false;
        hlsl::Includer fresh(paths, files);
        Check(SamePlan(remembered, hlsl::PlanInactiveText(text, "main.hlsl", fresh, files, walked)),
              "a walk taken from the memo planned otherwise");
    }
    // The program itself served lean (hlsl/lean_text.h), as the plan serves each include.
    const hlsl::LeanText lean = hlsl::MakeLeanText(text, skeleton);
    hlsl::Includer leaned(paths, files);
    const frontend::StageOutput lean_out =
        frontend::Preprocess(pack::Stage::kFragment, lean.text, "main.hlsl", leaned);
    Check(
        want.ok == lean_out.ok && want.text == lean_out.text && want.info_log == lean_out.info_log,
        "leaving out what glslang reads in vain changed its preprocessing");
    // Spliced three times, as a worker preprocesses variants: the second keeps glslang's output
    // for each #include whose walk the memo took (hlsl/output_memo.h), the third replays it.
    for (const int round : {0, 1, 2, 3}) {
        const bool splice = round > 0;
        hlsl::PlanOptions options;
        options.drop_needless = true;
        options.splice = splice;  // hlsl/splice.h
        hlsl::Includer includer(paths, files);
        const hlsl::InactiveTextPlan needless =
            hlsl::PlanInactiveText(text, "main.hlsl", includer, files, options);
        includer.UsePlan(&needless);
        frontend::StageOutput out =
            frontend::Preprocess(pack::Stage::kFragment, needless.main_text, "main.hlsl", includer);
        // A program with messages, or whose output is not as MakeWhole expects, is
        // preprocessed again without them (worker/execute.cpp).
        if (out.ok && out.info_log.empty() &&
            hlsl::MakeWhole(out.text, needless, &files.output_memo())) {
            Check(want.ok && want.info_log.empty() && want.text == out.text,
                  splice ? "serving plain lines short changed glslang's preprocessing"
                         : "blanking needless directives changed glslang's preprocessing");
        }
    }
    if (size > 0 && (data[0] & 1)) {
        hlsl::PlanOptions options;
        options.unknown = {"KILN_FUZZ_UNKNOWN"};
        const std::string one = "#define KILN_FUZZ_UNKNOWN 1\n" + text;
        hlsl::Includer a(paths, files);
        if (hlsl::PlanInactiveText(one, "main.hlsl", a, files, options).OutputIgnoresUnknown()) {
            hlsl::Includer b(paths, files);
            const std::string zero = "#define KILN_FUZZ_UNKNOWN 0\n" + text;
            Check(Preprocess(one, a) == Preprocess(zero, b),
                  "the output depends on a macro the plan says it does not");
        }
    }
    if (size > 0 && (data[0] & 2)) {
        hlsl::PreambleCache cache;
        for (const char* keyword : {"KILN_FUZZ_K1", "KILN_FUZZ_K2"}) {
            worker::Request r;
            r.kind = worker::RequestKind::kPreprocess;
            r.stage = pack::Stage::kFragment;
            r.name = "main.hlsl";
            r.source = "#define " + std::string(keyword) + " 1\n" + text;
            r.templates_dir = KILN_TEMPLATES_DIR;
            r.pinned = {"KILN_FUZZ_K1", "KILN_FUZZ_K2"};
            worker::ExecuteContext context{files, {}, &cache};
            hlsl::Includer includer(paths, files);
            bool for_both = false;
            const auto shared = worker::PreprocessWithPreamble(
                r, context, includer, hlsl::ScanSkeleton(r.source), for_both);
            if (!shared)
                continue;
            hlsl::Includer whole(paths, files);
            const frontend::StageOutput want_whole =
                frontend::Preprocess(r.stage, r.source, r.name, whole);
            Check(shared->ok == want_whole.ok && shared->text == want_whole.text &&
                      shared->info_log == want_whole.info_log,
                  "the shared preamble changed glslang's preprocessing");
        }
    }
    return 0;
}
