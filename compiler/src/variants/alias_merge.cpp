#include "variants/alias_merge.h"

#include <algorithm>
#include <map>
#include <utility>

namespace kiln::variants {
namespace {

using Modules = std::pair<uint32_t, uint32_t>;  // (vertex, fragment)

// Whether every variant choosing `from` in set `layout` has a twin choosing `to` with the same
// modules (and at least one variant chooses `from`).
bool Mergeable(const std::map<uint64_t, Modules>& by_key,
               const SetLayout& layout,
               uint32_t from,
               uint32_t to) {
    bool any = false;
    for (const auto& [bits, modules] : by_key) {
        pack::VariantKey key(bits);
        if (key.Get(layout.shift, layout.bits) != from)
            continue;
        any = true;
        key.Set(layout.shift, layout.bits, to);
        const auto twin = by_key.find(key.bits());
        if (twin == by_key.end() || twin->second != modules)
            return false;
    }
    return any;
}

}  // namespace

std::vector<KeywordAlias> MergeRedundantKeywords(const std::vector<KeywordSet>& sets,
                                                 const std::vector<SetLayout>& layout,
                                                 std::vector<pack::VariantRec>& variants) {
    std::map<uint64_t, Modules> by_key;
    for (const pack::VariantRec& v : variants)
        by_key[v.key] = {v.vertex_module, v.fragment_module};
    std::vector<KeywordAlias> aliases;
    for (size_t s = 0; s < sets.size() && s < layout.size(); ++s) {
        // `to` < `from`, and every keyword is tried as `from` before any later one: a keyword
        // already merged has no variants left, so it never becomes a target (no alias chains).
        const uint32_t n = static_cast<uint32_t>(sets[s].keywords.size());
        for (uint32_t from = 1; from < n; ++from) {
            for (uint32_t to = 0; to < from; ++to) {
                if (!Mergeable(by_key, layout[s], from, to))
                    continue;
                aliases.push_back({s, from, to});
                std::erase_if(by_key, [&](const auto& entry) {
                    return pack::VariantKey(entry.first).Get(layout[s].shift, layout[s].bits) ==
                           from;
                });
                break;
            }
        }
    }
    std::erase_if(variants,
                  [&](const pack::VariantRec& v) { return by_key.find(v.key) == by_key.end(); });
    return aliases;
}

}  // namespace kiln::variants
