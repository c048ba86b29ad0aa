#include "hlsl/reduce.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <vector>

#include "hlsl/identifier.h"

namespace kiln::hlsl {
namespace {

struct Item {
    size_t begin = 0, end = 0;  // byte range in the text
    bool is_function = false;
    std::string name;              // function name
    std::set<std::string> idents;  // identifiers used (for functions: excluding its name)
};

// Marks the bytes of directive lines (first non-blank character '#').
std::vector<bool> DirectiveMask(const std::string& s) {
    std::vector<bool> mask(s.size(), false);
    size_t i = 0;
    while (i < s.size()) {
        size_t j = i;
        while (j < s.size() && (s[j] == ' ' || s[j] == '\t'))
            ++j;
        size_t eol = s.find('\n', i);
        if (eol == std::string::npos)
            eol = s.size();
        if (j < s.size() && s[j] == '#') {
            for (size_t k = i; k < eol; ++k)
                mask[k] = true;
        }
        i = eol + 1;
    }
    return mask;
}

std::vector<Item> SplitItems(const std::string& s, const std::vector<bool>& directive) {
    std::vector<Item> items;
    Item cur;
    bool open = false;
    int depth = 0;           // {} () [] nesting
    bool saw_paren = false;  // a '(' at depth 0 before the first '{'
    bool saw_brace = false;
    bool type_decl = false;  // struct/cbuffer/...: not a function
    std::string last_ident, first_word;
    for (size_t i = 0; i < s.size(); ++i) {
        if (directive[i])
            continue;
        const char c = s[i];
        if (std::isspace(static_cast<unsigned char>(c)))
            continue;
        if (!open) {
            cur = Item{};
            cur.begin = i;
            open = true;
            saw_paren = saw_brace = type_decl = false;
            last_ident.clear();
            first_word.clear();
        }
        if (IdentStart(c)) {
            size_t j = i;
            while (j < s.size() && IdentChar(s[j]))
                ++j;
            std::string word = s.substr(i, j - i);
            if (first_word.empty()) {
                first_word = word;
                type_decl = word == "struct" || word == "cbuffer" || word == "tbuffer" ||
                            word == "class" || word == "interface" || word == "namespace" ||
                            word == "typedef";
            }
            cur.idents.insert(word);
            last_ident = word;
            i = j - 1;
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
            while (i + 1 < s.size() && (IdentChar(s[i + 1]) || s[i + 1] == '.'))
                ++i;
            continue;
        }
        if (c == '"') {
            const size_t start = i + 1;
            while (i + 1 < s.size() && s[i + 1] != '"' && s[i + 1] != '\n')
                ++i;
            // A string naming a function keeps it: a hull shader's
            // [patchconstantfunc("PatchConstants")] is its only reference.
            const std::string word = s.substr(start, i + 1 - start);
            if (!word.empty() && IdentStart(word[0]) &&
                std::all_of(word.begin(), word.end(), IdentChar))
                cur.idents.insert(word);
            ++i;
            continue;
        }
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
            cur.end = i + 1;
            cur.is_function = is_function_end;
            if (cur.is_function)
                cur.idents.erase(cur.name);
            items.push_back(std::move(cur));
            open = false;
        }
    }
    if (open) {
        cur.end = s.size();
        items.push_back(std::move(cur));
    }
    return items;
}

}  // namespace

Reduced ReduceToEntryPoint(const std::string& text, const std::string& entry_point) {
    const std::vector<bool> directive = DirectiveMask(text);
    std::vector<Item> items = SplitItems(text, directive);
    Reduced out;
    const bool entry_found = std::any_of(items.begin(), items.end(), [&](const Item& it) {
        return it.is_function && it.name == entry_point;
    });
    if (!entry_found) {
        for (const Item& it : items) {
            if (it.is_function)
                out.functions_if_entry_missing.push_back(it.name);
        }
    }

    std::set<std::string> reachable = {entry_point};
    for (const Item& it : items) {
        if (!it.is_function)
            reachable.insert(it.idents.begin(), it.idents.end());
    }
    std::vector<bool> keep(items.size(), false);
    for (size_t i = 0; i < items.size(); ++i)
        keep[i] = !items[i].is_function;
    for (bool changed = true; changed;) {
        changed = false;
        for (size_t i = 0; i < items.size(); ++i) {
            if (keep[i] || !reachable.count(items[i].name))
                continue;
            keep[i] = true;
            changed = true;
            reachable.insert(items[i].idents.begin(), items[i].idents.end());
        }
    }

    std::vector<bool> drop(text.size(), false);
    for (size_t i = 0; i < items.size(); ++i) {
        if (keep[i])
            continue;
        for (size_t k = items[i].begin; k < items[i].end; ++k)
            drop[k] = true;
    }
    out.text.reserve(text.size());
    size_t line_begin = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (i == line_begin && directive[i]) {
            size_t eol = text.find('\n', i);
            if (eol == std::string::npos)
                eol = text.size();
            std::string_view line(text.data() + i, eol - i);
            const size_t hash = line.find('#');
            if (line.substr(hash + 1).find("pragma") != 0)
                out.text.append(line);
            i = eol - 1;
            continue;
        }
        if (c == '\n') {
            out.text += '\n';
            line_begin = i + 1;
            continue;
        }
        if (!drop[i])
            out.text += c;
    }
    return out;
}

}  // namespace kiln::hlsl
