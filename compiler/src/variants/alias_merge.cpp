#include "variants/alias_merge.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <utility>

namespace kiln::variants {
namespace {

// (vertex, fragment, the pack's record of the other stages: equal records are equal modules)
using Modules = std::tuple<uint32_t, uint32_t, uint32_t>;
// A variant seen from one keyword set: its key with that set's choice cleared, and its modules.
using Entry = std::pair<uint64_t, Modules>;

}  // namespace

// Keyword `from` merges into `to` when every variant choosing `from` has a twin choosing `to`
// (the same choices in the other sets) with the same modules, and `from` has variants. Near-linear
// in keywords and variants (a shader_feature of 200,000 keywords takes a fraction of a second;
// trying every pair was quadratic): each keyword's variants are listed once per set, and only the
// keywords that hold `from`'s first variant are tried, lowest index first, as before.
std::vector<KeywordAlias> MergeRedundantKeywords(const std::vector<KeywordSet>& sets,
                                                 const std::vector<SetLayout>& layout,
                                                 std::vector<pack::VariantRec>& variants) {
    std::map<uint64_t, Modules> by_key;
    for (const pack::VariantRec& v : variants)
        by_key[v.key] = {v.vertex_module, v.fragment_module, v.stages};
    std::vector<KeywordAlias> aliases;
    for (size_t s = 0; s < sets.size() && s < layout.size(); ++s) {
        const SetLayout& l = layout[s];
        const uint32_t n = static_cast<uint32_t>(sets[s].keywords.size());
        // Each keyword's variants, in key order.
        std::vector<std::vector<Entry>> of(n);
        for (const auto& [bits, modules] : by_key) {
            pack::VariantKey key(bits);
            const uint32_t choice = key.Get(l.shift, l.bits);
            if (choice >= n)
                continue;
            key.Set(l.shift, l.bits, 0);
            of[choice].push_back({key.bits(), modules});
        }
        // Which keywords hold an entry (ascending), and the entries of each keyword.
        std::map<Entry, std::vector<uint32_t>> holders;
        std::set<std::pair<uint32_t, Entry>> held;
        for (uint32_t k = 0; k < n; ++k) {
            for (const Entry& e : of[k]) {
                holders[e].push_back(k);
                held.insert({k, e});
            }
        }
        std::vector<bool> merged(n, false);
        // `to` < `from`, and every keyword is tried as `from` before any later one: a keyword
        // already merged has no variants left, so it never becomes a target (no alias chains).
        for (uint32_t from = 1; from < n; ++from) {
            if (of[from].empty())
                continue;
            for (uint32_t to : holders[of[from].front()]) {
                if (to >= from)
                    break;
                if (merged[to])
                    continue;
                const bool twins =
                    std::all_of(of[from].begin(), of[from].end(), [&](const Entry& e) {
                        return held.count({to, e});
                    });
                if (!twins)
                    continue;
                aliases.push_back({s, from, to});
                merged[from] = true;
                for (const Entry& e : of[from]) {
                    pack::VariantKey key(e.first);
                    key.Set(l.shift, l.bits, from);
                    by_key.erase(key.bits());
                }
                break;
            }
        }
    }
    std::erase_if(variants,
                  [&](const pack::VariantRec& v) { return by_key.find(v.key) == by_key.end(); });
    return aliases;
}

}  // namespace kiln::variants
