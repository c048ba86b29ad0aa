#include "hlsl/tokens.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <unordered_set>

#include "hlsl/identifier.h"

namespace kiln::hlsl {

namespace {

// The length of the operator at s[i]: 3 for <<= and >>=, 2 for the two-character operators
// (== != <= >= += -= *= /= %= &= |= ^= ++ -- && || << >> :: ->), else 1.
size_t OperatorLength(const std::string& s, size_t i) {
    const char c = s[i];
    const char d = i + 1 < s.size() ? s[i + 1] : '\0';
    switch (c) {
        case '<':
        case '>':
            if (d == c)
                return i + 2 < s.size() && s[i + 2] == '=' ? 3 : 2;
            return d == '=' ? 2 : 1;
        case '=':
        case '!':
        case '*':
        case '/':
        case '%':
        case '^':
            return d == '=' ? 2 : 1;
        case '+':
        case '&':
        case '|':
            return d == '=' || d == c ? 2 : 1;
        case '-':
            return d == '=' || d == '-' || d == '>' ? 2 : 1;
        case ':':
            return d == ':' ? 2 : 1;
        default:
            return 1;
    }
}

// Tokens of s from byte `from`, where a line starts, appended to `out`.
void TokenizeFrom(const std::string& s, size_t from, std::vector<Token>& out) {
    bool line_start = true;
    for (size_t i = from; i < s.size();) {
        const char c = s[i];
        if (c == '\n') {
            line_start = true;
            ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f') {  // std::isspace
            ++i;
            continue;
        }
        if (line_start && c == '#') {
            const size_t eol = s.find('\n', i);
            i = eol == std::string::npos ? s.size() : eol;
            continue;
        }
        line_start = false;
        Token t;
        t.begin = i;
        if (IdentStart(c)) {
            while (i < s.size() && IdentChar(s[i]))
                ++i;
            t.ident = true;
        } else if ((c >= '0' && c <= '9') ||
                   (c == '.' && i + 1 < s.size() && s[i + 1] >= '0' && s[i + 1] <= '9')) {
            ++i;
            while (i < s.size() &&
                   (IdentChar(s[i]) || s[i] == '.' ||
                    ((s[i] == '+' || s[i] == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E'))))
                ++i;
        } else if (c == '"') {
            ++i;
            while (i < s.size() && s[i] != '"' && s[i] != '\n')
                ++i;
            if (i < s.size() && s[i] == '"')
                ++i;
        } else {
            i += OperatorLength(s, i);
        }
        t.end = i;
        t.text = std::string_view(s).substr(t.begin, t.end - t.begin);
        out.push_back(t);
    }
}

}  // namespace

std::vector<Token> Tokenize(const std::string& s) {
    std::vector<Token> out;
    out.reserve(s.size() / 4);
    TokenizeFrom(s, 0, out);
    return out;
}

std::vector<Token> TokenizeAfter(const std::string& s,
                                 size_t head_bytes,
                                 const std::vector<Token>& head) {
    if (head_bytes >= s.size() || s[head_bytes] != '\n')
        return Tokenize(s);  // the rest does not start a line: no token boundary is known there
    std::vector<Token> out;
    out.reserve(head.size() + (s.size() - head_bytes) / 4);
    const std::string_view view(s);
    for (Token t : head) {
        t.text = view.substr(t.begin, t.end - t.begin);
        out.push_back(t);
    }
    TokenizeFrom(s, head_bytes, out);
    return out;
}

bool IsAssignment(std::string_view op) {
    static const std::unordered_set<std::string_view> kOps = {
        "=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="};
    return kOps.count(op) > 0;
}

int NumericShape(std::string_view t) {
    // (float|half|fixed|int|uint|bool|double|min16float|min10float|min16int|min12int|min16uint)
    // then nothing (a scalar), a size 1-4 (a vector) or RxC with R, C in 1-4 (a matrix).
    static constexpr std::string_view kBases[] = {
        "float",  "half",       "fixed",      "int",      "uint",     "bool",
        "double", "min16float", "min10float", "min16int", "min12int", "min16uint"};
    auto size = [](char c) { return c >= '1' && c <= '4'; };
    for (const std::string_view base : kBases) {
        if (t.substr(0, base.size()) != base)
            continue;
        const std::string_view rest = t.substr(base.size());
        if (rest.empty())
            return 1;
        if (rest.size() == 1 && size(rest[0]))
            return rest[0] - '0';
        if (rest.size() == 3 && size(rest[0]) && rest[1] == 'x' && size(rest[2]))
            return 5;
    }
    return 0;
}

bool IsStatementWord(std::string_view t) {
    // By length, as a hash of every word of the text cost more than the compares (a rewrite
    // asks for most tokens).
    switch (t.size()) {
        case 2:
            return t == "in" || t == "do";
        case 3:
            return t == "out";
        case 4:
            return t == "else" || t == "case" || t == "goto";
        case 5:
            return t == "inout" || t == "const" || t == "break";
        case 6:
            return t == "return" || t == "struct" || t == "static" || t == "extern" ||
                   t == "inline" || t == "sizeof";
        case 7:
            return t == "typedef" || t == "cbuffer" || t == "tbuffer" || t == "uniform" ||
                   t == "discard";
        case 8:
            return t == "volatile" || t == "continue";
        default:
            return false;
    }
}

namespace {

std::string_view Partner(std::string_view b) {
    if (b == ")")
        return "(";
    if (b == "]")
        return "[";
    if (b == "}")
        return "{";
    if (b == "(")
        return ")";
    if (b == "[")
        return "]";
    if (b == "{")
        return "}";
    return "";
}

}  // namespace

bool SameTokens(const std::vector<Token>& a, const std::vector<Token>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Token& x, const Token& y) {
        return x.begin == y.begin && x.end == y.end && x.ident == y.ident &&
               x.text.data() == y.text.data();
    });
}

size_t MatchBack(const std::vector<Token>& tok, size_t close) {
    const std::string_view c = tok[close].text;
    const std::string_view o = Partner(c);
    int depth = 0;
    for (size_t k = close + 1; k-- > 0;) {
        if (tok[k].text == c)
            ++depth;
        else if (tok[k].text == o && --depth == 0)
            return k;
    }
    return SIZE_MAX;
}

size_t MatchForward(const std::vector<Token>& tok, size_t open) {
    const std::string_view o = tok[open].text;
    const std::string_view c = Partner(o);
    int depth = 0;
    for (size_t k = open; k < tok.size(); ++k) {
        if (tok[k].text == o)
            ++depth;
        else if (tok[k].text == c && --depth == 0)
            return k;
    }
    return SIZE_MAX;
}

RewriteWarning PlaceOf(const std::string& text, size_t offset) {
    RewriteWarning w;
    size_t from = 0;
    // The last #line directive before the offset, at the start of a line.
    for (size_t at = text.rfind("#line", offset); at != std::string::npos;
         at = at ? text.rfind("#line", at - 1) : std::string::npos) {
        if (at == 0 || text[at - 1] == '\n') {
            const char* p = text.c_str() + at + 5;
            char* rest = nullptr;
            w.line = static_cast<unsigned>(std::strtoul(p, &rest, 10));
            const size_t q1 = text.find('"', at);
            const size_t eol = text.find('\n', at);
            if (q1 != std::string::npos && q1 < eol) {
                const size_t q2 = text.find('"', q1 + 1);
                if (q2 != std::string::npos && q2 < eol)
                    w.file = text.substr(q1 + 1, q2 - q1 - 1);
            }
            from = eol == std::string::npos ? text.size() : eol + 1;
            break;
        }
        if (at == 0)
            break;
    }
    if (from == 0)
        w.line = 1;
    for (size_t i = from; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n')
            ++w.line;
    }
    return w;
}

}  // namespace kiln::hlsl
