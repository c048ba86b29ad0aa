#include "worker/preamble.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "hlsl/assemble.h"
#include "hlsl/inactive_text.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/preamble.h"

namespace kiln::worker {
namespace {

// What else decides the prefix's output: the stage (or both), and where includes resolve.
std::string Context(const Request& r, bool both) {
    std::string c = both ? "both" : std::to_string(static_cast<int>(r.stage));
    for (const std::string* s : {&r.name, &r.templates_dir}) {
        c += '\0';
        c += *s;
    }
    for (const std::string& dir : r.include_dirs) {
        c += '\0';
        c += dir;
    }
    c += '\0';
    c += std::to_string(r.unity_version);
    return c;
}

// The preamble of `prefix` with `pinned` taken as unknown: usable when the inactive-text plan
// proves its output the same whatever they are and glslang preprocesses it without a message.
std::shared_ptr<const hlsl::Preamble> Make(const Request& r,
                                           std::string_view prefix,
                                           const std::vector<std::string>& pinned,
                                           ExecuteContext& context,
                                           const hlsl::Includer& includer) {
    auto p = std::make_shared<hlsl::Preamble>();
    hlsl::PlanOptions options;
    options.unknown = pinned;
    options.record_macros = true;
    options.stop_when_unknown_matters = true;  // refused at once where a keyword is read
    const hlsl::InactiveTextPlan plan =
        hlsl::PlanInactiveText(prefix, r.name, includer, context.files, options);
    for (const hlsl::InactiveTextPlan::Inclusion& inc : plan.inclusions) {
        if (std::shared_ptr<const SourceFile> file = context.files.Get(inc.path))
            p->files.push_back(std::move(file));
    }
    if (!plan.OutputIgnoresUnknown() || p->files.size() != plan.inclusions.size())
        return p;
    hlsl::Includer fresh = includer.Fresh();
    fresh.UsePlan(&plan);
    const frontend::StageOutput out = frontend::Preprocess(r.stage, plan.main_text, r.name, fresh);
    if (!out.ok || !out.info_log.empty() || fresh.served_from_plan() != plan.inclusions.size() ||
        !hlsl::CutPrefixOutput(out.text, *p))
        return p;
    for (size_t i = 0; i < plan.inclusions.size(); ++i) {
        const std::shared_ptr<const hlsl::PpSkeleton> skeleton =
            context.files.Skeleton(p->files[i]);
        p->served.inclusions.push_back(
            {plan.inclusions[i].path, hlsl::DirectivesOnly(hlsl::ServedText(*p->files[i]),
                                                           *skeleton, skeleton->line_count)});
    }
    p->served.complete = true;
    p->usable = true;
    p->tokens = hlsl::Tokenize(p->output);
    p->reduce_prefix = hlsl::MakeReducePrefix(p->output, p->tokens);
    std::vector<uint32_t> lines;
    for (const auto& [number, line] : hlsl::PinnedDefines(prefix, pinned))
        lines.push_back(number);
    if (plan.macros_exact && plan.unknown_define_lines == lines) {
        hlsl::SetMacros(*p, plan.macros);
        p->replayable = true;
    }
    return p;
}

std::shared_ptr<const hlsl::Preamble> Find(const Request& r,
                                           std::string_view prefix,
                                           bool both,
                                           ExecuteContext& context,
                                           const hlsl::Includer& includer,
                                           std::vector<std::string>& pinned) {
    pinned = r.pinned;
    if (both) {
        pinned.emplace_back(hlsl::StageMacro(pack::Stage::kVertex));
        pinned.emplace_back(hlsl::StageMacro(pack::Stage::kFragment));
    }
    const std::string key = hlsl::PreambleKey(prefix, pinned, Context(r, both));
    std::shared_ptr<const hlsl::Preamble> p = context.preambles->Find(key, context.files);
    if (!p) {
        p = Make(r, prefix, pinned, context, includer);
        context.preambles->Remember(key, p);
    }
    return p->usable ? p : nullptr;
}

// The program preprocessed from the preamble's macro table: glslang reads no file.
std::optional<frontend::StageOutput> FromMacros(const Request& r,
                                                const hlsl::Preamble& p,
                                                std::string_view prefix,
                                                std::string_view rest,
                                                const std::vector<std::string>& pinned,
                                                hlsl::Includer& includer) {
    std::string main = hlsl::MacrosFor(p, rest);
    for (const auto& [number, line] : hlsl::PinnedDefines(prefix, pinned)) {
        main += line;
        if (main.back() != '\n')
            main += '\n';
    }
    main += p.marks.back();
    main += '\n';
    main += rest;
    includer.Hold(p.files);  // read for the program all the same (depfiles, direct mode)
    frontend::StageOutput out = frontend::Preprocess(r.stage, main, r.name, includer);
    std::optional<std::string> joined;
    if (out.ok && out.info_log.empty())
        joined = hlsl::JoinReplayedPreamble(p, out.text);
    if (!joined)
        return std::nullopt;
    out.text = std::move(*joined);
    return out;
}

// The program preprocessed with the prefix's code blanked: glslang reads its directives.
std::optional<frontend::StageOutput> FromDirectives(const Request& r,
                                                    const hlsl::Preamble& p,
                                                    const hlsl::PpSkeleton& skeleton,
                                                    uint32_t cut_lines,
                                                    hlsl::Includer& includer) {
    const std::string main = hlsl::DirectivesOnly(r.source, skeleton, cut_lines);
    includer.UsePlan(&p.served);
    frontend::StageOutput out = frontend::Preprocess(r.stage, main, r.name, includer);
    const size_t served = includer.served_from_plan();
    includer.UsePlan(nullptr);
    std::optional<std::string> joined;
    if (out.ok && out.info_log.empty() && served == p.served.inclusions.size())
        joined = hlsl::JoinPreamble(p, out.text);
    if (!joined)
        return std::nullopt;
    out.text = std::move(*joined);
    return out;
}

}  // namespace

std::optional<frontend::StageOutput> PreprocessWithPreamble(
    const Request& r,
    ExecuteContext& context,
    hlsl::Includer& includer,
    const hlsl::PpSkeleton& skeleton,
    bool& for_both,
    std::shared_ptr<const hlsl::Preamble>* used) {
    for_both = false;
    if (r.pinned.empty() || !context.preambles)
        return std::nullopt;
    const std::optional<hlsl::PrefixCut> cut =
        skeleton.safe ? hlsl::FindPrefixCut(r.source, skeleton) : std::nullopt;
    if (!cut)
        return std::nullopt;
    const std::string_view prefix(r.source.data(), cut->bytes);
    // The rest is shared by both stages when it does not name them either (a macro of the prefix
    // that names them is refused by the plan).
    const bool both = !r.second_entry.empty() &&
                      std::string_view(r.source).substr(cut->bytes).find("SHADER_STAGE_") ==
                          std::string_view::npos;
    bool shared_both = both;
    std::vector<std::string> pinned;
    std::shared_ptr<const hlsl::Preamble> p =
        both ? Find(r, prefix, true, context, includer, pinned) : nullptr;
    if (!p) {
        shared_both = false;
        p = Find(r, prefix, false, context, includer, pinned);
    }
    if (!p)
        return std::nullopt;
    const std::string_view rest = std::string_view(r.source).substr(cut->bytes);
    std::optional<frontend::StageOutput> out =
        p->replayable ? FromMacros(r, *p, prefix, rest, pinned, includer)
                      : FromDirectives(r, *p, skeleton, cut->lines, includer);
    if (out) {
        for_both = shared_both;
        if (used)
            *used = std::move(p);
    }
    return out;
}

}  // namespace kiln::worker
