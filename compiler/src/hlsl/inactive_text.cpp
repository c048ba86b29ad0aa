#include "hlsl/inactive_text.h"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <unordered_set>
#include <utility>

#include "hlsl/identifier.h"
#include "hlsl/lean_text.h"
#include "hlsl/needless_defines.h"
#include "hlsl/pp_macros.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/splice.h"

namespace kiln::hlsl {
namespace {

enum class Region { kRead, kMaybe };  // read for certain, or perhaps

bool IsIdentChar(std::string_view s, size_t i) {
    if (i >= s.size())
        return false;
    return IdentChar(s[i]);
}

using LineRanges = std::vector<std::pair<uint32_t, uint32_t>>;  // inclusive

// A #define glslang reads, which is needless when nothing else it reads names it.
struct DefineLine {
    uint32_t first_line = 0, last_line = 0;
    std::string_view name;  // in the file's skeleton
    bool maybe = false;     // in a branch it may or may not read: kept, but counted as a read
};

// One file as the walk reads it.
struct File {
    const std::string& name;  // as glslang names it to the Includer
    std::string_view text;
    const PpSkeleton& skeleton;
    const std::vector<uint32_t>& line_starts;  // of `text`: the skeleton's, or the lean text's
    LineRanges blank;
    std::vector<DefineLine> defines;  // with PlanOptions::drop_needless
};

// An inclusion whose text is made when the walk ends, once it is known which #define lines no
// other line names.
struct Pending {
    size_t index = 0;  // in InactiveTextPlan::inclusions
    std::shared_ptr<const SourceFile> file;
    std::shared_ptr<const PpSkeleton> skeleton;
    std::shared_ptr<const LeanText> lean;
    LineRanges blank;
    std::vector<DefineLine> defines;
};

struct State {
    const Includer& includer;
    FileCache& files;
    const PlanOptions& options;
    InactiveTextPlan& plan;
    PpMacros macros;
    size_t depth = 0;  // files open, as glslang counts them for the Includer
    bool stopped = false;
    // PlanOptions::record_macros: the table as #define texts, and whether it is glslang's.
    const File* main = nullptr;
    size_t conditionals = 0;  // conditionals open around the directive walked
    std::map<std::string, std::string> table;
    bool exact = true;
    std::vector<Pending> pending;
};

void WalkRange(State& s, File& f, uint32_t begin, uint32_t end, Region region);

std::string Blanked(std::string_view text,
                    const std::vector<uint32_t>& line_starts,
                    LineRanges& blank,
                    size_t& blanked_lines) {
    std::sort(blank.begin(), blank.end());
    return BlankLines(text, line_starts, blank, blanked_lines);
}

// The index of the directive on physical line `line`, or npos.
size_t DirectiveAt(const PpSkeleton& skeleton, uint32_t line) {
    const auto& d = skeleton.directives;
    auto it = std::upper_bound(d.begin(), d.end(), line,
                               [](uint32_t l, const PpDirective& x) { return l < x.first_line; });
    if (it == d.begin() || (it - 1)->last_line < line)
        return std::string::npos;
    return static_cast<size_t>(it - 1 - d.begin());
}

// Whether `f`'s lines that glslang reads name PlanOptions::unknown only in conditions, in their
// own #define and #undef, or in a #pragma.
bool MentionsOnlyInConditions(const State& s, const File& f) {
    const std::vector<uint32_t>& starts = f.line_starts;
    for (const std::string& name : s.options.unknown) {
        for (size_t at = f.text.find(name); at != std::string_view::npos;
             at = f.text.find(name, at + 1)) {
            if ((at > 0 && IsIdentChar(f.text, at - 1)) || IsIdentChar(f.text, at + name.size()))
                continue;  // part of a longer name
            const auto line = static_cast<uint32_t>(
                std::upper_bound(starts.begin(), starts.end(), static_cast<uint32_t>(at)) -
                starts.begin() - 1);
            const auto blank =
                std::upper_bound(f.blank.begin(), f.blank.end(), std::make_pair(line, UINT32_MAX));
            if (blank != f.blank.begin() && (blank - 1)->second >= line)
                continue;  // blanked
            const size_t i = DirectiveAt(f.skeleton, line);
            if (i == std::string::npos)
                return false;
            const PpDirective& d = f.skeleton.directives[i];
            const bool condition = d.kind == PpKind::kIf || d.kind == PpKind::kIfdef ||
                                   d.kind == PpKind::kIfndef || d.kind == PpKind::kElif;
            const bool own = (d.kind == PpKind::kDefine || d.kind == PpKind::kUndef) &&
                             d.rest.find_first_not_of(" \t") == d.rest.find(name) &&
                             !IsIdentChar(d.rest, d.rest.find(name) + name.size());
            // glslang prints a #pragma's tokens without expanding them.
            if (!condition && !own && d.kind != PpKind::kPragma)
                return false;
        }
    }
    return true;
}

// Keeps the macro table as #define texts for PlanOptions::record_macros (InactiveTextPlan::macros).
void Record(State& s, const File& f, const PpDirective& d) {
    const std::string_view name = DirectiveMacroName(d.rest);
    const std::vector<std::string>& unknown = s.options.unknown;
    if (std::find(unknown.begin(), unknown.end(), name) != unknown.end()) {
        if (d.kind == PpKind::kDefine && &f == s.main && s.conditionals == 0)
            s.plan.unknown_define_lines.push_back(d.first_line);
        else
            s.exact = false;
    } else if (name.empty() || GlslangMayDefine(name)) {
        s.exact = false;
    } else if (d.kind == PpKind::kDefine) {
        s.table[std::string(name)] = d.rest;
    } else {
        s.table.erase(std::string(name));
    }
}

// The header an #include names, and whether it was "..." (local) rather than <...>.
std::optional<std::pair<std::string, bool>> Header(std::string_view rest) {
    const size_t open = rest.find_first_not_of(" \t\v\f");
    if (open == std::string_view::npos || (rest[open] != '"' && rest[open] != '<'))
        return std::nullopt;
    const char close_char = rest[open] == '"' ? '"' : '>';
    const size_t close = rest.find(close_char, open + 1);
    if (close == std::string_view::npos ||
        rest.find_first_not_of(" \t\v\f", close + 1) != std::string_view::npos)
        return std::nullopt;
    return std::make_pair(std::string(rest.substr(open + 1, close - open - 1)), close_char == '"');
}

void Include(State& s, const File& f, const PpDirective& d) {
    const auto header = Header(d.rest);
    if (!header || s.depth + 1 > Includer::kMaxDepth) {
        s.stopped = true;
        return;
    }
    std::string path = s.includer.Resolve(header->first, f.name, header->second);
    if (path.empty() && header->second)
        path = s.includer.Resolve(header->first, f.name, false);
    const std::shared_ptr<const SourceFile> file = path.empty() ? nullptr : s.files.Get(path);
    if (!file) {
        s.stopped = true;
        return;
    }
    const std::shared_ptr<const PpSkeleton> skeleton = s.files.Skeleton(file);
    const size_t index = s.plan.inclusions.size();
    s.plan.inclusions.push_back({path, {}});
    // Served lean (hlsl/lean_text.h): what glslang would read in vain is left out.
    const std::shared_ptr<const LeanText> lean = s.files.Lean(file);
    File inner{path, lean->text, *skeleton, lean->line_starts, {}, {}};
    if (!skeleton->safe || inner.text.empty()) {
        s.stopped = !skeleton->safe;
    } else {
        ++s.depth;
        WalkRange(s, inner, 0, static_cast<uint32_t>(skeleton->directives.size()), Region::kRead);
        --s.depth;
    }
    std::sort(inner.blank.begin(), inner.blank.end());
    if (!s.options.unknown.empty() && !MentionsOnlyInConditions(s, inner)) {
        s.plan.unknown_only_in_conditions = false;
        s.stopped = s.stopped || s.options.stop_when_unknown_matters;
    }
    s.pending.push_back(
        {index, file, skeleton, lean, std::move(inner.blank), std::move(inner.defines)});
}

std::optional<bool> Condition(const State& s, const PpDirective& d) {
    switch (d.kind) {
        case PpKind::kIf:
        case PpKind::kElif:
            return s.macros.If(d.rest);
        case PpKind::kIfdef:
            return s.macros.Ifdef(d.rest);
        case PpKind::kIfndef: {
            const std::optional<bool> defined = s.macros.Ifdef(d.rest);
            return defined ? std::optional<bool>(!*defined) : std::nullopt;
        }
        default:
            return true;  // #else
    }
}

// The conditional whose first directive is `first`; returns the index after its #endif.
uint32_t Conditional(State& s, File& f, uint32_t first, Region region) {
    const std::vector<PpDirective>& d = f.skeleton.directives;
    bool taken = false;        // a branch before is read for certain
    bool maybe_taken = false;  // a branch before may be read
    // Whether every branch is decided for certain: glslang then needs none of its directives.
    bool decided = region == Region::kRead && s.options.drop_needless;
    LineRanges lines;
    uint32_t b = first;
    for (; d[b].kind != PpKind::kEndif && !s.stopped; b = d[b].next) {
        const uint32_t next = d[b].next;
        if (decided)  // else never blanked: no need to keep its lines
            lines.emplace_back(d[b].first_line, d[b].last_line);
        std::optional<Region> branch = Region::kMaybe;
        if (region == Region::kRead) {
            const std::optional<bool> c = taken ? std::optional<bool>(false) : Condition(s, d[b]);
            if (c && !*c) {
                branch.reset();  // skipped
            } else if (!c || maybe_taken) {
                maybe_taken = true;
                decided = false;
                ++s.plan.maybe_branches;
                s.stopped = s.stopped || s.options.stop_when_unknown_matters;
            } else {
                branch = Region::kRead;
                taken = true;
            }
        }
        if (!branch) {
            if (d[b].last_line + 1 < d[next].first_line)
                f.blank.emplace_back(d[b].last_line + 1, d[next].first_line - 1);
        } else {
            ++s.conditionals;
            WalkRange(s, f, b + 1, next, *branch);
            --s.conditionals;
        }
    }
    if (decided && !s.stopped) {
        lines.emplace_back(d[b].first_line, d[b].last_line);
        f.blank.insert(f.blank.end(), lines.begin(), lines.end());
    }
    return b + 1;
}

void WalkRange(State& s, File& f, uint32_t begin, uint32_t end, Region region) {
    const std::vector<PpDirective>& d = f.skeleton.directives;
    for (uint32_t i = begin; i < end && !s.stopped;) {
        const PpDirective& at = d[i];
        switch (at.kind) {
            case PpKind::kIf:
            case PpKind::kIfdef:
            case PpKind::kIfndef:
                i = Conditional(s, f, i, region);
                continue;
            case PpKind::kDefine:
            case PpKind::kUndef:
                if (s.options.drop_needless && at.kind == PpKind::kDefine && &f != s.main) {
                    f.defines.push_back({at.first_line, at.last_line, DirectiveMacroName(at.rest),
                                         region == Region::kMaybe});
                }
                if (region == Region::kMaybe)
                    s.macros.Forget(at.rest);
                else if (!(at.kind == PpKind::kDefine ? s.macros.Define(at.rest)
                                                      : s.macros.Undef(at.rest)))
                    s.stopped = true;
                else if (s.options.record_macros)
                    Record(s, f, at);
                break;
            case PpKind::kInclude:
                if (region == Region::kMaybe)
                    s.stopped = true;  // glslang may or may not read it
                else
                    Include(s, f, at);
                break;
            case PpKind::kPragma:
                // `#pragma once` changes what a later #include reads.
                if (at.rest.find("once") != std::string::npos)
                    s.stopped = true;
                break;
            case PpKind::kKnown:
                break;
            default:  // an unknown directive (glslang's error), or a branch out of place
                if (region == Region::kRead)
                    s.stopped = true;
                break;
        }
        ++i;
    }
}

// Whether a paste (##) in the files read may make one of PlanOptions::unknown. The first piece
// of a pasted name is a word of some text read (a macro body's, or an argument's), so a name none
// of whose proper prefixes is such a word cannot be made by pasting.
bool PasteMayMakeUnknown(const State& s, const PpSkeleton& main) {
    std::vector<std::shared_ptr<const PpSkeleton>> read;
    bool pastes = main.pastes;
    for (const InactiveTextPlan::Inclusion& inc : s.plan.inclusions) {
        if (const std::shared_ptr<const SourceFile> file = s.files.Get(inc.path)) {
            read.push_back(s.files.Skeleton(file));
            pastes = pastes || read.back()->pastes;
        }
    }
    if (!pastes)
        return false;
    for (const std::string& name : s.options.unknown) {
        for (size_t k = 1; k < name.size(); ++k) {
            const std::string prefix = name.substr(0, k);
            if (main.words.count(prefix))
                return true;
            for (const auto& skeleton : read) {
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
void BlankNeedlessDefines(State& s, const PpSkeleton& main) {
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

}  // namespace

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
    File f{name, main, skeleton, skeleton.line_starts, {}, {}};
    if (skeleton.safe) {
        State s{includer, files, options, plan, {}, 0, false, &f, 0, {}, true, {}};
        for (const std::string& unknown : options.unknown)
            s.macros.Pin(unknown);
        WalkRange(s, f, 0, static_cast<uint32_t>(skeleton.directives.size()), Region::kRead);
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
        for (size_t i = 0; i < s.pending.size(); ++i) {
            Pending& p = s.pending[i];
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
    }
    plan.main_text = Blanked(main, skeleton.line_starts, f.blank, plan.blanked_lines);
    return plan;
}

}  // namespace kiln::hlsl
