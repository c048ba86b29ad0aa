#include "worker/execute.h"

#include <cstdlib>
#include <optional>
#include <string_view>
#include <unordered_set>

#include "frontend/glslang_stage.h"
#include "hlsl/assemble.h"
#include "hlsl/inactive_text.h"
#include "hlsl/includer.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/reduce.h"
#include "hlsl/rewrite.h"
#include "hlsl/splice.h"
#include "spirv/optimize.h"
#include "worker/preamble.h"

namespace kiln::worker {
namespace {

void Enter(ExecuteContext& context, Component c) {
    if (context.phase)
        context.phase(c);
}

// True when the preprocessed text cannot depend on the stage: the source names SHADER_STAGE_
// once (the prelude's #define of its own stage) and no file it read names it at all. The two
// stages' sources then differ only in that #define (the driver checks), so they preprocess alike.
bool StageFree(const Request& r, ExecuteContext& context, const hlsl::Includer& includer) {
    constexpr std::string_view kStageMacro = "SHADER_STAGE_";
    const size_t first = r.source.find(kStageMacro);
    if (first == std::string::npos || r.source.find(kStageMacro, first + 1) != std::string::npos)
        return false;
    for (const std::string& path : includer.Served()) {
        const std::shared_ptr<const SourceFile> file = context.files.Get(path);
        if (!file || file->text().find(kStageMacro) != std::string::npos)
            return false;
    }
    return true;
}

// The check KILN_CHECK_INACTIVE_TEXT asks for: `source` preprocessed as it is must give `got`;
// with `text_only`, only the same text (the partner stage's source, whose messages name another
// stage). A difference becomes an internal error in `got`.
void CheckAgainstPlain(const Request& r,
                       pack::Stage stage,
                       const std::string& source,
                       const hlsl::Includer& includer,
                       bool text_only,
                       frontend::StageOutput& got) {
    hlsl::Includer plain = includer.Fresh();
    const frontend::StageOutput want = frontend::Preprocess(stage, source, r.name, plain);
    if (want.ok == got.ok && want.text == got.text && (text_only || want.info_log == got.info_log))
        return;
    size_t at = 0;
    while (at < want.text.size() && at < got.text.size() && want.text[at] == got.text[at])
        ++at;
    got.info_log = "ERROR: internal: blanking skipped text changed glslang's preprocessing" +
                   std::string(text_only ? " of the other stage" : "") + " (result " +
                   std::to_string(want.ok) + " -> " + std::to_string(got.ok) +
                   ", first difference at byte " + std::to_string(at) + ": '" +
                   want.text.substr(at, 80) + "' -> '" + got.text.substr(at, 80) + "')\n" +
                   want.info_log;
    got.ok = false;
}

// glslang's preprocessing of the program with the text it would skip blanked first
// (hlsl/inactive_text.h), the directives it does not need, its included files' plain lines
// served short (hlsl/splice.h) and its blank inclusions as one line break
// (hlsl/blank_inclusions.h), made whole after. With a partner entry, the plan
// first takes the two stages' macros as unknown: `for_both` says whether the output holds for both
// stages' sources then (they differ only in that #define; the driver checks). A program that
// gives messages is preprocessed again without the needless directives blanked or lines served
// short, as glslang's messages may count the conditionals open where it stopped (an #error); so
// is one whose output is not as MakeWhole expects.
frontend::StageOutput PreprocessPlanned(const Request& r,
                                        ExecuteContext& context,
                                        hlsl::Includer& includer,
                                        const hlsl::PpSkeleton& skeleton,
                                        bool& for_both) {
    hlsl::PlanOptions options;
    options.main_skeleton = &skeleton;
    options.drop_needless = true;
    options.splice = true;
    hlsl::InactiveTextPlan plan;
    for_both = false;
    if (!r.second_entry.empty()) {
        hlsl::PlanOptions both = options;
        both.unknown = {hlsl::StageMacro(pack::Stage::kVertex),
                        hlsl::StageMacro(pack::Stage::kFragment)};
        both.stop_when_unknown_matters = true;  // a plan that names the stage is made again
        plan = hlsl::PlanInactiveText(r.source, r.name, includer, context.files, both);
        for_both = plan.OutputIgnoresUnknown();
        if (for_both)
            options = both;
    }
    if (!for_both)
        plan = hlsl::PlanInactiveText(r.source, r.name, includer, context.files, options);
    includer.UsePlan(&plan);
    frontend::StageOutput out = frontend::Preprocess(r.stage, plan.main_text, r.name, includer);
    includer.UsePlan(nullptr);
    if (out.ok && out.info_log.empty() &&
        hlsl::MakeWhole(out.text, plan, &context.files.output_memo()))
        return out;
    options.drop_needless = false;
    options.splice = false;
    plan = hlsl::PlanInactiveText(r.source, r.name, includer, context.files, options);
    includer.UsePlan(&plan);
    out = frontend::Preprocess(r.stage, plan.main_text, r.name, includer);
    includer.UsePlan(nullptr);
    return out;
}

// glslang's preprocessing of the program: with its pass's include prefix shared
// (worker/preamble.h) where it can be, else planned as above. With KILN_CHECK_INACTIVE_TEXT set,
// the program is also preprocessed whole without blanking (and for both stages, when shared),
// and any difference is an internal error (the corpus tests run so).
frontend::StageOutput PreprocessBlanked(const Request& r,
                                        ExecuteContext& context,
                                        hlsl::Includer& includer,
                                        bool& for_both,
                                        std::shared_ptr<const hlsl::Preamble>& preamble) {
    const hlsl::PpSkeleton skeleton = hlsl::ScanSkeleton(r.source);
    std::optional<frontend::StageOutput> shared =
        PreprocessWithPreamble(r, context, includer, skeleton, for_both, &preamble);
    frontend::StageOutput out =
        shared ? std::move(*shared) : PreprocessPlanned(r, context, includer, skeleton, for_both);
    static const bool check = std::getenv("KILN_CHECK_INACTIVE_TEXT") != nullptr;
    if (!check)
        return out;
    CheckAgainstPlain(r, r.stage, r.source, includer, false, out);
    if (for_both) {
        const std::string vertex = "#define " + std::string(hlsl::StageMacro(pack::Stage::kVertex));
        const std::string fragment =
            "#define " + std::string(hlsl::StageMacro(pack::Stage::kFragment));
        const bool is_vertex = r.source.find(vertex) != std::string::npos;
        std::string other = r.source;
        const size_t at = other.find(is_vertex ? vertex : fragment);
        if (at != std::string::npos)
            other.replace(at, (is_vertex ? vertex : fragment).size(),
                          is_vertex ? fragment : vertex);
        CheckAgainstPlain(r, is_vertex ? pack::Stage::kFragment : pack::Stage::kVertex, other,
                          includer, true, out);
    }
    return out;
}

Response Preprocess(const Request& r, ExecuteContext& context, hlsl::Includer& includer) {
    Enter(context, Component::kGlslangPreprocessor);
    bool for_both = false;
    std::shared_ptr<const hlsl::Preamble> preamble;  // the shared prefix the output starts with
    frontend::StageOutput out = PreprocessBlanked(r, context, includer, for_both, preamble);
    Response resp;
    resp.ok = out.ok;
    resp.failed_in = out.ok ? Component::kNone : Component::kGlslangPreprocessor;
    resp.info_log = std::move(out.info_log);
    if (!out.ok)
        return resp;
    // Kiln's own steps run here too: the worker then answers with the (smaller) reduced text.
    // Reduced first, then rewritten: the rewrite reads only what the entry point reaches (about
    // a fifth of the text), and what it cannot reach is neither compiled nor warned about, as
    // fxc compiles only what an entry point calls.
    Enter(context, Component::kKilnReduction);
    std::vector<std::string> entries = {r.entry};
    if (!r.second_entry.empty() && (for_both || StageFree(r, context, includer)))
        entries.push_back(r.second_entry);
    // The shared prefix's tokens and split into items are made once, with the preamble: where
    // the program's output goes on from it with a line break (TokenizeAfter then starts with its
    // tokens).
    const size_t head = preamble ? preamble->output.size() : 0;
    const bool after = preamble && preamble->reduce_prefix && out.text.size() > head &&
                       out.text[head] == '\n' && out.text.compare(0, head, preamble->output) == 0;
    std::vector<hlsl::Reduced> reduced = hlsl::ReduceToEntryPoints(
        out.text,
        after ? hlsl::TokenizeAfter(out.text, head, preamble->tokens) : hlsl::Tokenize(out.text),
        entries, after ? preamble->reduce_prefix.get() : nullptr, !r.keep_declarations);
    bool changed = false;
    std::unordered_set<std::string> warned;  // a warning of code both entry points reach, once
    static const bool check = std::getenv("KILN_CHECK_INACTIVE_TEXT") != nullptr;
    for (hlsl::Reduced& one : reduced) {
        if (check && !hlsl::SameTokens(one.tokens, hlsl::Tokenize(one.text))) {
            resp.ok = false;
            resp.failed_in = Component::kKilnReduction;
            resp.info_log = "ERROR: internal: the reduced text's tokens are not its own\n";
            return resp;
        }
        hlsl::RewriteResult rewritten = hlsl::RewriteForGlslang(one.text, std::move(one.tokens));
        // Unity's warnings for what the rewrite changed, in glslang's form: the one place that
        // maps messages to .shader positions (frontend/glslang_messages.h) places them.
        for (const hlsl::RewriteWarning& w : rewritten.warnings) {
            std::string line = "WARNING: " + w.file + ":" + std::to_string(w.line) + ": '" +
                               w.token + "' : " + w.message + "\n";
            if (warned.insert(line).second)
                resp.info_log += line;
        }
        if (rewritten.changed()) {
            one.text = std::move(rewritten.text);
            changed = true;
        }
    }
    if (reduced.size() == 2) {
        resp.second_ok = true;
        resp.second_text = std::move(reduced[1].text);
        resp.second_functions = std::move(reduced[1].functions_if_entry_missing);
    }
    resp.text = std::move(reduced[0].text);
    resp.functions = std::move(reduced[0].functions_if_entry_missing);
    // The whole text rewritten, for the driver's exact messages should the program not compile
    // (compile_jobs.cpp); only where the program needed a rewrite, as glslang would trip on the
    // assembled source where the reduced program did not.
    if (changed)
        resp.rewritten = hlsl::RewriteForGlslang(out.text).text;
    return resp;
}

Response Compile(const Request& r, ExecuteContext& context, hlsl::Includer& includer) {
    Enter(context, Component::kGlslang);
    frontend::StageOutput out =
        frontend::Compile(r.stage, r.source, r.name, r.entry, includer, r.debug_info);
    Response resp;
    resp.ok = out.ok;
    resp.entry_missing = out.entry_missing;
    resp.info_log = std::move(out.info_log);
    if (!out.ok) {
        resp.failed_in = Component::kGlslang;
        return resp;
    }
    resp.words = std::move(out.spirv);
    if (!r.optimize)
        return resp;
    Enter(context, Component::kSpirvOpt);
    if (!spirv::Optimize(resp.words, static_cast<spirv::OptLevel>(r.opt_level), r.half_arithmetic,
                         resp.messages)) {
        resp.ok = false;
        resp.failed_in = Component::kSpirvOpt;
        resp.words.clear();
    }
    return resp;
}

Response Finish(const Request& r, ExecuteContext& context) {
    Response resp;
    resp.words = r.words;
    Enter(context, Component::kSpirvOpt);
    if (!spirv::StripReflectionInfo(resp.words, r.debug_info, resp.messages)) {
        resp.failed_in = Component::kSpirvOpt;
        return resp;
    }
    Enter(context, Component::kSpirvVal);
    resp.ok = spirv::Validate(resp.words, resp.messages);
    resp.failed_in = resp.ok ? Component::kNone : Component::kSpirvVal;
    return resp;
}

Response Validate(const Request& r, ExecuteContext& context) {
    Response resp;
    Enter(context, Component::kSpirvVal);
    resp.ok = spirv::Validate(r.words, resp.messages);
    resp.failed_in = resp.ok ? Component::kNone : Component::kSpirvVal;
    return resp;
}

}  // namespace

Response Execute(const Request& request, ExecuteContext& context) {
    frontend::InitializeGlslang();
    const hlsl::IncludePaths paths{request.include_dirs, request.templates_dir,
                                   request.unity_version};
    hlsl::Includer includer(paths, context.files);
    Response resp;
    switch (request.kind) {
        case RequestKind::kPreprocess:
            resp = Preprocess(request, context, includer);
            break;
        case RequestKind::kCompile:
            resp = Compile(request, context, includer);
            break;
        case RequestKind::kFinish:
            resp = Finish(request, context);
            break;
        case RequestKind::kValidate:
            resp = Validate(request, context);
            break;
        case RequestKind::kSelfTest:
            resp.messages = "self tests run only in a worker process";
            break;
    }
    resp.files_read = includer.Served();
    Enter(context, Component::kNone);
    return resp;
}

}  // namespace kiln::worker
