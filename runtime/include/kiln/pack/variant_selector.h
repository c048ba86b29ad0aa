// Picking the compiled variant for (shader, pass, enabled keywords), with a clear error when a
// variant was stripped, an optional closest-match policy, and a record of every lookup: the usage
// file (kiln_usage 1), the input to scene-driven stripping. Needs only the pack reader: an engine
// links kiln::pack for this, without Vulkan, OpenColorIO or tinygltf.
#ifndef KILN_PACK_VARIANT_SELECTOR_H_
#define KILN_PACK_VARIANT_SELECTOR_H_

#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "kiln/pack/reader.h"
#include "kiln/result.h"

namespace kiln::pack {

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
    VariantSelector(const Pack& pack, MissingVariantPolicy policy)
        : pack_(&pack), policy_(policy) {}

    // O(log n): the key is built from the keywords (names in no keyword set of the pass are
    // ignored, as Unity ignores them) and binary-searched in the pass's sorted variant table. An
    // error for a pass index out of range, and (kError) for a variant the pack lacks.
    Result<VariantChoice> Select(uint32_t pass, const std::vector<std::string>& keywords);

    // Every Select() so far, grouped: (shader, pass's PassLabel, keywords) -> (count, found).
    struct Usage {
        uint64_t count = 0;
        bool found = true;
    };
    using UsageKey = std::tuple<std::string, std::string, std::vector<std::string>>;
    const std::map<UsageKey, Usage>& usage() const { return usage_; }

  private:
    const Pack* pack_;
    MissingVariantPolicy policy_;
    std::map<UsageKey, Usage> usage_;
};

// Keywords as messages show them: "A B C", or "(no keywords)".
std::string JoinKeywords(const std::vector<std::string>& keywords);

// One line of a usage file.
struct UsageEntry {
    std::string shader, pass;  // pass: its PassLabel (kiln/pack/pass_id.h)
    std::vector<std::string> keywords;
    uint64_t count = 0;
    bool found = true;
};

std::vector<UsageEntry> UsageOf(const std::vector<const VariantSelector*>& selectors);
// The usage file's text (JSON, kiln_usage 1) and its reader; the reader rejects anything else
// with a message naming what is wrong.
std::string UsageFileText(const std::vector<UsageEntry>& entries);
Result<std::vector<UsageEntry>> ParseUsageFile(std::string_view text);
// Writes UsageFileText via a temporary file (kiln/base/files.h).
Status WriteUsageFile(const std::string& path, const std::vector<UsageEntry>& entries);

}  // namespace kiln::pack

#endif  // KILN_PACK_VARIANT_SELECTOR_H_
