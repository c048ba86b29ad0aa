#include "hlsl/pp_macros.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <xxhash.h>

#include "hlsl/identifier.h"

namespace kiln::hlsl {
namespace {

constexpr int kMaxExpansionDepth = 32;

bool IsSpace(char c) {
    return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

// Names glslang's preprocessor may define itself (its preamble: GL_* extensions, VULKAN,
// GL_SPIRV; __LINE__ and the like), which Kiln does not track.
bool GlslangOwns(std::string_view name) {
    return name.rfind("GL_", 0) == 0 || name.rfind("__", 0) == 0 || name == "VULKAN";
}

// kUnknown: a value the plan does not know (a macro whose definition it does not know).
enum class Tok { kIdent, kInt, kUnknown, kOp, kBad };

struct Token {
    Tok kind;
    std::string_view text;
    int64_t value = 0;
};

// A plain decimal, octal or hex int glslang reads as an int; anything else is kBad.
Token Number(std::string_view s) {
    Token t{Tok::kBad, s};
    int base = 10;
    size_t i = 0;
    if (s.size() > 1 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        base = 16;
        i = 2;
        if (s.size() == 2)
            return t;
    } else if (s.size() > 1 && s[0] == '0') {
        base = 8;
        i = 1;
    }
    int64_t v = 0;
    for (; i < s.size(); ++i) {
        const char c = s[i];
        int d = -1;
        if (c >= '0' && c <= '9')
            d = c - '0';
        else if (c >= 'a' && c <= 'f')
            d = c - 'a' + 10;
        else if (c >= 'A' && c <= 'F')
            d = c - 'A' + 10;
        if (d < 0 || d >= base)
            return t;
        v = v * base + d;
        if (v > INT32_MAX)
            return t;
    }
    t.kind = Tok::kInt;
    t.value = v;
    return t;
}

// Splits `s` into tokens; false when it holds a literal or character the evaluation does not take.
bool Tokenize(std::string_view s, std::vector<Token>& out) {
    static constexpr std::string_view kTwo[] = {
        "||", "&&", "==", "!=", ">=", "<=", "<<", ">>", "##"};
    size_t i = 0;
    while (i < s.size()) {
        const char c = s[i];
        if (IsSpace(c)) {
            ++i;
        } else if (IdentStart(c)) {
            size_t j = i;
            while (j < s.size() && IdentChar(s[j]))
                ++j;
            out.push_back({Tok::kIdent, s.substr(i, j - i)});
            i = j;
        } else if (c >= '0' && c <= '9') {
            size_t j = i;
            while (j < s.size() && (IdentChar(s[j]) || s[j] == '.'))
                ++j;
            out.push_back(Number(s.substr(i, j - i)));
            i = j;
        } else {
            size_t n = 1;
            for (std::string_view two : kTwo) {
                if (s.substr(i, 2) == two)
                    n = 2;
            }
            out.push_back({Tok::kOp, s.substr(i, n)});
            i += n;
        }
    }
    for (const Token& t : out) {
        if (t.kind == Tok::kBad)
            return false;
    }
    return true;
}

// Reads the identifier at the start of `rest` (after blanks) into `name`; returns what follows.
std::optional<std::string_view> Name(std::string_view rest, std::string_view& name) {
    size_t i = 0;
    while (i < rest.size() && IsSpace(rest[i]))
        ++i;
    if (i == rest.size() || !IdentStart(rest[i]))
        return std::nullopt;
    size_t j = i;
    while (j < rest.size() && IdentChar(rest[j]))
        ++j;
    name = rest.substr(i, j - i);
    return rest.substr(j);
}

bool Blank(std::string_view s) {
    for (char c : s) {
        if (!IsSpace(c))
            return false;
    }
    return true;
}

// A value, or not known.
struct Val {
    int64_t v = 0;
    bool known = true;
};

// Recursive descent over expanded tokens, with glslang's operators and precedence. A value not
// known makes the result not known, but where && and || decide without it.
struct Parser {
    const std::vector<Token>& t;
    size_t i = 0;
    bool ok = true;

    bool Is(std::string_view op) const {
        return i < t.size() && t[i].kind == Tok::kOp && t[i].text == op;
    }
    static bool Fits(int64_t v) { return v >= INT32_MIN && v <= INT32_MAX; }

    Val Unary() {
        if (i >= t.size()) {
            ok = false;
            return {};
        }
        if (t[i].kind == Tok::kInt)
            return {t[i++].value, true};
        if (t[i].kind == Tok::kUnknown) {
            ++i;
            return {0, false};
        }
        for (std::string_view op : {"+", "-", "~", "!"}) {
            if (Is(op)) {
                ++i;
                Val v = Unary();
                if (op == "-")
                    v.v = -v.v;
                else if (op == "~")
                    v.v = ~v.v;
                else if (op == "!")
                    v.v = v.v == 0;
                return v;
            }
        }
        if (Is("(")) {
            ++i;
            const Val v = Binary(1);
            if (!Is(")"))
                ok = false;
            ++i;
            return v;
        }
        ok = false;
        return {};
    }

    static int Precedence(std::string_view op) {
        static constexpr std::pair<std::string_view, int> kTable[] = {
            {"||", 1}, {"&&", 2}, {"|", 3}, {"^", 4},  {"&", 5},  {"==", 6},
            {"!=", 6}, {"<", 7},  {">", 7}, {"<=", 7}, {">=", 7}, {"<<", 8},
            {">>", 8}, {"+", 9},  {"-", 9}, {"*", 10}, {"/", 10}, {"%", 10}};
        for (const auto& [name, p] : kTable) {
            if (name == op)
                return p;
        }
        return 0;
    }

    int64_t Known(std::string_view op, int64_t a, int64_t b) {
        if ((op == "/" || op == "%") && b == 0) {
            ok = false;  // glslang reports a division by zero
            return 0;
        }
        if ((op == "<<" || op == ">>") && (b < 0 || b > 31 || a < 0)) {
            ok = false;
            return 0;
        }
        int64_t r = 0;
        if (op == "||")
            r = (a != 0) || (b != 0);
        else if (op == "&&")
            r = (a != 0) && (b != 0);
        else if (op == "|")
            r = a | b;
        else if (op == "^")
            r = a ^ b;
        else if (op == "&")
            r = a & b;
        else if (op == "==")
            r = a == b;
        else if (op == "!=")
            r = a != b;
        else if (op == "<")
            r = a < b;
        else if (op == ">")
            r = a > b;
        else if (op == "<=")
            r = a <= b;
        else if (op == ">=")
            r = a >= b;
        else if (op == "<<")
            r = a << b;
        else if (op == ">>")
            r = a >> b;
        else if (op == "+")
            r = a + b;
        else if (op == "-")
            r = a - b;
        else if (op == "*")
            r = a * b;
        else if (op == "/")
            r = a / b;
        else if (op == "%")
            r = a % b;
        if (!Fits(r))
            ok = false;  // glslang wraps 32-bit ints: not modelled
        return r;
    }

    Val Apply(std::string_view op, Val a, Val b) {
        if (a.known && b.known)
            return {Known(op, a.v, b.v), true};
        if (op == "&&" && ((a.known && a.v == 0) || (b.known && b.v == 0)))
            return {0, true};
        if (op == "||" && ((a.known && a.v != 0) || (b.known && b.v != 0)))
            return {1, true};
        if (b.known && (op == "/" || op == "%") && b.v == 0)
            ok = false;
        return {0, false};
    }

    Val Binary(int min_precedence) {
        Val left = Unary();
        while (ok && i < t.size() && t[i].kind == Tok::kOp) {
            const int p = Precedence(t[i].text);
            if (p == 0 || p < min_precedence)
                break;
            const std::string_view op = t[i++].text;
            const Val right = Binary(p + 1);
            left = Apply(op, left, right);
        }
        if (left.known && !Fits(left.v))
            ok = false;
        return left;
    }
};

}  // namespace

bool GlslangMayDefine(std::string_view name) {
    return GlslangOwns(name);
}

std::string_view DirectiveMacroName(std::string_view rest) {
    std::string_view name;
    return Name(rest, name) ? name : std::string_view();
}

bool PpMacros::Define(std::string_view rest) {
    std::string_view name;
    const std::optional<std::string_view> after = Name(rest, name);
    if (!after || name == "defined" || name.rfind("GL_", 0) == 0)
        return false;
    Macro m;
    std::string_view body = *after;
    if (!body.empty() && body[0] == '(') {
        m.function_like = true;
        const size_t close = body.find(')');
        if (close == std::string_view::npos)
            return false;
        m.params = std::string(body.substr(0, close + 1));
        body.remove_prefix(close + 1);
    }
    while (!body.empty() && IsSpace(body.front()))
        body.remove_prefix(1);
    while (!body.empty() && IsSpace(body.back()))
        body.remove_suffix(1);
    m.body = std::string(body);
    m.name_hash = WordHash(name);
    unknown_.erase(std::string(name));
    defined_[std::string(name)] = std::move(m);
    Wrote(name);
    return true;
}

bool PpMacros::Undef(std::string_view rest) {
    std::string_view name;
    const std::optional<std::string_view> after = Name(rest, name);
    if (!after || !Blank(*after) || name == "defined" || name.rfind("GL_", 0) == 0)
        return false;
    unknown_.erase(std::string(name));
    defined_.erase(std::string(name));
    Wrote(name);
    return true;
}

void PpMacros::Forget(std::string_view rest) {
    std::string_view name;
    if (Name(rest, name)) {
        defined_.erase(std::string(name));
        unknown_.insert(std::string(name));
        Wrote(name);
    }
}

MacroState PpMacros::Lookup(std::string_view name) const {
    if (GlslangOwns(name))
        return MacroState::kUnknown;
    const std::string key(name);
    if (!logs_.empty()) {
        MacroLog& log = *logs_.back();
        if (log.seen.insert(key).second) {
            log.reads.emplace_back(key, Value(key));
            return log.reads.back().second.state;
        }
    }
    if (unknown_.count(key) || pinned_.count(key))
        return MacroState::kUnknown;
    return defined_.count(key) ? MacroState::kDefined : MacroState::kUndefined;
}

MacroValue PpMacros::Value(const std::string& name) const {
    if (pinned_.count(name))
        return {MacroState::kUnknown, false, {}, {}};
    return Held(name);
}

MacroValue PpMacros::Held(const std::string& name) const {
    if (unknown_.count(name))
        return {MacroState::kUnknown, false, {}, {}};
    const auto it = defined_.find(name);
    if (it == defined_.end())
        return {};
    return {MacroState::kDefined, it->second.function_like, it->second.body, it->second.params};
}

void PpMacros::Set(const std::string& name, const MacroValue& value) {
    if (value.state == MacroState::kDefined) {
        unknown_.erase(name);
        Macro& m = defined_[name];
        m.function_like = value.function_like;
        m.body = value.body;
        m.params = value.params;
        m.name_hash = WordHash(name);
    } else {
        defined_.erase(name);
        if (value.state == MacroState::kUnknown)
            unknown_.insert(name);
        else
            unknown_.erase(name);
    }
    Wrote(name);
}

void PpMacros::Wrote(std::string_view name) {
    if (logs_.empty())
        return;
    MacroLog& log = *logs_.back();
    std::string key(name);
    log.seen.insert(key);
    if (log.written.insert(key).second)
        log.writes.push_back(std::move(key));
}

void PpMacros::CloseLog() {
    MacroLog* closed = logs_.back();
    logs_.pop_back();
    if (logs_.empty())
        return;
    NoteReads(closed->reads);
    for (const std::string& name : closed->writes)
        Wrote(name);
}

void PpMacros::NoteReads(const std::vector<std::pair<std::string, MacroValue>>& reads) {
    if (logs_.empty())
        return;
    MacroLog& log = *logs_.back();
    for (const auto& [name, value] : reads) {
        if (log.seen.insert(name).second)
            log.reads.emplace_back(name, value);
    }
}

uint64_t WordHash(std::string_view word) {
    const uint64_t h = XXH3_64bits(word.data(), word.size());
    return h == 0 ? 1 : h;
}

void WordHashSet::Insert(std::string_view word) {
    if (2 * (size_ + 1) > slots_.size()) {
        std::vector<uint64_t> old(std::max<size_t>(64, 2 * slots_.size()), 0);
        old.swap(slots_);
        size_ = 0;
        for (const uint64_t h : old) {
            if (h == 0)
                continue;
            size_t i = h & (slots_.size() - 1);
            while (slots_[i] != 0)
                i = (i + 1) & (slots_.size() - 1);
            slots_[i] = h;
            ++size_;
        }
    }
    const uint64_t h = WordHash(word);
    size_t i = h & (slots_.size() - 1);
    while (slots_[i] != 0) {
        if (slots_[i] == h)
            return;
        i = (i + 1) & (slots_.size() - 1);
    }
    slots_[i] = h;
    ++size_;
}

bool WordHashSet::Has(uint64_t hash) const {
    if (slots_.empty())
        return false;
    for (size_t i = hash & (slots_.size() - 1);; i = (i + 1) & (slots_.size() - 1)) {
        if (slots_[i] == hash)
            return true;
        if (slots_[i] == 0)
            return false;
    }
}

std::optional<std::pair<uint64_t, uint64_t>> PpMacros::Fingerprint(const WordHashSet& words) const {
    for (const std::unordered_set<std::string>* names : {&unknown_, &pinned_}) {
        for (const std::string& name : *names) {
            if (words.Has(std::string_view(name)))
                return std::nullopt;
        }
    }
    // A sum of each definition's hashes: the table's order does not matter.
    uint64_t a = 0, b = 0;
    std::unordered_set<uint64_t> reached;  // words of bodies outside `words`
    std::vector<std::string_view> todo;
    std::string one;
    const auto add = [&](const std::string& name, const Macro& m) {
        one.assign(name);
        one += m.function_like ? '\1' : '\2';
        one += m.params;
        one += '\0';
        one += m.body;
        a += XXH3_64bits_withSeed(one.data(), one.size(), 1);
        b += XXH3_64bits_withSeed(one.data(), one.size(), 2);
        ForEachWord(m.body, [&](std::string_view w) {
            const uint64_t h = WordHash(w);
            if (!words.Has(h) && reached.insert(h).second)
                todo.push_back(w);
        });
    };
    for (const auto& [name, m] : defined_) {
        if (words.Has(m.name_hash))
            add(name, m);
    }
    std::string key;
    while (!todo.empty()) {
        key.assign(todo.back());
        todo.pop_back();
        if (unknown_.count(key) || pinned_.count(key))
            return std::nullopt;
        if (const auto it = defined_.find(key); it != defined_.end())
            add(it->first, it->second);
    }
    return std::make_pair(a, b);
}

std::optional<bool> PpMacros::Ifdef(std::string_view rest) const {
    std::string_view name;
    const std::optional<std::string_view> after = Name(rest, name);
    if (!after || !Blank(*after))
        return std::nullopt;
    const MacroState s = Lookup(name);
    if (s == MacroState::kUnknown)
        return std::nullopt;
    return s == MacroState::kDefined;
}

std::optional<bool> PpMacros::If(std::string_view expression) const {
    std::vector<Token> in;
    if (!Tokenize(expression, in))
        return std::nullopt;
    // Expands `defined` and object-like macros into ints and operators.
    std::vector<Token> out;
    bool ok = true;
    auto expand = [&](auto& self, const std::vector<Token>& tokens, int depth) -> void {
        for (size_t i = 0; ok && i < tokens.size(); ++i) {
            const Token& t = tokens[i];
            if (t.kind != Tok::kIdent) {
                out.push_back(t);
                continue;
            }
            // glslang reads `defined` and its operand from a macro's body as from the line
            // (Unity's UNITY_SHOULD_SAMPLE_SH); an operand outside the body is not modelled.
            if (t.text == "defined") {
                const bool paren = i + 1 < tokens.size() && tokens[i + 1].text == "(";
                const size_t n = i + (paren ? 2 : 1);
                if (n >= tokens.size() || tokens[n].kind != Tok::kIdent ||
                    (paren && (n + 1 >= tokens.size() || tokens[n + 1].text != ")"))) {
                    ok = false;
                    return;
                }
                const MacroState s = Lookup(tokens[n].text);
                if (s == MacroState::kUnknown)
                    out.push_back({Tok::kUnknown, ""});
                else
                    out.push_back({Tok::kInt, "", s == MacroState::kDefined ? 1 : 0});
                i = n + (paren ? 1 : 0);
                continue;
            }
            const MacroState s = Lookup(t.text);
            if (s == MacroState::kUnknown) {
                out.push_back({Tok::kUnknown, ""});
                continue;
            }
            if (s == MacroState::kUndefined) {
                out.push_back({Tok::kInt, "", 0});
                continue;
            }
            const Macro& m = defined_.at(std::string(t.text));
            std::vector<Token> body;
            if (m.function_like || depth >= kMaxExpansionDepth || !Tokenize(m.body, body) ||
                body.empty()) {
                ok = false;
                return;
            }
            self(self, body, depth + 1);
        }
    };
    expand(expand, in, 0);
    if (!ok)
        return std::nullopt;
    for (const Token& t : out) {
        if (t.kind == Tok::kIdent || t.text == "#" || t.text == "##")
            return std::nullopt;
    }
    Parser p{out};
    const Val v = p.Binary(1);
    if (!p.ok || p.i != out.size() || !v.known)
        return std::nullopt;
    return v.v != 0;
}

}  // namespace kiln::hlsl
