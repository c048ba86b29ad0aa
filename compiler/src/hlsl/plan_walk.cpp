#include "hlsl/plan_walk.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

#include "hlsl/identifier.h"
#include "hlsl/lean_text.h"

namespace kiln::hlsl {
namespace {

enum class Region { kRead, kMaybe };  // read for certain, or perhaps

bool IsIdentChar(std::string_view s, size_t i) {
    if (i >= s.size())
        return false;
    return IdentChar(s[i]);
}

void WalkRange(PlanWalk& s, PlanFile& f, uint32_t begin, uint32_t end, Region region);

// The index of the directive on physical line `line`, or npos.
size_t DirectiveAt(const PpSkeleton& skeleton, uint32_t line) {
    const auto& d = skeleton.directives;
    auto it = std::upper_bound(d.begin(), d.end(), line,
                               [](uint32_t l, const PpDirective& x) { return l < x.first_line; });
    if (it == d.begin() || (it - 1)->last_line < line)
        return std::string::npos;
    return static_cast<size_t>(it - 1 - d.begin());
}

// Keeps the macro table as #define texts for PlanOptions::record_macros (InactiveTextPlan::macros).
void Record(PlanWalk& s, const PlanFile& f, const PpDirective& d) {
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

// Walks the file `path` names, included from a file the walk reads for certain.
void Walk(PlanWalk& s, const std::string& path, const std::shared_ptr<const SourceFile>& file) {
    const std::shared_ptr<const PpSkeleton> skeleton = s.files.Skeleton(file);
    const size_t index = s.plan.inclusions.size();
    s.plan.inclusions.push_back({path, {}});
    // Served lean (hlsl/lean_text.h): what glslang would read in vain is left out.
    const std::shared_ptr<const LeanText> lean = s.files.Lean(file);
    PlanFile inner{path, lean->text, *skeleton, lean->line_starts, {}, {}};
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

// Does what `walk` did, when the files it read are still those it read.
bool Replay(PlanWalk& s, const IncludeWalk& walk) {
    for (const Pending& p : walk.pending) {
        if (s.files.Get(walk.paths[p.index]) != p.file)
            return false;
    }
    const size_t base = s.plan.inclusions.size();
    for (const std::string& path : walk.paths)
        s.plan.inclusions.push_back({path, {}});
    for (const Pending& p : walk.pending) {
        s.pending.push_back(p);
        s.pending.back().index += base;
    }
    s.plan.maybe_branches += walk.maybe_branches;
    if (walk.names_unknown)
        s.plan.unknown_only_in_conditions = false;
    s.stopped = walk.stopped;
    s.macros.NoteReads(walk.reads);
    for (const auto& [name, value] : walk.writes)
        s.macros.Set(name, value);
    return true;
}

// What the walk did from the plan's state `before` on (its inclusions and pending texts from
// those indices), for the memo: what it read and wrote as `log` says.
struct Before {
    size_t inclusions = 0, pending = 0, maybe_branches = 0;
};

std::shared_ptr<IncludeWalk> Captured(PlanWalk& s,
                                      const Before& before,
                                      bool names_unknown,
                                      MacroLog& log) {
    auto walk = std::make_shared<IncludeWalk>();
    for (size_t i = before.inclusions; i < s.plan.inclusions.size(); ++i) {
        walk->paths.push_back(s.plan.inclusions[i].path);
        walk->bytes += walk->paths.back().size() + 64;
    }
    for (size_t i = before.pending; i < s.pending.size(); ++i) {
        const Pending& p = walk->pending.emplace_back(s.pending[i]);
        walk->pending.back().index -= before.inclusions;
        walk->bytes +=
            128 + p.blank.size() * sizeof(p.blank[0]) + p.defines.size() * sizeof(DefineLine);
    }
    walk->maybe_branches = s.plan.maybe_branches - before.maybe_branches;
    walk->names_unknown = names_unknown;
    walk->stopped = s.stopped;
    walk->reads = std::move(log.reads);
    for (const auto& [name, value] : walk->reads)
        walk->bytes += name.size() + value.body.size() + 96;
    for (std::string& name : log.writes) {
        MacroValue value = s.macros.Held(name);
        walk->bytes += 2 * name.size() + value.body.size() + 96;
        walk->writes.emplace_back(std::move(name), std::move(value));
    }
    return walk;
}

// Walk, remembered (hlsl/plan_memo.h): a walk that would read what an earlier one read is
// replayed.
void WalkRemembered(PlanWalk& s,
                    const std::string& path,
                    const std::shared_ptr<const SourceFile>& file) {
    PlanMemo& memo = s.files.plan_memo();
    const std::string context = s.memo_context + std::to_string(s.depth);
    if (const auto walk = memo.Find(file, context, s.macros)) {
        // The key of its output is of the macros at the #include, before the replay writes.
        const size_t root = s.plan.inclusions.size();
        std::optional<OutputKey> key;
        if (s.options.splice && s.options.drop_needless)
            key = s.files.output_memo().Key(walk, s.macros);
        if (Replay(s, *walk)) {
            ++s.plan.remembered_walks;
            if (key) {
                s.plan.outputs.push_back({root, walk->paths.size(), walk, *key,
                                          s.files.output_memo().Find(walk.get(), *key), nullptr});
            }
            return;
        }
    }
    if (!memo.Open(file, context)) {
        Walk(s, path, file);
        return;
    }
    const Before before{s.plan.inclusions.size(), s.pending.size(), s.plan.maybe_branches};
    // Whether this walk finds PlanOptions::unknown named elsewhere, whatever the plan found.
    const bool only = s.plan.unknown_only_in_conditions;
    s.plan.unknown_only_in_conditions = true;
    MacroLog log;
    s.macros.OpenLog(&log);
    Walk(s, path, file);
    s.macros.CloseLog();
    const bool names_unknown = !s.plan.unknown_only_in_conditions;
    s.plan.unknown_only_in_conditions = only && !names_unknown;
    memo.Add(file, context, Captured(s, before, names_unknown, log));
}

void Include(PlanWalk& s, const PlanFile& f, const PpDirective& d) {
    const auto header = Header(d.rest);
    if (!header || s.depth + 1 > Includer::kMaxDepth) {
        s.stopped = true;
        return;
    }
    std::string path = s.includer.Resolve(header->first, f.name, header->second);
    if (path.empty() && header->second)
        path = s.includer.Resolve(header->first, f.name, false);
    const std::shared_ptr<const SourceFile> file = path.empty() ? nullptr : s.files.Get(path);
    if (!file)
        s.stopped = true;
    else if (s.memo_context.empty())
        Walk(s, path, file);
    else
        WalkRemembered(s, path, file);
}

std::optional<bool> Condition(const PlanWalk& s, const PpDirective& d) {
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
uint32_t Conditional(PlanWalk& s, PlanFile& f, uint32_t first, Region region) {
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

void WalkRange(PlanWalk& s, PlanFile& f, uint32_t begin, uint32_t end, Region region) {
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

// What a walk of an #include depends on besides its file, the macros and the depth.
std::string MemoContext(const Includer& includer, const PlanOptions& options) {
    std::string context = includer.PathsKey();
    for (const std::string& name : options.unknown)
        context += "\n?" + name;
    context += options.stop_when_unknown_matters ? "\nstop" : "\n";
    context += options.drop_needless ? "\ndrop\n" : "\n\n";
    return context;
}

}  // namespace

bool MentionsOnlyInConditions(const PlanWalk& s, const PlanFile& f) {
    const std::vector<uint32_t>& starts = f.line_starts;
    for (const std::string& name : s.options.unknown) {
        // A file whose code never spells the name cannot name it (a comment is whitespace).
        if (!f.skeleton.words.count(name))
            continue;
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

void WalkMain(PlanWalk& s, PlanFile& f) {
    if (s.options.remember && !s.options.record_macros)
        s.memo_context = MemoContext(s.includer, s.options);
    for (const std::string& unknown : s.options.unknown)
        s.macros.Pin(unknown);
    WalkRange(s, f, 0, static_cast<uint32_t>(f.skeleton.directives.size()), Region::kRead);
}

}  // namespace kiln::hlsl
