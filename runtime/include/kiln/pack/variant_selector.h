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
#include <unordered_map>
#include <utility>
#include <vector>

#include "kiln/pack/reader.h"
#include "kiln/result.h"

namespace kiln::pack {

enum class MissingVariantPolicy {
    kError,    // a missing variant is an error naming the closest variants present
    kClosest,  // take the closest variant (fewest keyword sets differing) and warn
};

// Who asked for a lookup: at most this many distinct requesters are kept per lookup.
inline constexpr size_t kMaxRequestedBy = 16;

struct VariantChoice {
    uint32_t variant = 0;  // index into the pack's variant table
    bool exact = true;
    std::string warning;  // set when a closest match was taken
};

class VariantSelector {
  public:
    VariantSelector(const Pack& pack, MissingVariantPolicy policy)
        : pack_(&pack), policy_(policy) {}

    // O(k log m + log n) for k keywords, m keywords declared by the pass and n variants: each
    // keyword is looked up in the pass's sorted keyword table (built on the pass's first lookup;
    // names in no keyword set of the pass are ignored, as Unity ignores them) and the key is
    // binary-searched in the pass's sorted variant table. A found variant allocates nothing after
    // the first lookup of the same key (without a requester). An error for a pass index out of
    // range, and (kError) for a variant the pack lacks. `requester`, when not empty, is recorded
    // with the lookup (who asked: a planned frame's "material on node: light").
    Result<VariantChoice> Select(uint32_t pass,
                                 const std::vector<std::string>& keywords,
                                 const std::string& requester = {});
    // The key Select builds for `keywords` (Pack::KeyFor's, from the cached table).
    VariantKey KeyFor(uint32_t pass, const std::vector<std::string>& keywords);

    // Every Select() so far, grouped: (shader, pass's PassLabel, keywords) -> (count, found,
    // who asked).
    struct Usage {
        uint64_t count = 0;
        bool found = true;
        std::vector<std::string> requested_by;  // at most kMaxRequestedBy, distinct
        uint64_t requesters = 0;
    };
    using UsageKey = std::tuple<std::string, std::string, std::vector<std::string>>;
    std::map<UsageKey, Usage> usage() const;

  private:
    // A pass's declared keywords, sorted by name: (keyword, set's index within the pass, the
    // keyword's index within its set).
    struct Declared {
        std::string_view keyword;
        uint32_t set = 0, index = 0;
    };
    struct PassTable {
        bool built = false;
        std::vector<Declared> keywords;
        std::vector<KeywordSetRec> sets;  // the pass's, in order
    };
    const PassTable& TableFor(uint32_t pass);
    struct KeyHash {
        size_t operator()(const std::pair<uint32_t, uint64_t>& k) const {
            return std::hash<uint64_t>()(k.second * 0x9E3779B97F4A7C15ull ^ k.first);
        }
    };

    const Pack* pack_;
    MissingVariantPolicy policy_;
    std::vector<PassTable> tables_;  // per pass
    // (pass, key) -> usage: strings are made when usage() is read, not per lookup.
    std::unordered_map<std::pair<uint32_t, uint64_t>, Usage, KeyHash> usage_;
};

// Keywords as messages show them: "A B C", or "(no keywords)".
std::string JoinKeywords(const std::vector<std::string>& keywords);

// One line of a usage file: a (shader, pass, keywords) lookup, how often it was made and whether
// the pack had the variant. `requested_by` says who asked (a planned frame fills it: "material on
// node: which light"); at most kMaxRequestedBy distinct entries are kept, `requesters` counts all.
struct UsageEntry {
    std::string shader, pass;  // pass: its PassLabel (kiln/pack/pass_id.h)
    std::vector<std::string> keywords;
    uint64_t count = 0;
    bool found = true;
    std::vector<std::string> requested_by;
    uint64_t requesters = 0;
};

// A material instance a frame resolved, and the shader it uses: stripping keeps such a shader
// even when none of its passes is drawn, so the stripped pack renders as the full one does.
struct UsageMaterial {
    std::string material, shader;
    friend bool operator==(const UsageMaterial&, const UsageMaterial&) = default;
    friend auto operator<=>(const UsageMaterial&, const UsageMaterial&) = default;
};

// A usage file (kiln_usage 1): the lookups, then the materials (optional in the file).
struct UsageLog {
    std::vector<UsageEntry> lookups;
    std::vector<UsageMaterial> materials;
};

std::vector<UsageEntry> UsageOf(const std::vector<const VariantSelector*>& selectors);
// Adds a requester to a lookup: counted, and kept when new and fewer than kMaxRequestedBy are.
void AddRequester(std::vector<std::string>& requested_by,
                  uint64_t& requesters,
                  const std::string& reason);
// The usage file's text (JSON, kiln_usage 1) and its reader; the reader rejects anything else
// with a message naming what is wrong.
std::string UsageFileText(const UsageLog& log);
Result<UsageLog> ParseUsageFile(std::string_view text);
// Writes UsageFileText via a temporary file (kiln/base/files.h).
Status WriteUsageFile(const std::string& path, const UsageLog& log);

}  // namespace kiln::pack

#endif  // KILN_PACK_VARIANT_SELECTOR_H_
