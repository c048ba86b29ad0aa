// Expands a pass's keyword sets into the variant keys to build: the Cartesian product of the
// sets, with shader_feature sets narrowed to the requested keywords, then skip_variants applied,
// guarded by a variant limit whose error shows the multiplication.
#ifndef KILN_VARIANTS_EXPAND_H_
#define KILN_VARIANTS_EXPAND_H_

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/variant_key.h"
#include "variants/pass_pragmas.h"

namespace kiln::variants {

struct SetLayout {
    uint32_t shift = 0, bits = 0;
};

struct VariantRequest {
    // Keywords asked for (by --keywords or material instances). Unset: every shader_feature
    // variant is built.
    std::optional<std::set<std::string>> shader_features;
    uint64_t max_variants = 4096;
};

struct Expansion {
    std::vector<SetLayout> layout;        // one per keyword set
    std::vector<pack::VariantKey> keys;   // sorted ascending
    std::vector<size_t> effective_sizes;  // choices per set after shader_feature narrowing
    uint64_t permutations = 0;            // product of effective_sizes (before skip_variants)
};

// Bit layout of the sets (see kiln/pack/variant_key.h); nullopt when wider than 64 bits.
std::optional<std::vector<SetLayout>> LayoutSets(const std::vector<KeywordSet>& sets);

// Returns nullopt after reporting an error (key too wide, too many variants, none left).
std::optional<Expansion> ExpandVariants(const PassPragmas& pragmas,
                                        const VariantRequest& request,
                                        const std::string& pass_label,
                                        const std::string& file,
                                        SourceRange pass_range,
                                        DiagnosticList& diags);

// The keywords a key enables, in set order ("no keyword" choices omitted).
std::vector<std::string> EnabledKeywords(const std::vector<KeywordSet>& sets,
                                         const std::vector<SetLayout>& layout,
                                         pack::VariantKey key);

// "SPOT _NORMALMAP", or "(no keywords)".
std::string DescribeKeywords(const std::vector<std::string>& keywords);

}  // namespace kiln::variants

#endif  // KILN_VARIANTS_EXPAND_H_
