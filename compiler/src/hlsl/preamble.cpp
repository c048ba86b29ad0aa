#include "hlsl/preamble.h"

#include <algorithm>
#include <unordered_set>
#include <utility>

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

std::string PreambleKey(std::string_view prefix,
                        const std::vector<std::string>& pinned,
                        std::string_view context) {
    const std::unordered_set<std::string_view> names(pinned.begin(), pinned.end());
    std::string key(context);
    key += '\0';
    for (const std::string& name : pinned) {
        key += name;
        key += '\1';
    }
    key += '\0';
    key.reserve(key.size() + prefix.size());
    constexpr std::string_view kDefine = "#define ";
    for (size_t at = 0; at < prefix.size();) {
        const size_t eol = prefix.find('\n', at);
        const size_t end = eol == std::string_view::npos ? prefix.size() : eol + 1;
        const std::string_view line = prefix.substr(at, end - at);
        at = end;
        if (StartsWith(line, kDefine)) {
            const std::string_view rest = line.substr(kDefine.size());
            const std::string_view name = rest.substr(0, rest.find_first_of(" \t\r\n"));
            if (names.count(name)) {
                key += kDefine;
                key += '\1';
                key += rest.substr(name.size());
                continue;
            }
        }
        key += line;
    }
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
