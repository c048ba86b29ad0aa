// A vector argument to a scalar parameter: fxc passes the first component with warning X3206
// ("implicit truncation of vector type"); glslang finds no matching overload. The rule Kiln
// applies, so that it never picks between overloads: the call's name has exactly one function in
// the text whose parameter count fits the call (default arguments included), the parameter is a
// scalar `in` parameter, and the argument is known to be a vector without type checking: a name
// whose nearest declaration before the call has a vector type, a multi-component swizzle
// (`v.xy`), or a vector constructor (`float3(...)`). The argument becomes `(argument).x`. Other
// shapes keep glslang's error, whose note says how to pass the component.
#include <algorithm>
#include <cctype>
#include <optional>
#include <regex>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "hlsl/rewrite_steps.h"

namespace kiln::hlsl {
namespace {

struct Param {
    bool scalar_in = false;
    bool has_default = false;
    std::string_view name;
};

struct Candidate {
    std::vector<Param> params;
    std::string_view signature;  // parameter tokens, to count a prototype and its definition once
    bool any_scalar_in = false;  // a call can need the rewrite only then
};

bool IsScalarType(std::string_view t) {
    return NumericShape(t) == 1;
}

// The component count of a vector type name (float3 -> 3), or 0.
int VectorSize(std::string_view t) {
    const int shape = NumericShape(t);
    return shape >= 2 && shape <= 4 ? shape : 0;
}

bool IsQualifier(std::string_view t) {
    static const std::unordered_set<std::string_view> kWords = {
        "in",      "out",       "inout",       "uniform",         "const",
        "precise", "linear",    "centroid",    "nointerpolation", "noperspective",
        "sample",  "row_major", "column_major"};
    return kWords.count(t) > 0;
}

// Depth-0 comma-separated ranges of tokens between open and close.
std::vector<std::pair<size_t, size_t>> Split(const std::vector<Token>& tok,
                                             size_t open,
                                             size_t close) {
    std::vector<std::pair<size_t, size_t>> out;
    size_t b = open + 1;
    for (size_t k = open + 1; k < close; ++k) {
        const std::string_view t = tok[k].text;
        if (t == "(" || t == "[" || t == "{") {
            k = MatchForward(tok, k);
            if (k == SIZE_MAX || k > close)
                return {};
        } else if (t == ",") {
            out.push_back({b, k});
            b = k + 1;
        }
    }
    if (b < close)
        out.push_back({b, close});
    return out;
}

Candidate ParseCandidate(const std::string& text,
                         const std::vector<Token>& tok,
                         size_t open,
                         size_t close) {
    Candidate c;
    c.signature = std::string_view(text).substr(tok[open].begin, tok[close].end - tok[open].begin);
    for (const auto& [b, e] : Split(tok, open, close)) {
        Param p;
        bool in = true;
        size_t k = b;
        for (; k < e && IsQualifier(tok[k].text); ++k) {
            if (tok[k].text == "out" || tok[k].text == "inout")
                in = false;
        }
        p.scalar_in = in && k < e && IsScalarType(tok[k].text);
        if (k + 1 < e && tok[k + 1].ident)
            p.name = tok[k + 1].text;
        for (size_t m = k; m < e; ++m)
            p.has_default = p.has_default || tok[m].text == "=";
        c.any_scalar_in = c.any_scalar_in || p.scalar_in;
        c.params.push_back(p);
    }
    return c;
}

// Functions declared or defined at the top level, by name.
std::unordered_map<std::string_view, std::vector<Candidate>> Functions(
    const std::string& text,
    const std::vector<Token>& tok) {
    std::unordered_map<std::string_view, std::vector<Candidate>> out;
    int depth = 0;
    for (size_t k = 1; k + 1 < tok.size(); ++k) {
        const std::string_view t = tok[k].text;
        if (t == "{")
            ++depth;
        else if (t == "}")
            --depth;
        if (depth != 0 || !tok[k].ident || tok[k + 1].text != "(" || !tok[k - 1].ident ||
            IsStatementWord(tok[k - 1].text))
            continue;
        const size_t close = MatchForward(tok, k + 1);
        if (close == SIZE_MAX)
            break;
        Candidate c = ParseCandidate(text, tok, k + 1, close);
        std::vector<Candidate>& list = out[t];
        bool seen = false;
        for (const Candidate& other : list)
            seen = seen || other.signature == c.signature;
        if (!seen)
            list.push_back(std::move(c));
        k = close;
    }
    return out;
}

// Every declaration `Type name` followed by ; , = : ) or [ (a local, parameter, global or member),
// by name, in text order: the nearest one before a use is its type, found by binary search so
// the rewrite stays n log n on any input.
using Declarations =
    std::unordered_map<std::string_view, std::vector<std::pair<size_t, std::string_view>>>;

Declarations AllDeclarations(const std::vector<Token>& tok) {
    Declarations out;
    for (size_t m = 1; m + 1 < tok.size(); ++m) {
        const std::string_view next = tok[m + 1].text;
        if (!tok[m].ident || (next != ";" && next != "," && next != "=" && next != ":" &&
                              next != ")" && next != "["))
            continue;
        if (tok[m - 1].ident && !IsStatementWord(tok[m - 1].text))
            out[tok[m].text].push_back({m, tok[m - 1].text});
    }
    return out;
}

// The type name of the nearest declaration of `name` before token `before`, or "".
std::string_view DeclaredType(const Declarations& decls, size_t before, std::string_view name) {
    const auto it = decls.find(name);
    if (it == decls.end())
        return {};
    const auto& list = it->second;
    auto after = std::lower_bound(list.begin(), list.end(), before,
                                  [](const auto& d, size_t k) { return d.first < k; });
    if (after == list.begin())
        return {};
    return std::prev(after)->second;
}

// The vector type of argument [b, e) when it is known without type checking, or "".
std::string KnownVector(const std::vector<Token>& tok,
                        const Declarations& decls,
                        size_t b,
                        size_t e) {
    if (e == b + 1 && tok[b].ident) {
        const std::string_view type = DeclaredType(decls, b, tok[b].text);
        return VectorSize(type) ? std::string(type) : "";
    }
    static const std::regex kSwizzle("[xyzw]{2,4}|[rgba]{2,4}");
    if (e >= b + 3 && tok[e - 2].text == "." && tok[e - 1].ident &&
        std::regex_match(tok[e - 1].text.begin(), tok[e - 1].text.end(), kSwizzle)) {
        return "float" + std::to_string(tok[e - 1].text.size());  // the component count
    }
    if (e >= b + 3 && VectorSize(tok[b].text) && tok[b + 1].text == "(" &&
        MatchForward(tok, b + 1) == e - 1)
        return std::string(tok[b].text);
    return "";
}

}  // namespace

size_t TruncatedArguments(const std::string& text,
                          const std::vector<Token>& tok,
                          std::vector<Edit>& edits,
                          std::vector<RewriteWarning>& warnings) {
    const auto functions = Functions(text, tok);
    if (functions.empty())
        return 0;
    std::optional<Declarations> decls;  // built on the first argument that needs it
    size_t count = 0;
    for (size_t k = 1; k + 1 < tok.size(); ++k) {
        if (!tok[k].ident || tok[k + 1].text != "(" ||
            (tok[k - 1].ident && !IsStatementWord(tok[k - 1].text)) || tok[k - 1].text == ".")
            continue;
        const auto it = functions.find(tok[k].text);
        if (it == functions.end())
            continue;
        const size_t close = MatchForward(tok, k + 1);
        if (close == SIZE_MAX)
            break;
        if (std::none_of(it->second.begin(), it->second.end(),
                         [](const Candidate& c) { return c.any_scalar_in; }))
            continue;  // no scalar parameter to pass a vector to
        const auto args = Split(tok, k + 1, close);
        const Candidate* only = nullptr;
        size_t fitting = 0;
        for (const Candidate& c : it->second) {
            size_t required = 0;
            for (const Param& p : c.params)
                required += p.has_default ? 0 : 1;
            if (args.size() >= required && args.size() <= c.params.size()) {
                only = &c;
                ++fitting;
            }
        }
        if (fitting != 1)
            continue;
        for (size_t a = 0; a < args.size(); ++a) {
            const auto [b, e] = args[a];
            if (!only->params[a].scalar_in)
                continue;
            if (!decls)
                decls = AllDeclarations(tok);
            const std::string vector = KnownVector(tok, *decls, b, e);
            if (vector.empty())
                continue;
            edits.push_back({tok[b].begin, tok[b].begin, "("});
            edits.push_back({tok[e - 1].end, tok[e - 1].end, ").x"});
            RewriteWarning w = PlaceOf(text, tok[b].begin);
            // The argument as written (the preprocessor spaced its tokens), for the message
            // and for finding its column on the source line.
            for (size_t m = b; m < e; ++m) {
                const bool word =
                    tok[m].ident || std::isdigit(static_cast<unsigned char>(tok[m].text[0]));
                if (word && !w.token.empty() &&
                    std::isalnum(static_cast<unsigned char>(w.token.back())))
                    w.token += ' ';
                w.token += tok[m].text;
            }
            w.message = "implicit truncation of vector type: '" + w.token + "' is a '" + vector +
                        "' passed to scalar parameter '" + std::string(only->params[a].name) +
                        "' of '" + std::string(tok[k].text) +
                        "', so its first component is used, as Unity's compiler does (X3206)";
            warnings.push_back(std::move(w));
            ++count;
        }
    }
    return count;
}

}  // namespace kiln::hlsl
