#include "hlsl/splice.h"

#include <algorithm>
#include <charconv>

#include "hlsl/identifier.h"
#include "hlsl/lean_text.h"
#include "hlsl/pp_macros.h"

namespace kiln::hlsl {
namespace {

using Line = SpliceFile::Line;
using Kind = SpliceFile::Kind;

bool Digit(char c) {
    return c >= '0' && c <= '9';
}

}  // namespace

DefineEnd EndOfDefine(std::string_view rest) {
    DefineEnd end;
    const std::string_view name = DirectiveMacroName(rest);
    std::string_view body = rest.substr(name.empty() ? 0 : name.data() - rest.data() + name.size());
    const auto count = [&](char c) { return std::count(body.begin(), body.end(), c); };
    if (name.empty() || (!body.empty() && body[0] == '(') ||
        body.find("##") != std::string_view::npos || count('(') != count(')')) {
        end.calls = true;
        return end;
    }
    while (!body.empty() && (body.back() == ' ' || body.back() == '\t' || body.back() == '\r'))
        body.remove_suffix(1);
    size_t start = body.size();
    while (start > 0 && IdentChar(body[start - 1]))
        --start;
    if (start < body.size() && !Digit(body[start]))
        end.last_word = body.substr(start);
    return end;
}

std::vector<char> MacroWords(const SpliceFile& file,
                             const std::unordered_set<std::string_view>& defined,
                             const std::unordered_set<std::string_view>& callable) {
    std::vector<char> macro(file.words.size(), 0);
    for (size_t id = 0; id < file.words.size(); ++id) {
        const std::string_view w = file.words[id];
        if (GlslangMayDefine(w) || callable.count(w))
            macro[id] = 2;
        else if (defined.count(w))
            macro[id] = 1;
    }
    return macro;
}

std::vector<uint32_t> SpliceableLines(const SpliceFile& file,
                                      const std::vector<char>& macro,
                                      bool& poisoned) {
    std::vector<uint32_t> out;
    if (!file.usable)
        return out;
    bool awaiting = false;  // the last line of code ended with a macro's name
    int depth = 0;          // brackets open since a macro's name
    for (uint32_t l = 0; l < file.lines.size(); ++l) {
        const Line& line = file.lines[l];
        if (line.kind == Kind::kDirective) {
            if (awaiting || depth > 0) {
                poisoned = true;
                return {};
            }
            continue;
        }
        if (line.kind == Kind::kEmpty)
            continue;
        const bool pending = awaiting || depth > 0;
        bool active = pending, named = false;
        for (uint32_t e = line.events_begin; e < line.events_end; ++e) {
            const int32_t event = file.events[e];
            if (event >= 0) {
                named = named || macro[event] != 0;
                active = active || macro[event] == 2;
            } else if (active) {
                depth = event == SpliceFile::kOpen ? depth + 1 : std::max(depth - 1, 0);
            }
        }
        awaiting = line.last_word >= 0 && macro[line.last_word] == 2;
        if (line.kind == Kind::kPlain && !pending && !named)
            out.push_back(l);
    }
    if (awaiting || depth > 0) {
        poisoned = true;
        return {};
    }
    return out;
}

SpliceChoice ChooseSpliceLines(const SpliceFile& file,
                               const std::unordered_set<std::string_view>& defined,
                               const std::unordered_set<std::string_view>& callable) {
    SpliceChoice choice;
    choice.macro = MacroWords(file, defined, callable);
    choice.lines = SpliceableLines(file, choice.macro, choice.poisoned);
    return choice;
}

std::string ServeSpliced(const SpliceFile& file,
                         size_t inclusion,
                         const std::vector<std::pair<uint32_t, uint32_t>>& blank,
                         const std::vector<uint32_t>& lines,
                         size_t& blanked_lines) {
    const std::string& text = file.text->text;
    const std::vector<uint32_t>& starts = file.text->line_starts;
    std::string out;
    out.reserve(text.size());
    char number[24];
    const auto append_number = [&](size_t v) {
        const auto r = std::to_chars(number, number + sizeof(number), v);
        out.append(number, r.ptr);
    };
    size_t copied = 0, b = 0, k = 0;
    while (b < blank.size() || k < lines.size()) {
        if (k < lines.size() && (b == blank.size() || lines[k] < blank[b].first)) {
            const Line& line = file.lines[lines[k]];
            out.append(text, copied, line.first_end - copied);
            out += ' ';
            out += kSpliceMarker;
            append_number(inclusion);
            out += 'x';
            append_number(lines[k]);
            out += ' ';
            copied = line.last_begin;
            ++k;
            continue;
        }
        const auto [first, last] = blank[b++];
        out.append(text, copied, starts[first] - copied);
        const bool at_end = last + 1 >= starts.size();
        out.append(last - first + (at_end ? 0 : 1), '\n');
        blanked_lines += last - first + 1;
        if (at_end && !text.empty() && text.back() != '\n')
            out += ' ';  // as BlankLines
        copied = at_end ? text.size() : starts[last + 1];
    }
    out.append(text, copied);
    return out;
}

bool Unsplice(std::string& text, const std::vector<std::shared_ptr<const SpliceFile>>& files) {
    std::string out;
    size_t copied = 0;
    std::vector<std::vector<char>> used(files.size());
    const auto read_number = [&](size_t& i, size_t& value) {
        const auto r = std::from_chars(text.data() + i, text.data() + text.size(), value);
        if (r.ec != std::errc() || r.ptr == text.data() + i)
            return false;
        i = r.ptr - text.data();
        return true;
    };
    for (size_t p = text.find(kSpliceMarker); p != std::string::npos;
         p = text.find(kSpliceMarker, p + 1)) {
        size_t i = p + kSpliceMarker.size(), k = 0, l = 0;
        if ((p > 0 && IdentChar(text[p - 1])) || !read_number(i, k) || i >= text.size() ||
            text[i++] != 'x' || !read_number(i, l) || (i < text.size() && IdentChar(text[i])))
            return false;
        if (k >= files.size() || !files[k] || l >= files[k]->lines.size() ||
            files[k]->lines[l].kind != Kind::kPlain)
            return false;
        std::vector<char>& seen = used[k];
        seen.resize(files[k]->lines.size());
        if (seen[l])
            return false;
        seen[l] = 1;
        const Line& line = files[k]->lines[l];
        // glslang's spaces around the marker: one where the line's ends take one, else none.
        size_t from = p, to = i;
        if (line.space_after_first && (from == 0 || text[--from] != ' '))
            return false;
        if (line.space_before_last && (to >= text.size() || text[to++] != ' '))
            return false;
        if ((from > 0 && text[from - 1] == ' ') || (to < text.size() && text[to] == ' '))
            return false;
        if (from < copied)
            return false;
        if (out.empty())
            out.reserve(text.size() + text.size() / 2);
        out.append(text, copied, from - copied);
        out.append(files[k]->middles, line.middle_begin, line.middle_end - line.middle_begin);
        copied = to;
        p = to - 1;
    }
    if (copied == 0)
        return true;
    out.append(text, copied);
    text = std::move(out);
    return true;
}

}  // namespace kiln::hlsl
