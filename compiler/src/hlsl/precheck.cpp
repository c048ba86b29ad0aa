#include "hlsl/precheck.h"

#include <cctype>
#include <limits>
#include <map>
#include <string>
#include <string_view>

#include "hlsl/identifier.h"

namespace kiln::hlsl {
namespace {

using shaderlab::ProgramBlock;

struct Token {
    enum class Kind { kIdent, kNumber, kPunct } kind = Kind::kPunct;
    uint32_t begin = 0, end = 0;  // offsets in the block text
    int directive = -1;           // index into Scan::directives, -1 outside a directive line
};

struct Directive {
    std::string_view name;       // "define", "if", ...
    uint32_t begin = 0;          // offset of the '#'
    size_t first = 0, last = 0;  // its tokens (after the name), [first, last)
};

struct Scan {
    std::vector<Token> tokens;
    std::vector<Directive> directives;
};

bool IsSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// Skips a comment or literal starting at i (returns i unchanged if there is none).
size_t SkipTrivia(std::string_view s, size_t i) {
    if (s.compare(i, 2, "//") == 0) {
        while (i < s.size() && s[i] != '\n')
            ++i;
        return i;
    }
    if (s.compare(i, 2, "/*") == 0) {
        const size_t end = s.find("*/", i + 2);
        return end == std::string_view::npos ? s.size() : end + 2;
    }
    if (s[i] == '"' || s[i] == '\'') {
        const char q = s[i++];
        while (i < s.size() && s[i] != q && s[i] != '\n')
            i += s[i] == '\\' ? 2 : 1;
        return std::min(s.size(), i + 1);
    }
    return i;
}

size_t PunctLength(std::string_view s, size_t i) {
    static constexpr std::string_view kMulti[] = {
        "<<=", ">>=", "==", "!=", "<=", ">=", "+=", "-=", "*=", "/=", "%=",
        "&=",  "|=",  "^=", "++", "--", "&&", "||", "<<", ">>", "##"};
    for (std::string_view m : kMulti) {
        if (s.compare(i, m.size(), m) == 0)
            return m.size();
    }
    return 1;
}

Scan Tokenize(std::string_view s) {
    Scan out;
    bool line_start = true;
    int directive = -1;
    for (size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (c == '\n') {
            line_start = true;
            if (directive >= 0)
                out.directives[size_t(directive)].last = out.tokens.size();
            directive = -1;
            ++i;
            continue;
        }
        if (c == '\\' && i + 1 < s.size() && (s[i + 1] == '\n' || s[i + 1] == '\r')) {
            i += s[i + 1] == '\r' && i + 2 < s.size() && s[i + 2] == '\n' ? 3 : 2;
            continue;  // a continued line: the directive goes on
        }
        if (IsSpace(c)) {
            ++i;
            continue;
        }
        if (const size_t j = SkipTrivia(s, i); j != i) {
            i = j;
            continue;
        }
        if (line_start && c == '#') {
            size_t j = i + 1;
            while (j < s.size() && IsSpace(s[j]))
                ++j;
            size_t k = j;
            while (k < s.size() && IdentChar(s[k]))
                ++k;
            directive = static_cast<int>(out.directives.size());
            out.directives.push_back({s.substr(j, k - j), uint32_t(i), out.tokens.size(), 0});
            out.directives.back().first = out.tokens.size();
            line_start = false;
            i = k;
            continue;
        }
        line_start = false;
        Token t;
        t.begin = uint32_t(i);
        t.directive = directive;
        if (IdentStart(c)) {
            t.kind = Token::Kind::kIdent;
            while (i < s.size() && IdentChar(s[i]))
                ++i;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            t.kind = Token::Kind::kNumber;
            while (i < s.size() && (IdentChar(s[i]) || s[i] == '.'))
                ++i;
        } else {
            i += PunctLength(s, i);
        }
        t.end = uint32_t(i);
        out.tokens.push_back(t);
    }
    if (directive >= 0)
        out.directives[size_t(directive)].last = out.tokens.size();
    return out;
}

bool IsBinaryOperator(std::string_view t) {
    static constexpr std::string_view kOps[] = {"+",  "-",  "*",  "/",  "%",  "&", "|",
                                                "^",  "&&", "||", "<<", ">>", "<", ">",
                                                "<=", ">=", "==", "!=", "?",  ":"};
    for (std::string_view op : kOps) {
        if (t == op)
            return true;
    }
    return false;
}

uint64_t SaturatingAdd(uint64_t a, uint64_t b) {
    constexpr uint64_t kMax = std::numeric_limits<uint64_t>::max() / 2;
    return a >= kMax || b >= kMax - a ? kMax : a + b;
}

struct Macro {
    std::string name;
    uint32_t file_offset = 0;       // of the name in the #define
    uint64_t own_tokens = 0;        // body tokens that are not identifiers
    std::vector<std::string> refs;  // body identifiers that are not parameters
};

// Estimated tokens of `root` fully expanded under `macros` (by name): every identifier of a body
// that names a macro is replaced by that macro's expansion; a macro met again inside its own
// expansion stays one token, as the C preprocessor leaves it. Iterative, memoized.
uint64_t ExpandedSize(const std::vector<Macro>& all,
                      const std::map<std::string, size_t, std::less<>>& macros,
                      size_t root,
                      std::map<size_t, uint64_t>& memo) {
    if (auto it = memo.find(root); it != memo.end())
        return it->second;
    struct Frame {
        size_t macro, next = 0;
        uint64_t sum;
    };
    std::vector<Frame> stack{{root, 0, all[root].own_tokens}};
    std::set<size_t> open{root};
    while (!stack.empty()) {
        Frame& f = stack.back();
        if (f.next < all[f.macro].refs.size()) {
            const std::string& ref = all[f.macro].refs[f.next++];
            auto m = macros.find(ref);
            if (m == macros.end() || open.count(m->second)) {
                f.sum = SaturatingAdd(f.sum, 1);
            } else if (auto done = memo.find(m->second); done != memo.end()) {
                f.sum = SaturatingAdd(f.sum, done->second);
            } else {
                open.insert(m->second);
                stack.push_back({m->second, 0, all[m->second].own_tokens});
            }
            continue;
        }
        const Frame finished = f;
        memo[finished.macro] = finished.sum;
        open.erase(finished.macro);
        stack.pop_back();
        if (!stack.empty())
            stack.back().sum = SaturatingAdd(stack.back().sum, finished.sum);
    }
    return memo[root];
}

}  // namespace

namespace {

struct BlockState {
    const SourceFile& file;
    const ProgramBlock& block;
    std::string_view text;
    Scan scan;

    SourceRange RangeOf(uint32_t begin, uint32_t end) const {
        const uint32_t base = block.body_begin.offset;
        return {file.LocAt(base + begin), file.LocAt(base + end)};
    }
    std::string_view TextOf(const Token& t) const { return text.substr(t.begin, t.end - t.begin); }
};

void CheckNesting(const BlockState& b, const PrecheckLimits& limits, DiagnosticList& diags) {
    size_t depth = 0, conditions = 0, operators = 0;
    size_t expression_start = 0;
    int directive = -2;
    size_t directive_depth = 0;
    bool nesting_reported = false, conditions_reported = false, operators_reported = false;
    auto report = [&](bool& once, DiagCode code, uint32_t begin, uint32_t end, std::string msg) {
        if (!once)
            diags.Error(code, b.file.path(), b.RangeOf(begin, end), std::move(msg));
        once = true;
    };
    size_t next_directive = 0;
    for (size_t i = 0; i < b.scan.tokens.size(); ++i) {
        const Token& t = b.scan.tokens[i];
        // Directives are counted when their first token (or, if they have none, the next token
        // after them) is reached.
        while (next_directive < b.scan.directives.size() &&
               b.scan.directives[next_directive].first <= i) {
            const Directive& d = b.scan.directives[next_directive++];
            if (d.name == "if" || d.name == "ifdef" || d.name == "ifndef") {
                if (++conditions > limits.max_nesting) {
                    report(conditions_reported, DiagCode::kProgramNestingTooDeep, d.begin,
                           d.begin + 1,
                           "#if directives nested more than " + std::to_string(limits.max_nesting) +
                               " deep");
                }
            } else if (d.name == "endif" && conditions > 0) {
                --conditions;
            }
        }
        size_t& level = t.directive >= 0 ? directive_depth : depth;
        if (t.directive != directive) {
            directive = t.directive;
            directive_depth = 0;
        }
        const std::string_view s = b.TextOf(t);
        if (t.kind == Token::Kind::kPunct && (s == "(" || s == "[" || s == "{")) {
            if (++level > limits.max_nesting) {
                report(nesting_reported, DiagCode::kProgramNestingTooDeep, t.begin, t.end,
                       "brackets nested more than " + std::to_string(limits.max_nesting) +
                           " deep (glslang recurses once per level)");
            }
        } else if (t.kind == Token::Kind::kPunct && (s == ")" || s == "]" || s == "}")) {
            level -= level > 0 ? 1 : 0;
        }
        if (t.directive >= 0)
            continue;
        if (s == ";" || s == "{" || s == "}" || s == ",") {
            operators = 0;
            expression_start = i + 1;
        } else if (t.kind == Token::Kind::kPunct && IsBinaryOperator(s) &&
                   ++operators > limits.max_operators) {
            const Token& first = b.scan.tokens[std::min(expression_start, i)];
            report(operators_reported, DiagCode::kExpressionTooLong, first.begin, first.end,
                   "an expression with more than " + std::to_string(limits.max_operators) +
                       " operators; split it into several statements");
        }
    }
}

}  // namespace

void Prechecker::CheckPass(const std::vector<const ProgramBlock*>& blocks) {
    std::vector<Macro> all;
    std::map<std::string, size_t, std::less<>> current;  // name -> index into `all`
    std::map<size_t, uint64_t> memo;
    for (const ProgramBlock* block : blocks) {
        BlockState b{file_, *block, block->text, Tokenize(block->text)};
        if (checked_.insert(block).second)
            CheckNesting(b, limits_, diags_);
        size_t next_directive = 0;
        for (size_t i = 0; i <= b.scan.tokens.size(); ++i) {
            while (next_directive < b.scan.directives.size() &&
                   b.scan.directives[next_directive].first <= i) {
                const Directive& d = b.scan.directives[next_directive++];
                if ((d.name != "define" && d.name != "undef") || d.first == d.last ||
                    b.scan.tokens[d.first].kind != Token::Kind::kIdent)
                    continue;
                const Token& name = b.scan.tokens[d.first];
                memo.clear();
                if (d.name == "undef") {
                    current.erase(std::string(b.TextOf(name)));
                    continue;
                }
                Macro m;
                m.name = std::string(b.TextOf(name));
                m.file_offset = block->body_begin.offset + name.begin;
                size_t k = d.first + 1;
                std::set<std::string_view> params;
                if (k < d.last && name.end < b.text.size() && b.text[name.end] == '(') {
                    for (++k; k < d.last && b.TextOf(b.scan.tokens[k]) != ")"; ++k) {
                        if (b.scan.tokens[k].kind == Token::Kind::kIdent)
                            params.insert(b.TextOf(b.scan.tokens[k]));
                    }
                    ++k;
                }
                for (; k < d.last; ++k) {
                    const Token& t = b.scan.tokens[k];
                    if (t.kind == Token::Kind::kIdent && !params.count(b.TextOf(t)))
                        m.refs.emplace_back(b.TextOf(t));
                    else
                        ++m.own_tokens;
                }
                current[m.name] = all.size();
                all.push_back(std::move(m));
            }
            if (i == b.scan.tokens.size())
                break;
            const Token& t = b.scan.tokens[i];
            // Expansions happen in program text and in #if/#elif conditions only.
            const std::string_view in =
                t.directive >= 0 ? b.scan.directives[size_t(t.directive)].name : "";
            if (t.kind != Token::Kind::kIdent || (t.directive >= 0 && in != "if" && in != "elif"))
                continue;
            auto m = current.find(b.TextOf(t));
            if (m == current.end())
                continue;
            const uint64_t size = ExpandedSize(all, current, m->second, memo);
            const uint32_t at = block->body_begin.offset + t.begin;
            if (size <= limits_.max_macro_tokens || !reported_.insert(at).second)
                continue;
            const Macro& macro = all[m->second];
            Diagnostic& d = diags_.Error(
                DiagCode::kMacroExpansionTooLarge, file_.path(), b.RangeOf(t.begin, t.end),
                "macro '" + macro.name + "' expands to about " + std::to_string(size) +
                    " tokens, more than the budget of " + std::to_string(limits_.max_macro_tokens) +
                    " for one use");
            const SourceLoc def = file_.LocAt(macro.file_offset);
            d.notes.push_back({file_.path(),
                               {def, file_.LocAt(macro.file_offset + uint32_t(macro.name.size()))},
                               "'" + macro.name + "' is defined here"});
        }
    }
}

}  // namespace kiln::hlsl
