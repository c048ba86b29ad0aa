// Expands a pass's keyword sets into the variant keys to build, as Unity does: the Cartesian
// product of the multi_compile sets times the shader_feature combinations that material
// instances ask for (plus the all-off one), or every shader_feature combination when asked;
// then the built-in shortcuts' rules and skip_variants; guarded by a variant limit whose error
// shows the multiplication.
#ifndef KILN_VARIANTS_EXPAND_H_
#define KILN_VARIANTS_EXPAND_H_

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/variant_key.h"
#include "kiln/pack/variant_selector.h"  // pack::JoinKeywords, how messages show keywords
#include "variants/pass_pragmas.h"

namespace kiln::variants {

struct SetLayout {
    uint32_t shift = 0, bits = 0;
};

struct VariantRequest {
    // Every shader_feature combination (--all-features) instead of the requested ones.
    bool all_features = false;
    // Keyword combinations material instances enable (one set per material); each gives one
    // shader_feature combination. The all-off combination is always built.
    std::vector<std::set<std::string>> feature_combinations;
    uint64_t max_variants = 4096;
    // Build every multi_compile combination (--strict-variants); false: leave out those Unity's
    // default stripping leaves out (variants/strip_profile.h), unless a feature combination asks
    // for the keyword.
    bool strict_variants = false;
};

struct Expansion {
    std::vector<SetLayout> layout;        // one per keyword set
    std::vector<pack::VariantKey> keys;   // sorted ascending
    std::vector<size_t> effective_sizes;  // choices per set after shader_feature narrowing
    size_t feature_combinations = 0;      // distinct shader_feature combinations built
    // multi_compile product x feature_combinations, before rules and skip_variants.
    uint64_t permutations = 0;
    std::string formula;  // the product as written: "3 x 2 x 4 shader_feature combinations"
    // Variants the default stripping profile left out (none with strict_variants), and the
    // declared keywords it strips, in declaration order.
    uint64_t profile_stripped = 0;
    std::vector<std::string> profile_keywords;
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

// The key of the variant that enables `enabled`: in each set the first of its keywords that
// `enabled` names, else the set's first choice. This is the rule pack::Pack::KeyFor applies to a
// pack's sets (a test checks that both agree), so a lookup the runtime recorded maps back to the
// variant it asked for.
pack::VariantKey KeyForKeywords(const std::vector<KeywordSet>& sets,
                                const std::vector<SetLayout>& layout,
                                const std::vector<std::string>& enabled);

// Why a variant enabling `enabled` is not built ("skip_variants names 'POINT'", a shortcut's
// rule); empty when it is built.
std::string ExclusionReason(const PassPragmas& pragmas, const std::vector<std::string>& enabled);

// A requested variant that is not built, and why.
struct ExcludedRequest {
    size_t request = 0;  // index into the requests
    std::vector<std::string> keywords;
    std::string reason;
};

// The variants a scene or usage file asks for, and only those: each request's key, kept when
// skip_variants and the shortcut rules allow it (`excluded` gets the others, with the reason).
// Nothing enumerates the product of the sets, so a pass declaring 2^40 combinations is planned
// from its requests alone. `permutations` is that product (UINT64_MAX when it overflows), what
// the kept variants are a part of. No requests (or none kept) gives an expansion without keys.
std::optional<Expansion> ExpandRequested(const PassPragmas& pragmas,
                                         const std::vector<std::vector<std::string>>& requests,
                                         uint64_t max_variants,
                                         const std::string& pass_label,
                                         const std::string& file,
                                         SourceRange pass_range,
                                         DiagnosticList& diags,
                                         std::vector<ExcludedRequest>& excluded);

// The keywords a key enables, in set order ("no keyword" choices omitted).
std::vector<std::string> EnabledKeywords(const std::vector<KeywordSet>& sets,
                                         const std::vector<SetLayout>& layout,
                                         pack::VariantKey key);

}  // namespace kiln::variants

#endif  // KILN_VARIANTS_EXPAND_H_
