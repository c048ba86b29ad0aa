#include "hlsl/pp_skeleton.h"

#include <array>
#include <utility>

#include "hlsl/identifier.h"

namespace kiln::hlsl {
namespace {

constexpr std::array<std::pair<std::string_view, PpKind>, 16> kNames = {{
    {"if", PpKind::kIf},
    {"ifdef", PpKind::kIfdef},
    {"ifndef", PpKind::kIfndef},
    {"elif", PpKind::kElif},
    {"else", PpKind::kElse},
    {"endif", PpKind::kEndif},
    {"define", PpKind::kDefine},
    {"undef", PpKind::kUndef},
    {"include", PpKind::kInclude},
    {"pragma", PpKind::kPragma},
    {"line", PpKind::kKnown},
    {"error", PpKind::kKnown},
    {"extension", PpKind::kKnown},
    {"version", PpKind::kKnown},
    {"warning", PpKind::kKnown},
    {"", PpKind::kUnknown},
}};

bool IsSpace(int c) {
    return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

bool IsIdent(int c) {
    return c >= 0 && IdentChar(static_cast<char>(c));
}

bool IsDigit(char c) {
    return c >= '0' && c <= '9';
}

// A number glslang's scanner reads without a message: an int that fits 32 bits (decimal, octal
// or hex, `u` allowed) or a plain float (`f` or HLSL's `h` allowed). Anything else (a bad digit, an
// exponent without digits, another suffix, a too long literal) is not modelled.
bool SafeNumber(std::string_view n) {
    if (!n.empty() && (n.back() == 'u' || n.back() == 'U')) {
        n.remove_suffix(1);
        if (n.find_first_of(".eE") != std::string_view::npos &&
            !(n.size() > 1 && (n[1] == 'x' || n[1] == 'X')))
            return false;
    }
    if (n.size() > 2 && n[0] == '0' && (n[1] == 'x' || n[1] == 'X')) {
        if (n.size() > 10)
            return false;
        for (size_t i = 2; i < n.size(); ++i) {
            const char c = n[i];
            if (!IsDigit(c) && !(c >= 'a' && c <= 'f') && !(c >= 'A' && c <= 'F'))
                return false;
        }
        return true;
    }
    if (n.find_first_of(".eE") == std::string_view::npos) {  // an int
        if (n.empty() || n.size() > 11)
            return false;
        uint64_t v = 0;
        for (char c : n) {
            if (!IsDigit(c) || (n[0] == '0' && c > '7'))
                return false;
            v = v * (n[0] == '0' ? 8 : 10) + static_cast<uint64_t>(c - '0');
        }
        return v <= 0xFFFFFFFFu;
    }
    if (!n.empty() && (n.back() == 'f' || n.back() == 'F' || n.back() == 'h' || n.back() == 'H'))
        n.remove_suffix(1);
    size_t i = 0, digits = 0;
    while (i < n.size() && IsDigit(n[i]))
        ++i, ++digits;
    if (i < n.size() && n[i] == '.') {
        ++i;
        while (i < n.size() && IsDigit(n[i]))
            ++i, ++digits;
    }
    if (digits == 0 || digits > 40)
        return false;
    if (i < n.size() && (n[i] == 'e' || n[i] == 'E')) {
        ++i;
        if (i < n.size() && (n[i] == '+' || n[i] == '-'))
            ++i;
        const size_t exponent = i;
        while (i < n.size() && IsDigit(n[i]))
            ++i;
        if (i == exponent || i - exponent > 3)
            return false;
    }
    return i == n.size();
}

// Whether glslang's scanner reads `code` (comments removed) without a message. It reports a
// malformed character literal or number even in text it skips, so such a file is not blanked.
bool LexicallySafe(std::string_view code) {
    size_t i = 0;
    while (i < code.size()) {
        const char c = code[i];
        if (c == '"') {
            const size_t close = code.find('"', i + 1);
            i = close == std::string_view::npos ? code.size() : close + 1;
        } else if (c == '\'') {
            // 'c' or '\c', as glslang's characterLiteral takes them silently.
            if (i + 2 < code.size() && code[i + 1] != '\'' && code[i + 1] != '\\' &&
                code[i + 2] == '\'') {
                i += 3;
            } else if (i + 3 < code.size() && code[i + 1] == '\\' && code[i + 2] != 'x' &&
                       code[i + 3] == '\'') {
                i += 4;
            } else {
                return false;
            }
        } else if (IsIdent(c) && !IsDigit(c)) {
            const size_t start = i;
            while (i < code.size() && IsIdent(code[i]))
                ++i;
            if (i - start > 1000)
                return false;
        } else if (IsDigit(c) || (c == '.' && i + 1 < code.size() && IsDigit(code[i + 1]))) {
            const size_t start = i;
            const bool hex = c == '0' && i + 1 < code.size() && (code[i + 1] | 0x20) == 'x';
            while (i < code.size() && (IsIdent(code[i]) || code[i] == '.' ||
                                       (!hex && (code[i] == '+' || code[i] == '-') &&
                                        (code[i - 1] == 'e' || code[i - 1] == 'E'))))
                ++i;
            if (!SafeNumber(code.substr(start, i - start)))
                return false;
        } else {
            ++i;
        }
    }
    return true;
}

bool Blank(std::string_view s) {
    for (char c : s) {
        if (!IsSpace(c))
            return false;
    }
    return true;
}

// `s` is one name between blanks.
bool OneName(std::string_view s) {
    size_t i = 0;
    while (i < s.size() && IsSpace(s[i]))
        ++i;
    if (i == s.size() || IsDigit(s[i]) || !IsIdent(s[i]))
        return false;
    while (i < s.size() && IsIdent(s[i]))
        ++i;
    return Blank(s.substr(i));
}

// Adds the identifiers of `code` (comments already removed) to `words`.
void AddWords(std::string_view code, std::unordered_map<std::string, uint32_t>& words) {
    ForEachWord(code, [&](std::string_view word) { ++words[std::string(word)]; });
}

// Reads characters as glslang's tStringInput::getch does: backslash-newline pairs vanish.
struct Cursor {
    std::string_view t;
    size_t i = 0;
    uint32_t line = 0;

    void Splice() {
        while (i + 1 < t.size() && t[i] == '\\' && (t[i + 1] == '\n' || t[i + 1] == '\r')) {
            i += (t[i + 1] == '\r' && i + 2 < t.size() && t[i + 2] == '\n') ? 3 : 2;
            ++line;
        }
    }
    int Peek() {
        Splice();
        return i < t.size() ? static_cast<unsigned char>(t[i]) : -1;
    }
    // The character after the next one (no splice between them is looked through).
    int PeekSecond() const { return i + 1 < t.size() ? static_cast<unsigned char>(t[i + 1]) : -1; }
    int Get() {
        const int c = Peek();
        if (c < 0)
            return c;
        ++i;
        if (c == '\r' && i < t.size() && t[i] == '\n')
            ++i;
        if (c == '\r' || c == '\n') {
            ++line;
            return '\n';
        }
        return c;
    }
};

struct State {
    Cursor c;
    PpSkeleton& out;
    std::vector<uint32_t> open;  // the last branch directive of each open conditional
};

// Consumes a block comment whose "/*" is next. Returns false at the end of the file.
bool BlockComment(Cursor& c) {
    c.Get();
    c.Get();
    int prev = 0;
    for (int ch = c.Get(); ch >= 0; ch = c.Get()) {
        if (prev == '*' && ch == '/')
            return true;
        prev = ch;
    }
    return false;
}

// Consumes a line comment whose "//" is next, up to (not including) the newline.
void LineComment(Cursor& c) {
    while (c.Peek() >= 0 && c.Peek() != '\r' && c.Peek() != '\n')
        c.Get();
}

// Consumes a "..." or '...' literal whose quote is next, appending it to `text` (when given).
// A literal with a backslash or without its closing quote on the line is not modelled.
bool Literal(Cursor& c, std::string* text) {
    const int quote = c.Get();
    if (text)
        *text += static_cast<char>(quote);
    for (int ch = c.Peek(); ch >= 0 && ch != '\n' && ch != '\r'; ch = c.Peek()) {
        c.Get();
        if (text)
            *text += static_cast<char>(ch);
        if (ch == '\\')
            return false;
        if (ch == quote)
            return true;
    }
    return false;
}

// The rest of a non-directive line, up to and including its newline.
void CodeLine(State& s) {
    Cursor& c = s.c;
    std::string code;
    for (int ch = c.Peek(); ch >= 0; ch = c.Peek()) {
        if (ch == '\n' || ch == '\r') {
            c.Get();
            break;
        }
        if (ch == '/' && c.PeekSecond() == '/') {
            LineComment(c);
        } else if (ch == '/' && c.PeekSecond() == '*') {
            if (!BlockComment(c))
                s.out.safe = false;
            code += ' ';
        } else if (ch == '"' || ch == '\'') {
            if (!Literal(c, &code))
                s.out.safe = false;
        } else {
            code += static_cast<char>(c.Get());
        }
    }
    if (!LexicallySafe(code))
        s.out.safe = false;
    AddWords(code, s.out.words);
}

// Links a conditional's branch directives; false when they do not nest.
bool Link(State& s, PpKind kind, uint32_t index) {
    std::vector<PpDirective>& d = s.out.directives;
    if (kind == PpKind::kIf || kind == PpKind::kIfdef || kind == PpKind::kIfndef) {
        s.open.push_back(index);
        return true;
    }
    if (kind != PpKind::kElif && kind != PpKind::kElse && kind != PpKind::kEndif)
        return true;
    if (s.open.empty() || (d[s.open.back()].kind == PpKind::kElse && kind != PpKind::kEndif))
        return false;
    d[s.open.back()].next = index;
    if (kind == PpKind::kEndif)
        s.open.pop_back();
    else
        s.open.back() = index;
    return true;
}

// A directive line whose '#' is next.
void Directive(State& s) {
    Cursor& c = s.c;
    PpDirective d;
    d.first_line = c.line;
    c.Get();
    while (IsSpace(c.Peek()))
        c.Get();
    std::string name;
    while (IsIdent(c.Peek()))
        name += static_cast<char>(c.Get());
    for (const auto& [n, kind] : kNames) {
        if (n == name || n.empty()) {
            d.kind = kind;
            break;
        }
    }
    for (int ch = c.Peek(); ch >= 0; ch = c.Peek()) {
        if (ch == '\n' || ch == '\r')
            break;
        if (ch == '/' && c.PeekSecond() == '/') {
            LineComment(c);
        } else if (ch == '/' && c.PeekSecond() == '*') {
            const uint32_t line = c.line;
            if (!BlockComment(c) || c.line != line)
                s.out.safe = false;  // a comment that joins lines of a directive: not modelled
            d.rest += ' ';
        } else if (ch == '"' || ch == '\'') {
            if (!Literal(c, &d.rest))
                s.out.safe = false;
        } else {
            d.rest += static_cast<char>(c.Get());
        }
    }
    d.last_line = c.line;
    c.Get();
    // glslang reads `# #if` in skipped text as an #if (the token after the first '#' is not a
    // name, so it looks again from the second): not modelled.
    if (name.empty() && d.rest.find('#') != std::string::npos)
        s.out.safe = false;
    if (!LexicallySafe(d.rest))
        s.out.safe = false;
    AddWords(d.rest, s.out.words);
    if (d.kind == PpKind::kDefine && d.rest.find("##") != std::string::npos)
        s.out.pastes = true;
    // glslang checks these even in skipped text: tokens after #else or #endif, and an #ifdef or
    // #ifndef without exactly one name (found by the fuzz target: `#endif#` in skipped text).
    if ((d.kind == PpKind::kElse || d.kind == PpKind::kEndif) && !Blank(d.rest))
        s.out.safe = false;
    if ((d.kind == PpKind::kIfdef || d.kind == PpKind::kIfndef) && !OneName(d.rest))
        s.out.safe = false;
    const uint32_t index = static_cast<uint32_t>(s.out.directives.size());
    const PpKind kind = d.kind;
    s.out.directives.push_back(std::move(d));
    if (!Link(s, kind, index))
        s.out.safe = false;
}

}  // namespace

PpSkeleton ScanSkeleton(std::string_view text) {
    PpSkeleton out;
    out.line_starts.push_back(0);
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n')
            out.line_starts.push_back(static_cast<uint32_t>(i + 1));
        else if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))
            out.safe = false;  // a lone CR ends a line for glslang but not its line count
    }
    out.line_count = static_cast<uint32_t>(out.line_starts.size());
    if (!out.safe)
        return out;
    State s{Cursor{text}, out, {}};
    while (s.c.Peek() >= 0) {
        while (IsSpace(s.c.Peek()))
            s.c.Get();
        bool comment_first = false;
        while (s.c.Peek() == '/' && s.c.PeekSecond() == '*') {
            if (!BlockComment(s.c))
                out.safe = false;
            comment_first = true;
            while (IsSpace(s.c.Peek()))
                s.c.Get();
        }
        if (s.c.Peek() == '#') {
            if (comment_first)
                out.safe = false;  // whether glslang takes this as a directive is not modelled
            Directive(s);
        } else {
            CodeLine(s);
        }
    }
    if (!s.open.empty())
        out.safe = false;
    return out;
}

}  // namespace kiln::hlsl
