#include "hlsl/needless_defines.h"

#include <algorithm>
#include <string>
#include <utility>

#include "hlsl/identifier.h"
#include "hlsl/pp_macros.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/splice.h"

namespace kiln::hlsl {
namespace {

using Files = std::vector<std::shared_ptr<const PpSkeleton>>;

bool Space(char c) {
    return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r';
}

// The body's tokens as far as pasting needs them: names and "##" (anything else one character,
// whose tokens a paste cannot start a name with).
std::vector<std::string_view> PasteTokens(std::string_view body) {
    std::vector<std::string_view> out;
    for (size_t i = 0; i < body.size();) {
        if (Space(body[i])) {
            ++i;
        } else if (IdentChar(body[i])) {
            const size_t start = i;
            while (i < body.size() && IdentChar(body[i]))
                ++i;
            out.push_back(body.substr(start, i - start));
        } else if (body.compare(i, 2, "##") == 0) {
            out.push_back(body.substr(i, 2));
            i += 2;
        } else {
            out.push_back(body.substr(i, 1));
            ++i;
        }
    }
    return out;
}

// Adds the first piece of each paste in the #define `rest` to `pieces`; false when a piece is a
// parameter (then an argument, which may be any word) or not known.
bool AddPastePieces(std::string_view rest, std::unordered_set<std::string>& pieces) {
    if (rest.find("##") == std::string_view::npos)
        return true;
    const std::string_view name = DirectiveMacroName(rest);
    if (name.empty())
        return false;
    std::string_view body = rest.substr(rest.find(name) + name.size());
    std::vector<std::string_view> params;
    if (!body.empty() && body[0] == '(') {
        const size_t close = body.find(')');
        if (close == std::string_view::npos)
            return false;
        params = PasteTokens(body.substr(1, close - 1));
        body.remove_prefix(close + 1);
    }
    const std::vector<std::string_view> t = PasteTokens(body);
    for (size_t i = 0; i < t.size(); ++i) {
        if (t[i] != "##")
            continue;
        size_t first = i;  // the chain's first "##"
        while (first >= 2 && t[first - 2] == "##")
            first -= 2;
        if (first == 0)
            return false;
        const std::string_view left = t[first - 1];
        if (!IdentStart(left[0]))
            continue;  // a number or a punctuator starts no name
        if (std::find(params.begin(), params.end(), left) != params.end() || left == "__VA_ARGS__")
            return false;
        pieces.emplace(left);
    }
    return true;
}

// The first pieces of the files' pastes; false when one may be any word.
bool PastePieces(const std::vector<const PpSkeleton*>& files,
                 std::unordered_set<std::string>& pieces) {
    for (const PpSkeleton* file : files) {
        if (!file->pastes)
            continue;
        for (const PpDirective& d : file->directives) {
            if (d.kind == PpKind::kDefine && !AddPastePieces(d.rest, pieces))
                return false;
        }
    }
    return true;
}

bool HasPrefixIn(std::string_view name, const std::unordered_set<std::string>& pieces) {
    for (size_t n = 1; n < name.size(); ++n) {
        if (pieces.count(std::string(name.substr(0, n))))
            return true;
    }
    return false;
}

// Whether a proper prefix of `name` is a word of the files.
bool HasPrefixIn(std::string_view name, const Files& files) {
    for (size_t n = 1; n < name.size(); ++n) {
        const std::string piece(name.substr(0, n));
        for (const auto& file : files) {
            if (file->words.count(piece))
                return true;
        }
    }
    return false;
}

}  // namespace

IncludedDefines MakeIncludedDefines(std::vector<std::shared_ptr<const PpSkeleton>> files) {
    IncludedDefines out;
    out.skeletons = std::move(files);
    // Each #define's name with the words of its lines' bodies (its own name once per line).
    std::unordered_map<std::string_view, std::vector<std::string_view>> words;
    std::vector<const PpSkeleton*> raw;
    for (const auto& file : out.skeletons) {
        raw.push_back(file.get());
        for (const PpDirective& d : file->directives) {
            const std::string_view name =
                d.kind == PpKind::kDefine ? DirectiveMacroName(d.rest) : std::string_view();
            if (name.empty() || GlslangMayDefine(name))
                continue;
            out.defined.insert(name);
            std::vector<std::string_view>& w = words[name];
            ForEachWord(d.rest, [&](std::string_view word) { w.push_back(word); });
        }
    }
    // Those whose expansion may end with a macro's name (hlsl/splice.h), to a fixed point.
    std::vector<std::pair<std::string_view, std::string_view>> ends;  // name, its body's last word
    std::vector<std::pair<std::string_view, std::string_view>> only_words;  // name, body of words
    for (const auto& file : out.skeletons) {
        for (const PpDirective& d : file->directives) {
            const std::string_view name =
                d.kind == PpKind::kDefine ? DirectiveMacroName(d.rest) : std::string_view();
            if (name.empty() || GlslangMayDefine(name))
                continue;
            const DefineEnd end = EndOfDefine(d.rest);
            if (end.calls)
                out.callable.insert(name);
            else if (!end.last_word.empty())
                ends.emplace_back(name, end.last_word);
            if (!end.calls && end.words_only)
                only_words.emplace_back(name, end.body);
        }
    }
    for (bool grew = true; grew;) {  // bodies empty, or of names that may expand to nothing
        grew = false;
        for (const auto& [name, body] : only_words) {
            bool all = !out.empty.count(name);
            ForEachWord(body, [&](std::string_view w) { all = all && out.empty.count(w); });
            if (all) {
                out.empty.insert(name);
                grew = true;
            }
        }
    }
    for (bool grew = true; grew;) {
        grew = false;
        for (const auto& [name, last] : ends) {
            if (!out.callable.count(name) && (out.callable.count(last) || GlslangMayDefine(last))) {
                out.callable.insert(name);
                grew = true;
            }
        }
    }
    out.pieces_known = PastePieces(raw, out.pieces);
    // The times each name is spelled where it is not known to be needless: a name spelled only
    // in the #define lines of needless names is needless too.
    std::unordered_map<std::string_view, uint32_t> left;
    for (const auto& [name, w] : words) {
        uint32_t count = 0;
        const std::string key(name);
        for (const auto& file : out.skeletons) {
            if (const auto it = file->words.find(key); it != file->words.end())
                count += it->second;
        }
        left[name] = count;
    }
    std::vector<std::string_view> work;
    const auto drop = [&](std::string_view name) {  // one spelling of `name` is needless
        const auto it = left.find(name);
        if (it != left.end() && --it->second == 0)
            work.push_back(name);
    };
    for (const auto& [name, w] : words) {
        for (const std::string_view word : w) {
            if (word == name)
                drop(name);
        }
    }
    while (!work.empty()) {
        const std::string_view name = work.back();
        work.pop_back();
        if (out.pieces_known ? HasPrefixIn(name, out.pieces) : HasPrefixIn(name, out.skeletons))
            continue;
        out.unnamed.insert(name);
        for (const std::string_view word : words[name]) {
            if (word != name)  // its own spellings were dropped first
                drop(word);
        }
        if (!out.pieces_known) {
            for (size_t n = 1; n < name.size(); ++n)
                out.prefixes[name.substr(0, n)].push_back(name);
        }
    }
    for (const std::string_view name : out.unnamed)
        out.bodies[name] = std::move(words[name]);
    return out;
}

NeedlessDefines::NeedlessDefines(const IncludedDefines& included, const PpSkeleton& main)
    : included_(included) {
    std::unordered_set<std::string> pieces;
    const bool known = included.pieces_known && (!main.pastes || PastePieces({&main}, pieces));
    if (!known && included.pieces_known) {
        all_kept_ = true;  // an argument of the program's own paste may begin any name
        return;
    }
    for (const auto& [word, count] : main.words) {
        Keep(word);
        if (const auto it = included.prefixes.find(word); it != included.prefixes.end()) {
            for (const std::string_view name : it->second)
                Keep(name);
        }
    }
    if (pieces.empty())
        return;
    for (const std::string_view name : included.unnamed) {
        if (HasPrefixIn(name, pieces))
            Keep(name);
    }
}

void NeedlessDefines::Keep(std::string_view name) {
    const auto it = included_.unnamed.find(name);
    if (it == included_.unnamed.end() || !kept_.insert(*it).second)
        return;
    // Its body is read then: what it names is needed.
    for (const std::string_view word : included_.bodies.at(*it)) {
        if (word != name)
            Keep(word);
    }
}

}  // namespace kiln::hlsl
