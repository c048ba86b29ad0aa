#include "hlsl/inactive_text.h"

#include <algorithm>
#include <memory>
#include <unordered_set>
#include <utility>

#include "hlsl/blank_inclusions.h"
#include "hlsl/lean_text.h"
#include "hlsl/needless_defines.h"
#include "hlsl/plan_walk.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/splice.h"

namespace kiln::hlsl {
namespace {

std::string Blanked(std::string_view text,
                    const std::vector<uint32_t>& line_starts,
                    LineRanges& blank,
                    size_t& blanked_lines) {
    std::sort(blank.begin(), blank.end());
    return BlankLines(text, line_starts, blank, blanked_lines);
}

// Whether a paste (##) in the files read may make one of PlanOptions::unknown. The first piece
// of a pasted name is a word of some text read (a macro body's, or an argument's), so a name none
// of whose proper prefixes is such a word cannot be made by pasting.
bool PasteMayMakeUnknown(const PlanWalk& s, const PpSkeleton& main) {
    std::vector<const PpSkeleton*> read = {&main};  // each file once
    bool pastes = main.pastes;
    for (const Pending& p : s.pending) {
        if (std::find(read.begin(), read.end(), p.skeleton.get()) == read.end()) {
            read.push_back(p.skeleton.get());
            pastes = pastes || p.skeleton->pastes;
        }
    }
    if (!pastes)
        return false;
    for (const std::string& name : s.options.unknown) {
        std::string prefix;
        for (size_t k = 1; k < name.size(); ++k) {
            prefix += name[k - 1];
            for (const PpSkeleton* skeleton : read) {
                if (skeleton->words.count(prefix))
                    return true;
            }
        }
    }
    return false;
}

// Blanks the #define lines of the files included that no other line of the program names
// (hlsl/needless_defines.h), each read once for certain: only for a plan that reached the end of
// the program (a later text could name them). The main text's own are kept.
void BlankNeedlessDefines(PlanWalk& s, const PpSkeleton& main) {
    std::vector<std::shared_ptr<const PpSkeleton>> read;
    for (const Pending& p : s.pending) {
        if (std::find(read.begin(), read.end(), p.skeleton) == read.end())
            read.push_back(p.skeleton);
    }
    const std::shared_ptr<const IncludedDefines> included = s.files.Defines(read);
    NeedlessDefines needless(*included, main);
    for (const std::string& name : s.options.unknown)
        needless.Keep(name);
    std::unordered_set<std::string_view> read_once;
    for (const Pending& p : s.pending) {
        for (const DefineLine& d : p.defines) {
            if (needless.Needless(d.name) && !read_once.insert(d.name).second)
                needless.Keep(d.name);  // read twice (or perhaps)
        }
    }
    for (Pending& p : s.pending) {
        for (const DefineLine& d : p.defines) {
            if (!d.maybe && needless.Needless(d.name))
                p.blank.emplace_back(d.first_line, d.last_line);
        }
    }
}

// Each inclusion that is only line breaks served as one (hlsl/blank_inclusions.h).
void ServeBlankInclusions(InactiveTextPlan& plan) {
    for (size_t i = 0; i < plan.inclusions.size(); ++i) {
        InactiveTextPlan::Inclusion& p = plan.inclusions[i];
        if (!ServableAsBlank(p.text, p.path))
            continue;
        plan.blank_inclusions.resize(plan.inclusions.size());
        plan.blank_inclusions[i] = static_cast<uint32_t>(p.text.size());
        p.text.assign(1, '\n');
    }
}

// The walks whose output is remembered (hlsl/output_memo.h), where their marks hold: by
// inclusion, whether the file's output is replayed (it is then not served).
std::vector<char> KeepOutputs(InactiveTextPlan& plan, OutputMemo& memo) {
    std::vector<char> replayed(plan.inclusions.size(), 0);
    std::vector<OutputMark> kept;
    for (OutputMark& m : plan.outputs) {
        if (m.count == 0 || m.inclusion + m.count > plan.inclusions.size())
            continue;
        if (m.output) {
            m.words = memo.Words(m.walk.get());
            if (!m.words || !m.words->usable)
                continue;
            std::fill(replayed.begin() + m.inclusion, replayed.begin() + m.inclusion + m.count, 1);
        }
        kept.push_back(std::move(m));
    }
    plan.outputs = std::move(kept);
    return replayed;
}

// After the texts are served: a replayed walk's root served as its directives, and the files it
// includes not asked for; any other marked root served under its marked name, to be recorded,
// unless it is served blank.
void MarkOutputs(InactiveTextPlan& plan) {
    std::vector<OutputMark> kept;
    plan.output_marks.assign(plan.inclusions.size(), 0);
    for (OutputMark& m : plan.outputs) {
        if (m.output) {
            plan.inclusions[m.inclusion].text = ReplayedText(*m.words, *m.output);
        } else if (m.inclusion < plan.blank_inclusions.size() &&
                   plan.blank_inclusions[m.inclusion] > 0) {
            continue;
        }
        kept.push_back(std::move(m));
        plan.output_marks[kept.back().inclusion] = static_cast<uint32_t>(kept.size());
    }
    plan.outputs = std::move(kept);
    if (plan.outputs.empty())
        plan.output_marks.clear();
}

}  // namespace

bool MakeWhole(std::string& text, const InactiveTextPlan& plan, OutputMemo* memo) {
    if (!plan.blank_inclusions.empty() && !RestoreBlankInclusions(text, plan.blank_inclusions))
        return false;
    if (plan.spliced_runs != 0 && !Unsplice(text, plan.splices))
        return false;
    return RestoreOutputs(text, plan.outputs, memo);
}

std::string BlankLines(std::string_view text,
                       const std::vector<uint32_t>& line_starts,
                       const std::vector<std::pair<uint32_t, uint32_t>>& ranges,
                       size_t& blanked_lines) {
    if (ranges.empty())
        return std::string(text);
    std::string out;
    out.reserve(text.size());
    size_t copied = 0;
    for (const auto& [first, last] : ranges) {
        out.append(text.substr(copied, line_starts[first] - copied));
        const bool at_end = last + 1 >= line_starts.size();
        out.append(last - first + (at_end ? 0 : 1), '\n');
        blanked_lines += last - first + 1;
        // The file's last character stays a line break or not, as glslang checks it.
        if (at_end && !text.empty() && text.back() != '\n')
            out += ' ';
        copied = at_end ? text.size() : line_starts[last + 1];
    }
    out.append(text.substr(copied));
    return out;
}

InactiveTextPlan PlanInactiveText(std::string_view main,
                                  const std::string& name,
                                  const Includer& includer,
                                  FileCache& files,
                                  const PlanOptions& options) {
    InactiveTextPlan plan;
    const PpSkeleton own = options.main_skeleton ? PpSkeleton() : ScanSkeleton(main);
    const PpSkeleton& skeleton = options.main_skeleton ? *options.main_skeleton : own;
    PlanFile f{name, main, skeleton, skeleton.line_starts, {}, {}};
    if (skeleton.safe) {
        PlanWalk s{includer, files, options, plan, {}, 0, false, &f, 0, {}, true, {}, {}};
        WalkMain(s, f);
        plan.complete = !s.stopped;
        if (options.record_macros) {
            plan.macros.assign(s.table.begin(), s.table.end());
            plan.macros_exact = s.exact && plan.complete && plan.maybe_branches == 0;
        }
        std::sort(f.blank.begin(), f.blank.end());
        if (!options.unknown.empty() &&
            (!MentionsOnlyInConditions(s, f) || PasteMayMakeUnknown(s, skeleton)))
            plan.unknown_only_in_conditions = false;
        if (options.drop_needless && plan.complete)
            BlankNeedlessDefines(s, skeleton);
        for (Pending& p : s.pending)
            std::sort(p.blank.begin(), p.blank.end());
        std::vector<InclusionSplice> splices;
        if (options.splice && plan.complete) {
            std::vector<SpliceInclusion> inclusions;
            for (const Pending& p : s.pending)
                inclusions.push_back({p.file, p.skeleton, &p.blank});
            splices = ChooseSplices(files, options.unknown, skeleton, main, inclusions);
        }
        if (!splices.empty())
            plan.splices.resize(plan.inclusions.size());
        // The files of a walk whose output is replayed are not served.
        if (splices.empty())
            plan.outputs.clear();
        const std::vector<char> replayed = KeepOutputs(plan, files.output_memo());
        for (size_t i = 0; i < s.pending.size(); ++i) {
            Pending& p = s.pending[i];
            if (replayed[p.index])
                continue;
            if (splices.empty() || splices[i].runs.empty()) {
                plan.inclusions[p.index].text =
                    Blanked(p.lean->text, p.lean->line_starts, p.blank, plan.blanked_lines);
                continue;
            }
            const InclusionSplice& c = splices[i];
            plan.inclusions[p.index].text =
                ServeSpliced(*c.file, *c.choice, p.index, p.blank, c.runs, plan.blanked_lines);
            plan.splices[p.index] = c.choice;
            plan.spliced_runs += c.runs.size();
        }
        // No text of the program spells the marker's prefix where splices were chosen.
        if (!splices.empty()) {
            ServeBlankInclusions(plan);
            MarkOutputs(plan);
        }
    }
    plan.main_text = Blanked(main, skeleton.line_starts, f.blank, plan.blanked_lines);
    return plan;
}

}  // namespace kiln::hlsl
