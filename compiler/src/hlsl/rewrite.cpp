#include "hlsl/rewrite.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "hlsl/identifier.h"
#include "hlsl/rewrite_steps.h"

namespace kiln::hlsl {
namespace {

bool IsOneVectorType(std::string_view t) {
    static const std::unordered_set<std::string_view> kTypes = {
        "float1",  "half1",       "fixed1",      "int1",      "uint1",     "bool1",
        "double1", "min16float1", "min10float1", "min16int1", "min12int1", "min16uint1"};
    return kTypes.count(t) > 0;
}

// What can follow the declared name in a declaration.
bool EndsDeclarator(std::string_view t) {
    return t == ";" || t == "," || t == ":" || t == ")" || t == "=" || t == "[";
}

// Names declared only with a 1-vector type (the `.x` after them is the identity).
std::unordered_set<std::string_view> OneVectorNames(const std::vector<Token>& tok) {
    if (std::none_of(tok.begin(), tok.end(), [](const Token& t) {
            return t.ident && !t.text.empty() && t.text.back() == '1' && IsOneVectorType(t.text);
        }))
        return {};  // most programs declare none: no set of every declared name
    std::unordered_set<std::string_view> one, other;
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
    std::unordered_set<std::string_view> out;
    for (std::string_view n : one) {
        if (!other.count(n))
            out.insert(n);
    }
    return out;
}

void OneVectorSwizzles(const std::vector<Token>& tok, std::vector<Edit>& edits, size_t& count) {
    const std::unordered_set<std::string_view> names = OneVectorNames(tok);
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

// `min16float3x3` -> `float3x3` (and min10float, min16int/min12int -> int, min16uint -> uint):
// glslang 12 has minimum-precision scalars and vectors but no such matrices. Padded with spaces
// to the name's length, so the columns after it hold.
void MinPrecisionMatrices(const std::vector<Token>& tok, std::vector<Edit>& edits, size_t& count) {
    static const std::regex kMatrix(
        "(min16float|min10float|min16int|min12int|min16uint)([1-4]x[1-4])");
    std::match_results<std::string_view::const_iterator> m;
    for (const Token& t : tok) {
        if (!t.ident || t.text.size() < 11 || t.text.compare(0, 3, "min") != 0 ||
            !std::regex_match(t.text.begin(), t.text.end(), m, kMatrix))
            continue;
        const std::string base = m[1].str();
        std::string text = (base == "min16uint"                     ? "uint"
                            : base.find("int") != std::string::npos ? "int"
                                                                    : "float") +
                           m[2].str();
        text.resize(t.text.size(), ' ');
        edits.push_back({t.begin, t.end, text});
        ++count;
    }
}

// fxc's `VPOS` pixel-shader input (the pixel position; Unity's UNITY_VPOS_TYPE screenPos : VPOS)
// is SV_Position to glslang, which otherwise makes it a user varying no stage writes.
void VposSemantics(const std::vector<Token>& tok, std::vector<Edit>& edits, size_t& count) {
    for (size_t i = 1; i < tok.size(); ++i) {
        if (tok[i].ident && tok[i - 1].text == ":" &&
            (tok[i].text == "VPOS" || tok[i].text == "vpos")) {
            edits.push_back({tok[i].begin, tok[i].end, "SV_Position"});
            ++count;
        }
    }
}

// fxc converts a `switch` selector to int (a float selector truncates); glslang requires an
// integer. `switch (x)` becomes `switch ((int)(x))`, which is the identity for an int selector
// and the same bits for a uint one (glslang converts the case labels alike).
void SwitchSelectors(const std::vector<Token>& tok, std::vector<Edit>& edits, size_t& count) {
    for (size_t i = 0; i + 1 < tok.size(); ++i) {
        if (tok[i].text != "switch" || tok[i + 1].text != "(")
            continue;
        const size_t close = MatchForward(tok, i + 1);
        if (close == SIZE_MAX || close == i + 2)
            continue;
        if (tok[i + 2].text == "(" && i + 4 < close && tok[i + 3].text == "int" &&
            tok[i + 4].text == ")")
            continue;  // already (int)
        edits.push_back({tok[i + 1].end, tok[i + 1].end, "(int)("});
        edits.push_back({tok[close].begin, tok[close].begin, ")"});
        ++count;
    }
}

// A warning names what the user wrote: a global's private copy by the global's name.
void UserNames(std::string& s) {
    for (size_t at; (at = s.find(kPrivateCopyPrefix)) != std::string::npos;)
        s.erase(at, kPrivateCopyPrefix.size());
}

}  // namespace

std::string ApplyEdits(const std::string& text, std::vector<Edit> edits) {
    // By start, an insertion before a replacement that starts where it does (`switch (` then a
    // matrix swizzle right after it), so neither is dropped.
    std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
        return a.begin != b.begin ? a.begin < b.begin : a.end < b.end;
    });
    std::string out;
    out.reserve(text.size() + edits.size() * 16);
    size_t at = 0;
    for (const Edit& e : edits) {
        if (e.begin < at)
            continue;
        out.append(text, at, e.begin - at);
        out += e.text;
        at = e.end;
    }
    out.append(text, at, std::string::npos);
    return out;
}

RewriteResult RewriteForGlslang(const std::string& preprocessed) {
    return RewriteForGlslang(preprocessed, Tokenize(preprocessed));
}

RewriteResult RewriteForGlslang(const std::string& preprocessed, std::vector<Token> tok) {
    RewriteResult r;
    std::vector<Edit> edits;
    // Token-local rewrites first, in one pass: non-overlapping by construction (a matrix swizzle
    // never ends in `.x`, a matrix type name is not an expression, a semantic is neither, and a
    // switch's insertions touch only its parentheses).
    OneVectorSwizzles(tok, edits, r.one_vector_swizzles);
    MatrixSwizzles(preprocessed, tok, edits, r.matrix_swizzles);
    InfinityLiterals(tok, edits, r.infinity_literals);
    MinPrecisionMatrices(tok, edits, r.min_precision_matrices);
    VposSemantics(tok, edits, r.vpos_semantics);
    SwitchSelectors(tok, edits, r.switch_selectors);
    std::string text = edits.empty() ? preprocessed : ApplyEdits(preprocessed, std::move(edits));
    // Then each step that reads declarations, on the text the one before produced.
    using Step = size_t (*)(const std::string&, const std::vector<Token>&, std::vector<Edit>&,
                            std::vector<RewriteWarning>&);
    static constexpr Step kSteps[] = {
        [](const std::string& t, const std::vector<Token>& k, std::vector<Edit>& e,
           std::vector<RewriteWarning>&) { return PrivateGlobals(t, k, e); },
        TruncatedArguments};
    size_t* const counts[] = {&r.private_globals, &r.truncated_arguments};
    bool stale = r.changed();
    for (size_t step = 0; step < 2; ++step) {
        if (stale)
            tok = Tokenize(text);
        std::vector<Edit> more;
        *counts[step] = kSteps[step](text, tok, more, r.warnings);
        stale = !more.empty();
        if (stale)
            text = ApplyEdits(text, std::move(more));
    }
    for (RewriteWarning& w : r.warnings) {
        UserNames(w.token);
        UserNames(w.message);
    }
    r.text = std::move(text);
    return r;
}

}  // namespace kiln::hlsl
