// Keyword aliases: a keyword whose variants have exactly the modules (both stages) of another
// keyword of its set, in every combination of the other sets, is stored as an alias of it
// (kiln/pack/format.h, KeywordAliasRec): the pack keeps one set of variant records, and a lookup
// of either keyword finds them.
#ifndef KILN_VARIANTS_ALIAS_MERGE_H_
#define KILN_VARIANTS_ALIAS_MERGE_H_

#include <cstdint>
#include <vector>

#include "kiln/pack/format.h"
#include "variants/expand.h"
#include "variants/pass_pragmas.h"

namespace kiln::variants {

struct KeywordAlias {
    size_t set = 0;             // index into the pass's sets
    uint32_t from = 0, to = 0;  // keyword indices; to < from, and `to` is never aliased
};

// Finds the aliases of one pass and removes the merged variants from `variants` (the pass's
// records, sorted by key; modules compared by index, which the pack builder makes equal exactly
// for equal SPIR-V and reflection). A keyword merges into the lowest-index keyword of its set
// whose variants match it, so "no keyword" (index 0) is kept over a keyword that changes nothing.
std::vector<KeywordAlias> MergeRedundantKeywords(const std::vector<KeywordSet>& sets,
                                                 const std::vector<SetLayout>& layout,
                                                 std::vector<pack::VariantRec>& variants);

}  // namespace kiln::variants

#endif  // KILN_VARIANTS_ALIAS_MERGE_H_
