// Writes to a global, which fxc keeps private to the invocation (Unity 2018's UnityMetaPass does
// `unity_OneOverOutputBoost = saturate(unity_OneOverOutputBoost);`). In glslang a global is a
// uniform and the write is an error. A global that the text writes (assigns, increments, or
// passes to an `out`/`inout` parameter) gets a copy
//     static T kiln_private_NAME = NAME;
// right after its declaration (glslang runs a static's initializer at each entry point), and
// every use of NAME outside struct and cbuffer bodies is renamed to the copy. The uniform keeps
// its name, so reflection and the runtime see it as before. A local or parameter that shadows
// NAME is renamed with its uses, so the program means the same.
#include <map>
#include <regex>
#include <set>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "hlsl/rewrite_steps.h"

namespace kiln::hlsl {
namespace {

bool IsNumericType(std::string_view t) {
    return NumericShape(t) != 0;
}

struct Global {
    size_t name_token = 0;
    std::string type, array;  // "float4", "[4]" (or empty)
    size_t insert_at = 0;     // byte offset where its copy is declared
};

struct State {
    const std::string& text;
    const std::vector<Token>& tok;
    std::unordered_map<std::string_view, Global> globals;
    std::vector<std::pair<size_t, size_t>> declarations_only;  // token ranges not renamed
    std::map<std::string_view, std::set<size_t>> out_params;   // function -> out/inout indices
    std::unordered_set<size_t> declaration_tokens;
};

// Index of the statement end (`;` or `{` at depth 0) from `k`, or tok.size().
size_t StatementEnd(const std::vector<Token>& tok, size_t k) {
    for (; k < tok.size(); ++k) {
        const std::string_view t = tok[k].text;
        if (t == ";" || t == "{")
            return k;
        if (t == "(" || t == "[") {
            const size_t m = MatchForward(tok, k);
            if (m == SIZE_MAX)
                return tok.size();
            k = m;
        }
    }
    return tok.size();
}

// Variables declared by the statement [b, e), a top-level declaration or a cbuffer member;
// their copies go at byte `insert_at`.
void Declarations(State& s, size_t b, size_t e, size_t insert_at) {
    const std::vector<Token>& tok = s.tok;
    size_t k = b;
    while (k < e && (tok[k].text == "uniform" || tok[k].text == "row_major" ||
                     tok[k].text == "column_major" || tok[k].text == "nointerpolation"))
        ++k;
    if (k + 1 >= e || !IsNumericType(tok[k].text))
        return;  // static, const, groupshared, textures, samplers, structs: not uniforms it copies
    const std::string type(tok[k].text);
    for (++k; k < e && tok[k].ident;) {
        Global g;
        g.name_token = k;
        g.type = type;
        g.insert_at = insert_at;
        size_t n = k + 1;
        while (n < e && tok[n].text == "[") {
            const size_t m = MatchForward(tok, n);
            if (m == SIZE_MAX || m >= e)
                return;
            g.array += s.text.substr(tok[n].begin, tok[m].end - tok[n].begin);
            n = m + 1;
        }
        s.globals[tok[k].text] = g;
        s.declaration_tokens.insert(k);
        while (n < e && tok[n].text != ",") {  // semantic, register, initializer
            if (tok[n].text == "(" || tok[n].text == "[" || tok[n].text == "{")
                n = MatchForward(tok, n);
            if (n == SIZE_MAX)
                return;
            ++n;
        }
        k = n + 1;
    }
}

// Parameter indices declared out or inout in the list [open, close].
std::set<size_t> OutIndices(const std::vector<Token>& tok, size_t open, size_t close) {
    std::set<size_t> out;
    size_t index = 0;
    for (size_t k = open + 1; k < close; ++k) {
        const std::string_view t = tok[k].text;
        if (t == "(" || t == "[")
            k = MatchForward(tok, k);
        else if (t == ",")
            ++index;
        else if (t == "out" || t == "inout")
            out.insert(index);
        if (k == SIZE_MAX)
            break;
    }
    return out;
}

// The top level: globals, cbuffer members, struct bodies, function parameter qualifiers.
void ScanTopLevel(State& s) {
    const std::vector<Token>& tok = s.tok;
    for (size_t k = 0; k < tok.size();) {
        const size_t end = StatementEnd(tok, k);
        if (end >= tok.size())
            return;
        if (tok[end].text == ";") {
            if (end > k && tok[end - 1].text == ")") {  // a prototype
                const size_t open = MatchBack(tok, end - 1);
                if (open != SIZE_MAX && open > 0 && tok[open - 1].ident)
                    s.out_params[tok[open - 1].text].merge(OutIndices(tok, open, end - 1));
            } else {
                Declarations(s, k, end, tok[end].end);
            }
            k = end + 1;
            continue;
        }
        const size_t close = MatchForward(tok, end);
        if (close == SIZE_MAX)
            return;
        const std::string_view first = tok[k].text;
        if (first == "cbuffer" || first == "tbuffer") {
            size_t after = close + 1 < tok.size() && tok[close + 1].text == ";" ? close + 1 : close;
            for (size_t m = end + 1; m < close;) {
                const size_t e = StatementEnd(tok, m);
                if (e >= close)
                    break;
                Declarations(s, m, e, tok[after].end);
                m = e + 1;
            }
            s.declarations_only.push_back({end, close});
        } else if (first == "struct" || (k + 1 < end && tok[k + 1].text == "struct")) {
            s.declarations_only.push_back({end, close});
        } else {
            // A function: `T name(params) [: semantic] {`.
            for (size_t m = end; m-- > k;) {
                if (tok[m].text == ")") {
                    const size_t open = MatchBack(tok, m);
                    if (open != SIZE_MAX && open > 0 && tok[open - 1].ident)
                        s.out_params[tok[open - 1].text].merge(OutIndices(tok, open, m));
                    break;
                }
            }
        }
        k = close + 1;
        while (k < tok.size() && tok[k].text == ";")
            ++k;
    }
}

// True when token k (a use of a global) is written: assigned, incremented, or passed to an out
// or inout parameter.
bool IsWrite(const State& s, size_t k) {
    const std::vector<Token>& tok = s.tok;
    if (k > 0 && (tok[k - 1].text == "++" || tok[k - 1].text == "--"))
        return true;
    size_t n = k + 1;
    while (n < tok.size()) {
        if (tok[n].text == "." && n + 1 < tok.size() && tok[n + 1].ident) {
            n += 2;
        } else if (tok[n].text == "[") {
            n = MatchForward(tok, n);
            if (n == SIZE_MAX)
                return false;
            ++n;
        } else {
            break;
        }
    }
    if (n >= tok.size())
        return false;
    if (IsAssignment(tok[n].text) || tok[n].text == "++" || tok[n].text == "--")
        return true;
    if ((tok[n].text != "," && tok[n].text != ")") ||
        (tok[k - 1].text != "(" && tok[k - 1].text != ","))
        return false;
    // A whole argument: find the call and the argument's index.
    size_t index = 0;
    for (size_t m = k; m-- > 0;) {
        const std::string_view t = tok[m].text;
        if (t == ")" || t == "]") {
            m = MatchBack(tok, m);
            if (m == SIZE_MAX)
                return false;
        } else if (t == ",") {
            ++index;
        } else if (t == "(" && m > 0 && tok[m - 1].ident) {
            static const std::map<std::string_view, std::set<size_t>> kIntrinsics = {
                {"sincos", {1, 2}}, {"modf", {1}}, {"frexp", {1}}};
            const std::string_view f = tok[m - 1].text;
            if (const auto it = s.out_params.find(f); it != s.out_params.end())
                return it->second.count(index) > 0;
            const auto it = kIntrinsics.find(f);
            return it != kIntrinsics.end() && it->second.count(index) > 0;
        } else if (t == "(" || t == "{" || t == ";" || t == "}") {
            return false;
        }
    }
    return false;
}

}  // namespace

size_t PrivateGlobals(const std::string& text,
                      const std::vector<Token>& tok,
                      std::vector<Edit>& edits) {
    State s{text, tok, {}, {}, {}, {}};
    ScanTopLevel(s);
    if (s.globals.empty())
        return 0;
    // The tokens that may be renamed: not a declaration of a global, not a member access, not in
    // a struct or cbuffer body (a mask, so the passes below stay linear in the text).
    std::vector<bool> use(tok.size(), false);
    for (size_t k = 1; k < tok.size(); ++k) {
        use[k] = tok[k].ident && s.globals.count(tok[k].text) && !s.declaration_tokens.count(k) &&
                 tok[k - 1].text != "." && tok[k - 1].text != "->";
    }
    for (const auto& [b, e] : s.declarations_only) {
        for (size_t k = b + 1; k < e && k < tok.size(); ++k)
            use[k] = false;
    }
    std::set<std::string_view> written;
    for (size_t k = 1; k < tok.size(); ++k) {
        if (use[k] && !written.count(tok[k].text) && IsWrite(s, k))
            written.insert(tok[k].text);
    }
    if (written.empty())
        return 0;
    for (std::string_view name : written) {
        const Global& g = s.globals.at(name);
        edits.push_back({g.insert_at, g.insert_at,
                         " static " + g.type + " " + std::string(kPrivateCopyPrefix) +
                             std::string(name) + g.array + " = " + std::string(name) + ";"});
    }
    for (size_t k = 1; k < tok.size(); ++k) {
        if (use[k] && written.count(tok[k].text))
            edits.push_back({tok[k].begin, tok[k].end,
                             std::string(kPrivateCopyPrefix) + std::string(tok[k].text)});
    }
    return written.size();
}

}  // namespace kiln::hlsl
