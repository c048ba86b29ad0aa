// Picking the compiled variant for (shader, pass, enabled keywords), with a clear error when a
// variant was stripped, an optional closest-match policy, and a record of every lookup (the
// input to scene-driven stripping).
#ifndef KILN_RUNTIME_VARIANT_SELECTOR_H_
#define KILN_RUNTIME_VARIANT_SELECTOR_H_

#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "kiln/pack/reader.h"
#include "kiln/runtime/status.h"

namespace kiln::runtime {

enum class MissingVariantPolicy {
    kError,    // a missing variant is an error naming the closest variants present
    kClosest,  // take the closest variant (fewest keyword sets differing) and warn
};

struct VariantChoice {
    uint32_t variant = 0;  // index into the pack's variant table
    bool exact = true;
    std::string warning;  // set when a closest match was taken
};

class VariantSelector {
  public:
    VariantSelector(const pack::Pack& pack, MissingVariantPolicy policy)
        : pack_(&pack), policy_(policy) {}

    // O(log n): the key is built from the keywords (names in no keyword set of the pass are
    // ignored) and binary-searched in the pass's sorted variant table.
    std::optional<Error> Select(uint32_t pass,
                                const std::vector<std::string>& keywords,
                                VariantChoice& out);

    // Every Select() so far, grouped: (shader, pass, keywords) -> (count, found exactly).
    struct Usage {
        uint64_t count = 0;
        bool found = true;
    };
    using UsageKey = std::tuple<std::string, std::string, std::vector<std::string>>;
    const std::map<UsageKey, Usage>& usage() const { return usage_; }

  private:
    const pack::Pack* pack_;
    MissingVariantPolicy policy_;
    std::map<UsageKey, Usage> usage_;
};

// Keywords as messages show them: "A B C", or "(no keywords)".
std::string JoinKeywords(const std::vector<std::string>& keywords);

// The pass's display name: its Name, else its LightMode tag, else "#index".
std::string PassLabel(const pack::Pack& pack, uint32_t pass);

// Writes the usage of one or more selectors as JSON (kiln_usage 1), via a temporary file.
std::optional<Error> WriteUsageFile(const std::string& path,
                                    const std::vector<const VariantSelector*>& selectors);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_VARIANT_SELECTOR_H_
