#include "hlsl/reduce.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "hlsl/identifier.h"
#include "hlsl/reduce_declarations.h"

namespace kiln::hlsl {
namespace {

// A top-level declaration or function definition: its byte range and the words it uses.
struct Item {
    size_t begin = 0, end = 0;
    size_t first_word = 0, end_word = 0;    // its words: Split::words[first_word, end_word)
    size_t first_token = 0, end_token = 0;  // its tokens: [first_token, end_token)
    bool is_function = false;
    // A declaration kept only when a kept item names it (reduce_declarations.h), by one of
    // Split::names[first_name, end_name).
    bool droppable = false;
    size_t first_name = 0, end_name = 0;
    std::string_view name;  // a function's name
};

struct Split {
    std::vector<Item> items;
    // Identifiers each item uses, and the identifier-like strings it holds: a hull shader's
    // [patchconstantfunc("PatchConstants")] is the function's only reference.
    std::vector<std::string_view> words;
    std::vector<std::string_view> names;  // what droppable declarations declare
    // Function items (overloads share one entry) and droppable declarations by name; `reached`
    // is per entry point.
    struct Named {
        std::vector<uint32_t> items;
        bool reached = false;
        bool function = false;
    };
    std::unordered_map<std::string_view, Named> named;
};

bool IsTypeDeclaration(std::string_view w) {
    return w == "struct" || w == "cbuffer" || w == "tbuffer" || w == "class" || w == "interface" ||
           w == "namespace" || w == "typedef";
}

// The identifier inside a string token, or empty when the string holds anything else.
std::string_view StringWord(std::string_view t) {
    std::string_view inside = t.substr(1);
    if (!inside.empty() && inside.back() == '"')
        inside.remove_suffix(1);
    if (inside.empty() || !IdentStart(inside[0]) ||
        !std::all_of(inside.begin(), inside.end(), IdentChar))
        return {};
    return inside;
}

// Splits the tokens from `first` on into top-level items, after `out`'s (which close every token
// before `first`): a function ends at the `}` closing its body, a cbuffer, tbuffer or namespace
// at its `}`, anything else at a `;` outside brackets. `closed`: the first token after the last
// item closed (where a split of a longer text may go on from).
void SplitItemsFrom(const std::string& text,
                    const std::vector<Token>& tok,
                    size_t first,
                    Split& out,
                    size_t* closed = nullptr) {
    const std::string_view s(text);
    Item cur;
    bool open = false;
    int depth = 0;           // {} () [] nesting
    bool saw_paren = false;  // a '(' at depth 0 before the first '{'
    bool saw_brace = false;
    bool type_decl = false;  // struct/cbuffer/...: not a function
    std::string_view last_ident, first_word;
    for (size_t k = first; k < tok.size(); ++k) {
        const Token& t = tok[k];
        const std::string_view word = s.substr(t.begin, t.end - t.begin);
        if (!open) {
            cur = Item{};
            cur.begin = t.begin;
            cur.first_word = out.words.size();
            cur.first_token = k;
            open = true;
            saw_paren = saw_brace = type_decl = false;
            last_ident = first_word = {};
        }
        if (t.ident) {
            if (first_word.empty()) {
                first_word = word;
                type_decl = IsTypeDeclaration(word);
            }
            out.words.push_back(word);
            last_ident = word;
            continue;
        }
        if (word[0] == '"') {
            if (const std::string_view w = StringWord(word); !w.empty())
                out.words.push_back(w);
            continue;
        }
        if (word.size() != 1)
            continue;  // a number or a multi-character operator
        const char c = word[0];
        if (c == '(' && depth == 0 && !saw_brace && !saw_paren) {
            saw_paren = true;
            cur.name = last_ident;
        }
        if (c == '{' && depth == 0)
            saw_brace = true;
        if (c == '{' || c == '(' || c == '[')
            ++depth;
        if ((c == '}' || c == ')' || c == ']') && depth > 0)
            --depth;
        const bool ends_block = c == '}' && depth == 0;
        const bool is_function_end = ends_block && saw_paren && !type_decl;
        const bool cbuffer_end =
            ends_block && type_decl &&
            (first_word == "cbuffer" || first_word == "tbuffer" || first_word == "namespace");
        if ((c == ';' && depth == 0) || is_function_end || cbuffer_end) {
            cur.end = t.end;
            cur.end_word = out.words.size();
            cur.end_token = k + 1;
            cur.is_function = is_function_end;
            cur.first_name = out.names.size();
            cur.droppable = !cur.is_function &&
                            DroppableDeclaration(s, tok, cur.first_token, cur.end_token, out.names);
            cur.end_name = out.names.size();
            out.items.push_back(cur);
            open = false;
            if (closed != nullptr)
                *closed = k + 1;
        }
    }
    if (open && closed != nullptr) {
        out.words.resize(cur.first_word);  // the open item's: a longer text may close it later
        return;
    }
    if (open) {
        cur.end = text.size();
        cur.end_word = out.words.size();
        cur.end_token = tok.size();
        cur.first_name = cur.end_name = out.names.size();
        out.items.push_back(cur);
    }
}

// Function items and droppable declarations by name, once every item is split.
void NameItems(Split& split) {
    for (size_t i = 0; i < split.items.size(); ++i) {
        const Item& item = split.items[i];
        const auto index = static_cast<uint32_t>(i);
        if (item.is_function) {
            Split::Named& n = split.named[item.name];
            n.items.push_back(index);
            n.function = true;
            continue;
        }
        if (!item.droppable)
            continue;
        for (size_t k = item.first_name; k < item.end_name; ++k) {
            Split::Named& n = split.named[split.names[k]];
            if (n.items.empty() || n.items.back() != index)
                n.items.push_back(index);
        }
    }
}

// Which items the entry point keeps: every declaration but the droppable ones, and the functions
// and droppable declarations named by a word of a kept item or by the entry point, transitively
// (a worklist over names).
std::vector<char> Reachable(Split& split, const std::string& entry_point, bool drop_declarations) {
    for (auto& [name, named] : split.named)
        named.reached = false;
    std::vector<char> keep(split.items.size(), 0);
    std::vector<uint32_t> work;
    auto reach = [&](std::string_view word) {
        const auto it = split.named.find(word);
        if (it == split.named.end() || it->second.reached)
            return;
        it->second.reached = true;
        work.insert(work.end(), it->second.items.begin(), it->second.items.end());
    };
    auto reach_words = [&](const Item& item) {
        for (size_t w = item.first_word; w < item.end_word; ++w)
            reach(split.words[w]);
    };
    reach(entry_point);
    for (size_t i = 0; i < split.items.size(); ++i) {
        if (!split.items[i].is_function && (!split.items[i].droppable || !drop_declarations)) {
            keep[i] = 1;
            reach_words(split.items[i]);
        }
    }
    while (!work.empty()) {
        const uint32_t i = work.back();
        work.pop_back();
        if (keep[i])
            continue;  // named twice
        keep[i] = 1;
        reach_words(split.items[i]);
    }
    return keep;
}

// A line whose first character after spaces and tabs is '#'.
// A line whose first character other than a space or tab is `#`: [begin, end), without its line
// break; `pragma` when `pragma` follows the `#` at once.
struct DirectiveLine {
    size_t begin = 0, end = 0;
    bool pragma = false;
};

// The directive lines of a text from byte `from` (a line's start) on, after `out`'s, in order:
// found once for every entry point's assembly. `whole`: where the line after the last line
// break starts (and an unfinished last line is left for a longer text).
void DirectiveLinesFrom(const std::string& text,
                        size_t from,
                        std::vector<DirectiveLine>& out,
                        size_t* whole = nullptr) {
    const char* s = text.data();
    const size_t n = text.size();
    for (size_t i = from; i < n;) {
        size_t j = i;
        while (j < n && (s[j] == ' ' || s[j] == '\t'))
            ++j;
        const void* nl = std::memchr(s + j, '\n', n - j);
        const size_t eol = nl ? static_cast<size_t>(static_cast<const char*>(nl) - s) : n;
        if (eol == n && whole != nullptr)
            return;  // an unfinished line: a longer text may go on with it
        if (j < eol && s[j] == '#')
            out.push_back({i, eol, text.compare(j + 1, 6, "pragma") == 0});
        i = eol + 1;
        if (whole != nullptr)
            *whole = i;
    }
}

// A kept span of the text [from, to), copied to the reduced text at `at`.
struct Copied {
    size_t from, to, at;
};

// The text without the items not kept (their line breaks stay) and with `#pragma` lines blanked;
// every other directive line is kept, inside a dropped function too. Kept spans are copied whole
// (and listed in `copied`); only the directive lines and line breaks of dropped ones are looked at.
std::string Assemble(const std::string& text,
                     const Split& split,
                     const std::vector<char>& keep,
                     const std::vector<DirectiveLine>& directives,
                     std::vector<Copied>& copied) {
    std::string out;
    out.reserve(text.size());
    size_t d = 0;  // the first directive line that may end after the position reached
    auto copy = [&](size_t from, size_t to) {
        if (to > from) {
            copied.push_back({from, to, out.size()});
            out.append(text, from, to - from);
        }
    };
    // [from, to) of a kept span: all of it but the parts of #pragma lines.
    auto kept = [&](size_t from, size_t to) {
        while (d < directives.size() && directives[d].end <= from)
            ++d;
        for (size_t k = d; k < directives.size() && directives[k].begin < to; ++k) {
            if (!directives[k].pragma)
                continue;
            const size_t b = std::max(directives[k].begin, from);
            copy(from, b);
            from = std::min(directives[k].end, to);
        }
        copy(from, to);
    };
    // [from, to) of a dropped item: its line breaks, and the parts of directive lines but
    // #pragma lines.
    auto dropped = [&](size_t from, size_t to) {
        while (d < directives.size() && directives[d].end <= from)
            ++d;
        size_t k = d;
        for (size_t p = from; p < to;) {
            while (k < directives.size() && directives[k].end <= p)
                ++k;
            const size_t next_directive =
                k < directives.size() ? std::max(directives[k].begin, p) : to;
            if (next_directive <= p && k < directives.size()) {  // inside directive line k
                const size_t e = std::min(directives[k].end, to);
                if (!directives[k].pragma)
                    out.append(text, p, e - p);
                p = e;
                continue;
            }
            const size_t stop = std::min(next_directive, to);
            for (const char* c = text.data() + p;;) {
                const void* nl = std::memchr(c, '\n', text.data() + stop - c);
                if (!nl)
                    break;
                out += '\n';
                c = static_cast<const char*>(nl) + 1;
            }
            p = stop;
        }
    };
    size_t at = 0;
    for (size_t i = 0; i < split.items.size(); ++i) {
        if (keep[i])
            continue;
        kept(at, split.items[i].begin);
        dropped(split.items[i].begin, split.items[i].end);
        at = split.items[i].end;
    }
    kept(at, text.size());
    return out;
}

// Tokenize(out) from the whole text's tokens: those of the kept items, moved by where their span
// was copied to. False where that may not be so: a token outside every copied span, or one that
// begins with '#' and now starts its line (the tokenizer would skip that line as a directive).
bool ReducedTokens(const std::string& out,
                   const std::vector<Token>& tok,
                   const Split& split,
                   const std::vector<char>& keep,
                   const std::vector<Copied>& copied,
                   std::vector<Token>& reduced) {
    reduced.clear();
    size_t c = 0;
    for (size_t i = 0; i < split.items.size(); ++i) {
        if (!keep[i])
            continue;
        for (size_t k = split.items[i].first_token; k < split.items[i].end_token; ++k) {
            Token t = tok[k];
            while (c < copied.size() && copied[c].to <= t.begin)
                ++c;
            if (c == copied.size() || t.begin < copied[c].from || t.end > copied[c].to)
                return false;
            t.begin = copied[c].at + (t.begin - copied[c].from);
            t.end = copied[c].at + (t.end - copied[c].from);
            if (out[t.begin] == '#') {
                size_t b = t.begin;
                while (b > 0 && out[b - 1] != '\n' &&
                       std::isspace(static_cast<unsigned char>(out[b - 1])))
                    --b;
                if (b == 0 || out[b - 1] == '\n')
                    return false;
            }
            t.text = std::string_view(out).substr(t.begin, t.end - t.begin);
            reduced.push_back(t);
        }
    }
    return true;
}

}  // namespace

struct ReducePrefix {
    std::string text;  // the prefix: `split`'s words view it
    Split split;       // the items it closes (no functions by name yet)
    size_t next_token = 0;
    std::vector<DirectiveLine> directives;  // of its finished lines
    size_t next_line = 0;                   // where its unfinished line starts
};

std::shared_ptr<const ReducePrefix> MakeReducePrefix(const std::string& text,
                                                     const std::vector<Token>& tokens) {
    auto p = std::make_shared<ReducePrefix>();
    p->text = text;
    SplitItemsFrom(p->text, tokens, 0, p->split, &p->next_token);
    DirectiveLinesFrom(p->text, 0, p->directives, &p->next_line);
    return p;
}

std::vector<Reduced> ReduceToEntryPoints(const std::string& text,
                                         const std::vector<Token>& tokens,
                                         const std::vector<std::string>& entry_points,
                                         const ReducePrefix* prefix,
                                         bool drop_declarations) {
    Split split;
    std::vector<DirectiveLine> directives;
    if (prefix != nullptr) {
        split.items = prefix->split.items;
        split.words = prefix->split.words;
        split.names = prefix->split.names;
        directives = prefix->directives;
    }
    SplitItemsFrom(text, tokens, prefix ? prefix->next_token : 0, split);
    NameItems(split);
    DirectiveLinesFrom(text, prefix ? prefix->next_line : 0, directives);
    std::vector<Reduced> out(entry_points.size());
    for (size_t e = 0; e < entry_points.size(); ++e) {
        const auto entry = split.named.find(entry_points[e]);
        if (entry == split.named.end() || !entry->second.function) {
            for (const Item& it : split.items) {
                if (it.is_function)
                    out[e].functions_if_entry_missing.emplace_back(it.name);
            }
        }
        const std::vector<char> keep = Reachable(split, entry_points[e], drop_declarations);
        std::vector<Copied> copied;
        out[e].text = Assemble(text, split, keep, directives, copied);
        if (!ReducedTokens(out[e].text, tokens, split, keep, copied, out[e].tokens))
            out[e].tokens = Tokenize(out[e].text);
    }
    return out;
}

Reduced ReduceToEntryPoint(const std::string& text, const std::string& entry_point) {
    return std::move(ReduceToEntryPoints(text, Tokenize(text), {entry_point}).front());
}

}  // namespace kiln::hlsl
