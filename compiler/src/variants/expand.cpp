#include "variants/expand.h"

#include <algorithm>

namespace kiln::variants {

std::optional<std::vector<SetLayout>> LayoutSets(const std::vector<KeywordSet>& sets) {
    std::vector<SetLayout> layout;
    uint32_t shift = 0;
    for (const KeywordSet& s : sets) {
        const uint32_t bits = pack::BitsForCount(s.keywords.size());
        if (shift + bits > 64)
            return std::nullopt;
        layout.push_back({shift, bits});
        shift += bits;
    }
    return layout;
}

std::vector<std::string> EnabledKeywords(const std::vector<KeywordSet>& sets,
                                         const std::vector<SetLayout>& layout,
                                         pack::VariantKey key) {
    std::vector<std::string> out;
    for (size_t i = 0; i < sets.size() && i < layout.size(); ++i) {
        const uint32_t index = key.Get(layout[i].shift, layout[i].bits);
        if (index < sets[i].keywords.size() && !sets[i].keywords[index].empty()) {
            out.push_back(sets[i].keywords[index]);
        }
    }
    return out;
}

std::string DescribeKeywords(const std::vector<std::string>& keywords) {
    if (keywords.empty())
        return "(no keywords)";
    std::string s;
    for (const std::string& k : keywords)
        s += (s.empty() ? "" : " ") + k;
    return s;
}

std::optional<Expansion> ExpandVariants(const PassPragmas& pragmas,
                                        const VariantRequest& request,
                                        const std::string& pass_label,
                                        const std::string& file,
                                        SourceRange pass_range,
                                        DiagnosticList& diags) {
    Expansion ex;
    auto layout = LayoutSets(pragmas.sets);
    if (!layout) {
        diags.Error(
            DiagCode::kVariantKeyTooWide, file, pass_range,
            "keyword sets of pass " + pass_label +
                " need more than 64 bits of variant key; split the pass or use fewer keywords");
        return std::nullopt;
    }
    ex.layout = *layout;

    // Allowed choice indices per set.
    std::vector<std::vector<uint32_t>> choices;
    for (const KeywordSet& s : pragmas.sets) {
        std::vector<uint32_t> allowed;
        for (uint32_t i = 0; i < s.keywords.size(); ++i) {
            const bool feature = s.kind == pack::KeywordSetKind::kShaderFeature;
            // The first choice is what a material that enables none of the set's keywords gets.
            if (!feature || !request.shader_features || i == 0 ||
                request.shader_features->count(s.keywords[i])) {
                allowed.push_back(i);
            }
        }
        choices.push_back(std::move(allowed));
    }

    uint64_t product = 1;
    bool overflow = false;
    std::string formula;
    for (const auto& c : choices) {
        ex.effective_sizes.push_back(c.size());
        if (product > UINT64_MAX / c.size()) {
            overflow = true;
        } else {
            product *= c.size();
        }
        if (c.size() > 1)
            formula += (formula.empty() ? "" : " x ") + std::to_string(c.size());
    }
    ex.permutations = overflow ? UINT64_MAX : product;
    if (overflow || product > request.max_variants) {
        auto& d =
            diags.Error(DiagCode::kTooManyVariants, file, pass_range,
                        (formula.empty() ? std::string("1") : formula) + " = " +
                            (overflow ? std::string("more than 2^64") : std::to_string(product)) +
                            " variants in pass " + pass_label + ", over the limit of " +
                            std::to_string(request.max_variants) + " (--max-variants)");
        for (const KeywordSet& s : pragmas.sets) {
            if (s.keywords.size() > 1) {
                d.notes.push_back({file, s.range,
                                   std::to_string(s.keywords.size()) + " choices from '#pragma " +
                                       s.pragma + "'"});
            }
        }
        return std::nullopt;
    }

    std::set<std::string> skip;
    for (const auto& a : pragmas.skip_variants)
        skip.insert(a.text);
    std::vector<uint32_t> index(choices.size(), 0);
    while (true) {
        pack::VariantKey key;
        bool skipped = false;
        for (size_t s = 0; s < choices.size(); ++s) {
            const uint32_t k = choices[s][index[s]];
            key.Set(ex.layout[s].shift, ex.layout[s].bits, k);
            skipped = skipped || skip.count(pragmas.sets[s].keywords[k]) > 0;
        }
        if (!skipped)
            ex.keys.push_back(key);
        size_t s = 0;
        for (; s < choices.size(); ++s) {
            if (++index[s] < choices[s].size())
                break;
            index[s] = 0;
        }
        if (s == choices.size())
            break;
    }
    std::sort(ex.keys.begin(), ex.keys.end());
    if (ex.keys.empty()) {
        diags.Error(DiagCode::kNoVariantsLeft, file, pass_range,
                    "skip_variants removes every variant of pass " + pass_label);
        return std::nullopt;
    }
    return ex;
}

}  // namespace kiln::variants
