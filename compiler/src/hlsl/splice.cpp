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

// A token glslang prints no space around (`(char)token` in ";()[]").
bool Tight(std::string_view t) {
    return t.size() == 1 &&
           (t[0] == ';' || t[0] == '(' || t[0] == ')' || t[0] == '[' || t[0] == ']');
}

// Whether glslang prints a space between tokens `a` and `b` of one line.
bool SpaceBetween(std::string_view a, std::string_view b) {
    return !Tight(a) && !Tight(b) && b != ",";
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
    end.body = body;
    end.words_only = true;  // each run of name characters a word (no number)
    for (size_t i = 0; i < body.size() && end.words_only; ++i) {
        const bool starts = IdentChar(body[i]) && (i == 0 || !IdentChar(body[i - 1]));
        end.words_only = body[i] == ' ' || body[i] == '\t' ||
                         (IdentChar(body[i]) && !(starts && Digit(body[i])));
    }
    size_t start = body.size();
    while (start > 0 && IdentChar(body[start - 1]))
        --start;
    if (start < body.size() && !Digit(body[start]))
        end.last_word = body.substr(start);
    return end;
}

std::vector<char> MacroWords(const SpliceFile& file,
                             const std::unordered_set<std::string_view>& defined,
                             const std::unordered_set<std::string_view>& callable,
                             const std::unordered_set<std::string_view>& empty) {
    std::vector<char> macro(file.words.size(), kNoMacro);
    for (size_t id = 0; id < file.words.size(); ++id) {
        const std::string_view w = file.words[id];
        if (GlslangMayDefine(w) || callable.count(w))
            macro[id] = kCallMacro;
        else if (empty.count(w))
            macro[id] = kEmptyMacro;
        else if (defined.count(w))
            macro[id] = kMacro;
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
        bool active = pending, kept = false;
        for (uint32_t e = line.events_begin; e < line.events_end; ++e) {
            const int32_t event = file.events[e];
            if (event >= 0) {
                kept = kept || macro[event] >= kEmptyMacro;
                active = active || macro[event] == kCallMacro;
            } else if (active) {
                depth = event == SpliceFile::kOpen ? depth + 1 : std::max(depth - 1, 0);
            }
        }
        awaiting = line.last_word >= 0 && macro[line.last_word] == kCallMacro;
        if (line.kind == Kind::kPlain && !pending && !kept)
            out.push_back(l);
    }
    if (awaiting || depth > 0) {
        poisoned = true;
        return {};
    }
    return out;
}

SpliceChoice ChooseSpliceRuns(const SpliceFile& file, std::vector<char> macro) {
    SpliceChoice choice;
    choice.macro = std::move(macro);
    const std::string_view text = file.text->text;
    const auto spelling = [&](const SpliceFile::Tok& t) {
        return text.substr(t.begin, t.end - t.begin);
    };
    for (const uint32_t l : SpliceableLines(file, choice.macro, choice.poisoned)) {
        const Line& line = file.lines[l];
        // Runs between the first token, the last and the macros.
        uint32_t k = line.toks_begin + 1;
        while (k + 1 < line.toks_end) {
            uint32_t end = k;
            while (end + 1 < line.toks_end &&
                   (file.toks[end].word < 0 || choice.macro[file.toks[end].word] == kNoMacro))
                ++end;
            if (end - k >= 2) {
                SpliceRun run;
                run.line = l;
                run.begin = file.toks[k].begin;
                run.end = file.toks[end - 1].end;
                run.render_begin = static_cast<uint32_t>(choice.renders.size());
                for (uint32_t t = k; t < end; ++t) {
                    if (t > k && SpaceBetween(spelling(file.toks[t - 1]), spelling(file.toks[t])))
                        choice.renders += ' ';
                    choice.renders += spelling(file.toks[t]);
                }
                run.render_end = static_cast<uint32_t>(choice.renders.size());
                const std::string_view first = spelling(file.toks[k]);
                run.first_tight = Tight(first) || first == ",";
                run.last_tight = Tight(spelling(file.toks[end - 1]));
                choice.runs.push_back(run);
            }
            k = end + 1;
        }
    }
    if (choice.poisoned)
        choice.runs.clear();
    return choice;
}

std::string ServeSpliced(const SpliceFile& file,
                         const SpliceChoice& choice,
                         size_t inclusion,
                         const std::vector<std::pair<uint32_t, uint32_t>>& blank,
                         const std::vector<uint32_t>& runs,
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
    while (b < blank.size() || k < runs.size()) {
        if (k < runs.size() && (b == blank.size() || choice.runs[runs[k]].line < blank[b].first)) {
            const SpliceRun& run = choice.runs[runs[k]];
            out.append(text, copied, run.begin - copied);
            out += ' ';
            out += kSpliceMarker;
            append_number(inclusion);
            out += 'x';
            append_number(runs[k]);
            out += ' ';
            copied = run.end;
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

bool Unsplice(std::string& text, const std::vector<std::shared_ptr<const SpliceChoice>>& files) {
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
    const auto tight = [](char c) {
        return c == ';' || c == '(' || c == ')' || c == '[' || c == ']';
    };
    for (size_t p = text.find(kSpliceMarker); p != std::string::npos;
         p = text.find(kSpliceMarker, p + 1)) {
        size_t i = p + kSpliceMarker.size(), k = 0, r = 0;
        if (i < text.size() && text[i] == kOutputMarkTag)
            continue;  // a remembered output's marked name (hlsl/output_memo.h), given back after
        if ((p > 0 && IdentChar(text[p - 1])) || !read_number(i, k) || i >= text.size() ||
            text[i++] != 'x' || !read_number(i, r) || (i < text.size() && IdentChar(text[i])))
            return false;
        if (k >= files.size() || !files[k] || r >= files[k]->runs.size())
            return false;
        std::vector<char>& seen = used[k];
        seen.resize(files[k]->runs.size());
        if (seen[r])
            return false;
        seen[r] = 1;
        const SpliceRun& run = files[k]->runs[r];
        // The tokens glslang printed around the marker, on its line, and its spaces from them.
        size_t from = p, to = i;
        if (from > 0 && text[from - 1] == ' ')
            --from;
        if (to < text.size() && text[to] == ' ')
            ++to;
        if (from == 0 || to >= text.size() || from < copied)
            return false;
        const char before = text[from - 1], after = text[to];
        if (before == ' ' || before == '\n' || after == ' ' || after == '\n' ||
            (from < p) != !tight(before) || (to > i) != !(tight(after) || after == ','))
            return false;
        if (out.empty())
            out.reserve(text.size() + text.size() / 2);
        out.append(text, copied, from - copied);
        if (!tight(before) && !run.first_tight)
            out += ' ';
        out.append(files[k]->renders, run.render_begin, run.render_end - run.render_begin);
        if (!run.last_tight && !(tight(after) || after == ','))
            out += ' ';
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
