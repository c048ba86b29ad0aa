#include "hlsl/preamble.h"

#include <algorithm>
#include <unordered_set>
#include <utility>

#include "hlsl/identifier.h"
#include "hlsl/pp_skeleton.h"

namespace kiln::hlsl {
namespace {

bool StartsWith(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

}  // namespace

std::optional<PrefixCut> FindPrefixCut(std::string_view main, const PpSkeleton& skeleton) {
    const std::vector<PpDirective>& d = skeleton.directives;
    size_t last = d.size();
    for (size_t i = 0; i < d.size(); ++i) {
        if (d[i].kind == PpKind::kInclude)
            last = i;
    }
    if (last == d.size())
        return std::nullopt;
    // After the cut glslang must print nothing of its own before the first token (a #line there
    // would let that token's spacing depend on the prefix's last one), and read no file.
    for (size_t i = last + 1; i < d.size(); ++i) {
        if (d[i].kind == PpKind::kInclude || d[i].kind == PpKind::kKnown ||
            d[i].kind == PpKind::kUnknown)
            return std::nullopt;
    }
    const uint32_t next = d[last].last_line + 1;
    if (next >= skeleton.line_count || skeleton.line_starts[next] >= main.size())
        return std::nullopt;  // nothing after the prefix
    return PrefixCut{skeleton.line_starts[next], next};
}

std::string DirectivesOnly(std::string_view text, const PpSkeleton& skeleton, uint32_t end_line) {
    std::vector<std::pair<uint32_t, uint32_t>> ranges;
    uint32_t line = 0;
    for (const PpDirective& d : skeleton.directives) {
        if (d.first_line >= end_line)
            break;
        if (d.first_line > line)
            ranges.emplace_back(line, d.first_line - 1);
        line = std::max(line, d.last_line + 1);
    }
    if (line < end_line)
        ranges.emplace_back(line, end_line - 1);
    size_t blanked = 0;
    return BlankLines(text, skeleton.line_starts, ranges, blanked);
}

std::vector<std::pair<uint32_t, std::string_view>> PinnedDefines(
    std::string_view prefix,
    const std::vector<std::string>& pinned) {
    const std::unordered_set<std::string_view> names(pinned.begin(), pinned.end());
    std::vector<std::pair<uint32_t, std::string_view>> out;
    constexpr std::string_view kDefine = "#define ";
    uint32_t number = 0;
    for (size_t at = 0; at < prefix.size(); ++number) {
        const size_t eol = prefix.find('\n', at);
        const size_t end = eol == std::string_view::npos ? prefix.size() : eol + 1;
        const std::string_view line = prefix.substr(at, end - at);
        at = end;
        if (!StartsWith(line, kDefine))
            continue;
        const std::string_view rest = line.substr(kDefine.size());
        if (names.count(rest.substr(0, rest.find_first_of(" \t\r\n"))))
            out.emplace_back(number, line);
    }
    return out;
}

std::string PreambleKey(std::string_view prefix,
                        const std::vector<std::string>& pinned,
                        std::string_view context) {
    std::string key(context);
    key += '\0';
    for (const std::string& name : pinned) {
        key += name;
        key += '\1';
    }
    key += '\0';
    key.reserve(key.size() + prefix.size());
    // The prefix with each pinned #define's name taken out.
    size_t copied = 0;
    for (const auto& [number, line] : PinnedDefines(prefix, pinned)) {
        const size_t begin = static_cast<size_t>(line.data() - prefix.data());
        const size_t name_end = line.find_first_of(" \t\r\n", 8);
        key.append(prefix.substr(copied, begin - copied));
        key += "#define \1";
        copied = begin + (name_end == std::string_view::npos ? line.size() : name_end);
    }
    key.append(prefix.substr(copied));
    return key;
}

bool CutPrefixOutput(const std::string& prefix_output, Preamble& preamble) {
    const std::string& p = prefix_output;
    if (p.empty() || p.back() != '\n')
        return false;
    size_t end_of_marks = std::string::npos;
    for (size_t at = 0; at < p.size();) {
        const size_t eol = p.find('\n', at);
        const std::string_view line(p.data() + at, eol - at);
        if (line.find('#') != std::string_view::npos) {
            if (!StartsWith(line, "#line ") && !StartsWith(line, "#pragma "))
                return false;  // a '#' a token printed: marks could not be told from code
            preamble.marks.emplace_back(line);
            end_of_marks = eol + 1;
        }
        at = eol + 1;
    }
    if (preamble.marks.empty() || !StartsWith(preamble.marks.back(), "#line ") ||
        p.compare(end_of_marks, std::string::npos, "\n") != 0)
        return false;
    preamble.output = p.substr(0, end_of_marks);
    return true;
}

std::optional<std::string> JoinPreamble(const Preamble& preamble, std::string_view blanked) {
    // The prefix's code is blanked, so up to the cut glslang printed only line breaks and the
    // same directive lines, in the same order.
    size_t at = 0;
    for (const std::string& mark : preamble.marks) {
        while (at < blanked.size() && blanked[at] == '\n')
            ++at;
        if (blanked.substr(at, mark.size()) != mark || at + mark.size() >= blanked.size() ||
            blanked[at + mark.size()] != '\n')
            return std::nullopt;
        at += mark.size() + 1;
    }
    // glslang spaces a token it prints on the line of the cut by the token before it, which is
    // the prefix's in the whole program and none here: only a line break first is the same.
    const std::string_view rest = blanked.substr(at);
    if (rest.empty() || rest[0] != '\n')
        return std::nullopt;
    std::string out;
    out.reserve(preamble.output.size() + rest.size());
    out += preamble.output;
    out += rest;
    return out;
}

std::optional<std::string> JoinReplayedPreamble(const Preamble& preamble,
                                                std::string_view replayed) {
    // Nothing but line breaks before the prefix's last #line, which the program repeats.
    const size_t at = replayed.find_first_not_of('\n');
    const std::string& mark = preamble.marks.back();
    if (at == std::string_view::npos || replayed.substr(at, mark.size()) != mark)
        return std::nullopt;
    const std::string_view rest = replayed.substr(at + mark.size());
    if (rest.size() < 2 || rest[0] != '\n' || rest[1] != '\n')
        return std::nullopt;
    std::string out;
    out.reserve(preamble.output.size() + rest.size());
    out += preamble.output;
    out += rest.substr(1);
    return out;
}

namespace {

// The identifier that ends just before `at` (blanks skipped), or empty.
std::string_view WordBefore(std::string_view s, size_t at) {
    while (at > 0 && (s[at - 1] == ' ' || s[at - 1] == '\t'))
        --at;
    size_t begin = at;
    while (begin > 0 && IdentChar(s[begin - 1]))
        --begin;
    return begin < at && IdentStart(s[begin]) ? s.substr(begin, at - begin) : std::string_view();
}

// The identifier that starts at `at` (blanks skipped), or empty.
std::string_view WordAfter(std::string_view s, size_t at) {
    while (at < s.size() && (s[at] == ' ' || s[at] == '\t'))
        ++at;
    size_t end = at;
    while (end < s.size() && IdentChar(s[end]))
        ++end;
    return end > at && IdentStart(s[at]) ? s.substr(at, end - at) : std::string_view();
}

// Adds to `m` the macros a paste (##) in its body `rest` may make a name of; false when a paste
// could make any name (two parameters pasted, or an operand that is not a name).
bool PastedNames(const std::vector<std::pair<std::string, std::string>>& macros,
                 std::string_view rest,
                 std::vector<uint32_t>& names) {
    std::vector<std::string_view> params;
    const std::string_view name = WordAfter(rest, 0);
    const size_t after_name = rest.find(name) + name.size();
    if (after_name < rest.size() && rest[after_name] == '(') {
        const size_t close = rest.find(')', after_name);
        if (close == std::string_view::npos)
            return false;
        for (size_t i = after_name + 1; i < close;) {
            const std::string_view p = WordAfter(rest, i);
            if (p.empty()) {
                ++i;
                continue;
            }
            params.push_back(p);
            i = static_cast<size_t>(p.data() + p.size() - rest.data());
        }
    }
    auto is_param = [&](std::string_view w) {
        return std::find(params.begin(), params.end(), w) != params.end();
    };
    for (size_t at = rest.find("##"); at != std::string_view::npos; at = rest.find("##", at + 2)) {
        const std::string_view left = WordBefore(rest, at), right = WordAfter(rest, at + 2);
        if (left.empty() || right.empty() || (is_param(left) && is_param(right)))
            return false;
        for (size_t m = 0; m < macros.size(); ++m) {
            const std::string& n = macros[m].first;
            const bool match =
                is_param(left) ? n.size() > right.size() &&
                                     n.compare(n.size() - right.size(), right.size(), right) == 0
                : is_param(right) ? n.size() > left.size() && n.compare(0, left.size(), left) == 0
                                  : n.size() == left.size() + right.size() && StartsWith(n, left) &&
                                        n.compare(left.size(), right.size(), right) == 0;
            if (match)
                names.push_back(static_cast<uint32_t>(m));
        }
    }
    return true;
}

}  // namespace

void SetMacros(Preamble& preamble, const std::vector<std::pair<std::string, std::string>>& macros) {
    preamble.macros.clear();
    preamble.macro_index.clear();
    for (const auto& [name, rest] : macros) {
        preamble.macro_index.emplace(name, static_cast<uint32_t>(preamble.macros.size()));
        preamble.macros.push_back({"#define" + rest + "\n", {}, false});
    }
    for (size_t m = 0; m < macros.size(); ++m) {
        Preamble::Macro& macro = preamble.macros[m];
        ForEachWord(macros[m].second, [&](std::string_view word) {
            const auto it = preamble.macro_index.find(std::string(word));
            if (it != preamble.macro_index.end() && it->second != m)
                macro.names.push_back(it->second);
        });
        if (macros[m].second.find("##") != std::string::npos &&
            !PastedNames(macros, macros[m].second, macro.names))
            macro.pastes_any = true;
    }
}

std::string MacrosFor(const Preamble& preamble, std::string_view rest) {
    const size_t n = preamble.macros.size();
    // The rest's own pastes may make any name.
    const bool all = rest.find("##") != std::string_view::npos;
    std::vector<bool> reach(n, all);
    std::vector<uint32_t> work;
    if (!all) {
        ForEachWord(rest, [&](std::string_view word) {
            const auto it = preamble.macro_index.find(std::string(word));
            if (it != preamble.macro_index.end() && !reach[it->second]) {
                reach[it->second] = true;
                work.push_back(it->second);
            }
        });
    }
    while (!work.empty()) {
        const uint32_t m = work.back();
        work.pop_back();
        if (preamble.macros[m].pastes_any) {
            reach.assign(n, true);
            break;
        }
        for (uint32_t used : preamble.macros[m].names) {
            if (!reach[used]) {
                reach[used] = true;
                work.push_back(used);
            }
        }
    }
    std::string out;
    for (size_t m = 0; m < n; ++m) {
        if (reach[m])
            out += preamble.macros[m].line;
    }
    return out;
}

std::shared_ptr<const Preamble> PreambleCache::Find(const std::string& key,
                                                    FileCache& files) const {
    std::shared_ptr<const Preamble> p;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto it = map_.find(key);
        if (it == map_.end())
            return nullptr;
        p = it->second;
    }
    for (const std::shared_ptr<const SourceFile>& f : p->files) {
        if (files.Get(f->path()) != f)
            return nullptr;  // a file changed since: made again
    }
    return p;
}

void PreambleCache::Remember(const std::string& key, std::shared_ptr<const Preamble> preamble) {
    std::lock_guard<std::mutex> lock(mu_);
    map_[key] = std::move(preamble);
}

size_t PreambleCache::size() const {
    std::lock_guard<std::mutex> lock(mu_);
    return map_.size();
}

}  // namespace kiln::hlsl
