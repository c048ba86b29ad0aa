#include "hlsl/rewrite.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <regex>
#include <set>
#include <string_view>
#include <vector>

#include "hlsl/identifier.h"

namespace kiln::hlsl {
namespace {

struct Token {
    size_t begin = 0, end = 0;
    bool ident = false;
    std::string_view text;
};

// Tokens of the preprocessed text; directive lines (#line, #pragma, #extension) are skipped.
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

bool IsOneVectorType(std::string_view t) {
    static const std::set<std::string_view> kTypes = {
        "float1",  "half1",       "fixed1",      "int1",      "uint1",     "bool1",
        "double1", "min16float1", "min10float1", "min16int1", "min12int1", "min16uint1"};
    return kTypes.count(t) > 0;
}

// What can follow the declared name in a declaration.
bool EndsDeclarator(std::string_view t) {
    return t == ";" || t == "," || t == ":" || t == ")" || t == "=" || t == "[";
}

// Words that can precede `name ;` without declaring it.
bool IsStatementWord(std::string_view t) {
    static const std::set<std::string_view> kWords = {
        "return", "else",   "case",    "goto",    "typedef",  "struct", "cbuffer", "tbuffer",
        "in",     "out",    "inout",   "uniform", "static",   "const",  "extern",  "volatile",
        "inline", "sizeof", "discard", "break",   "continue", "do"};
    return kWords.count(t) > 0;
}

struct Edit {
    size_t begin, end;
    std::string text;
};

// Names declared only with a 1-vector type (the `.x` after them is the identity).
std::set<std::string_view> OneVectorNames(const std::vector<Token>& tok) {
    std::set<std::string_view> one, other;
    int decl = 0;  // inside a declaration list: 1 one-vector type, -1 another type, 0 none
    for (size_t i = 0; i + 2 < tok.size(); ++i) {
        const Token& a = tok[i];
        const Token& b = tok[i + 1];
        if (a.text == ";" || a.text == "{" || a.text == "}")
            decl = 0;
        if (a.ident && b.ident && !IsStatementWord(a.text) && EndsDeclarator(tok[i + 2].text)) {
            const bool is_one = IsOneVectorType(a.text);
            (is_one ? one : other).insert(b.text);
            decl = is_one ? 1 : -1;
            continue;
        }
        if (a.text == "," && b.ident && EndsDeclarator(tok[i + 2].text)) {
            (decl == 1 ? one : other).insert(b.text);
        }
    }
    std::set<std::string_view> out;
    for (std::string_view n : one) {
        if (!other.count(n))
            out.insert(n);
    }
    return out;
}

void OneVectorSwizzles(const std::vector<Token>& tok, std::vector<Edit>& edits, size_t& count) {
    const std::set<std::string_view> names = OneVectorNames(tok);
    if (names.empty())
        return;
    for (size_t i = 0; i + 2 < tok.size(); ++i) {
        if (tok[i].ident && names.count(tok[i].text) && tok[i + 1].text == "." &&
            (tok[i + 2].text == "x" || tok[i + 2].text == "r") &&
            (i + 3 >= tok.size() || tok[i + 3].text != ".")) {
            edits.push_back({tok[i + 1].begin, tok[i + 2].end, ""});
            ++count;
        }
    }
}

// fxc's infinity literal `1.#INF` (also how its disassembler prints infinity): glslang's scanner
// reads it, but its preprocessed output spells it `1.INF`, which glslang then cannot parse. A
// number token `1.INF` exists only that way, so it is put back.
void InfinityLiterals(const std::vector<Token>& tok, std::vector<Edit>& edits, size_t& count) {
    for (const Token& t : tok) {
        if (!t.ident && t.text == "1.INF") {
            edits.push_back({t.begin, t.end, "1.#INF"});
            ++count;
        }
    }
}

// Index of the bracket that opens the one closing at `close`, or SIZE_MAX.
size_t MatchBack(const std::vector<Token>& tok, size_t close) {
    const std::string_view c = tok[close].text;
    const std::string_view o = c == ")" ? "(" : "[";
    int depth = 0;
    for (size_t k = close + 1; k-- > 0;) {
        if (tok[k].text == c)
            ++depth;
        else if (tok[k].text == o && --depth == 0)
            return k;
    }
    return SIZE_MAX;
}

// First token of the postfix expression that ends at `last` (identifiers joined by '.', calls,
// indexing, parentheses), or SIZE_MAX.
size_t PrimaryStart(const std::vector<Token>& tok, size_t last) {
    size_t k = last;
    while (true) {
        if (tok[k].text == ")" || tok[k].text == "]") {
            k = MatchBack(tok, k);
            if (k == SIZE_MAX)
                return SIZE_MAX;
            if (k > 0 && tok[k - 1].ident && !IsStatementWord(tok[k - 1].text))
                --k;  // a call or an indexed name
        } else if (!tok[k].ident) {
            return SIZE_MAX;
        }
        if (k >= 2 && tok[k - 1].text == ".") {
            k -= 2;
            continue;
        }
        return k;
    }
}

void MatrixSwizzles(const std::string& s,
                    const std::vector<Token>& tok,
                    std::vector<Edit>& edits,
                    size_t& count) {
    static const std::regex kSwizzle("((_m[0-3][0-3])|(_[1-4][1-4])){2,4}");
    static const std::regex kElement("_m[0-3][0-3]|_[1-4][1-4]");
    for (size_t i = 1; i + 1 < tok.size(); ++i) {
        if (tok[i].text != "." || !tok[i + 1].ident || tok[i + 1].text[0] != '_')
            continue;
        const std::string swizzle(tok[i + 1].text);
        if (!std::regex_match(swizzle, kSwizzle))
            continue;
        if (i + 2 < tok.size() && IsAssignment(tok[i + 2].text))
            continue;  // a write: left as it is
        const size_t start = PrimaryStart(tok, i - 1);
        if (start == SIZE_MAX)
            continue;
        const std::string primary = s.substr(tok[start].begin, tok[i - 1].end - tok[start].begin);
        if (primary.find('\n') != std::string::npos)
            continue;  // would move lines
        std::vector<std::string> parts;
        for (auto it = std::sregex_iterator(swizzle.begin(), swizzle.end(), kElement);
             it != std::sregex_iterator(); ++it) {
            parts.push_back("(" + primary + ")." + it->str());
        }
        std::string text = "float" + std::to_string(parts.size()) + "(";
        for (size_t p = 0; p < parts.size(); ++p)
            text += (p ? ", " : "") + parts[p];
        text += ")";
        edits.push_back({tok[start].begin, tok[i + 1].end, text});
        ++count;
    }
}

}  // namespace

RewriteResult RewriteForGlslang(const std::string& preprocessed) {
    RewriteResult r;
    const std::vector<Token> tok = Tokenize(preprocessed);
    std::vector<Edit> edits;
    OneVectorSwizzles(tok, edits, r.one_vector_swizzles);
    MatrixSwizzles(preprocessed, tok, edits, r.matrix_swizzles);
    InfinityLiterals(tok, edits, r.infinity_literals);
    if (edits.empty()) {
        r.text = preprocessed;
        return r;
    }
    // Non-overlapping by construction (a matrix swizzle never ends in `.x`); apply in order.
    std::sort(edits.begin(), edits.end(),
              [](const Edit& a, const Edit& b) { return a.begin < b.begin; });
    r.text.reserve(preprocessed.size() + edits.size() * 16);
    size_t at = 0;
    for (const Edit& e : edits) {
        if (e.begin < at)
            continue;
        r.text.append(preprocessed, at, e.begin - at);
        r.text += e.text;
        at = e.end;
    }
    r.text.append(preprocessed, at, std::string::npos);
    return r;
}

}  // namespace kiln::hlsl
