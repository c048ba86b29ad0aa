#include "hlsl/tokens.h"

#include <cctype>
#include <cstdlib>
#include <regex>
#include <set>

#include "hlsl/identifier.h"

namespace kiln::hlsl {

std::vector<Token> Tokenize(const std::string& s) {
    static const char* const kMulti[] = {"<<=", ">>=", "==", "!=", "<=", ">=", "+=", "-=",
                                         "*=",  "/=",  "%=", "&=", "|=", "^=", "++", "--",
                                         "&&",  "||",  "<<", ">>", "::", "->"};
    std::vector<Token> out;
    bool line_start = true;
    for (size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (c == '\n') {
            line_start = true;
            ++i;
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        if (line_start && c == '#') {
            while (i < s.size() && s[i] != '\n')
                ++i;
            continue;
        }
        line_start = false;
        Token t;
        t.begin = i;
        if (IdentStart(c)) {
            while (i < s.size() && IdentChar(s[i]))
                ++i;
            t.ident = true;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < s.size() &&
                    std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
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
            size_t len = 1;
            for (const char* m : kMulti) {
                const size_t n = std::char_traits<char>::length(m);
                if (s.compare(i, n, m) == 0) {
                    len = n;
                    break;
                }
            }
            i += len;
        }
        t.end = i;
        t.text = std::string_view(s).substr(t.begin, t.end - t.begin);
        out.push_back(t);
    }
    return out;
}

bool IsAssignment(std::string_view op) {
    static const std::set<std::string_view> kOps = {
        "=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="};
    return kOps.count(op) > 0;
}

int NumericShape(std::string_view t) {
    static const std::regex kType(
        "(float|half|fixed|int|uint|bool|double|min16float|min10float|min16int|min12int|"
        "min16uint)([1-4](x[1-4])?)?");
    std::match_results<std::string_view::const_iterator> m;
    if (!std::regex_match(t.begin(), t.end(), m, kType))
        return 0;
    if (m[3].matched)
        return 5;
    return m[2].matched ? m[2].str()[0] - '0' : 1;
}

bool IsStatementWord(std::string_view t) {
    static const std::set<std::string_view> kWords = {
        "return", "else",   "case",    "goto",    "typedef",  "struct", "cbuffer", "tbuffer",
        "in",     "out",    "inout",   "uniform", "static",   "const",  "extern",  "volatile",
        "inline", "sizeof", "discard", "break",   "continue", "do"};
    return kWords.count(t) > 0;
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
