#include "variants/expand.h"

#include <algorithm>
#include <set>

#include "variants/strip_profile.h"

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

namespace {

// LayoutSets, or K4011 when the sets need more than 64 bits.
std::optional<std::vector<SetLayout>> LayoutOrReport(const PassPragmas& pragmas,
                                                     const std::string& pass_label,
                                                     const std::string& file,
                                                     SourceRange pass_range,
                                                     DiagnosticList& diags) {
    auto layout = LayoutSets(pragmas.sets);
    if (!layout) {
        diags.Error(
            DiagCode::kVariantKeyTooWide, file, pass_range,
            "keyword sets of pass " + pass_label +
                " need more than 64 bits of variant key; split the pass or use fewer keywords");
    }
    return layout;
}

}  // namespace

pack::VariantKey KeyForKeywords(const std::vector<KeywordSet>& sets,
                                const std::vector<SetLayout>& layout,
                                const std::vector<std::string>& enabled) {
    pack::VariantKey key;
    for (size_t s = 0; s < sets.size() && s < layout.size(); ++s) {
        const auto& kws = sets[s].keywords;
        for (uint32_t k = 0; k < kws.size(); ++k) {
            if (!kws[k].empty() &&
                std::find(enabled.begin(), enabled.end(), kws[k]) != enabled.end()) {
                key.Set(layout[s].shift, layout[s].bits, k);
                break;
            }
        }
    }
    return key;
}

std::string ExclusionReason(const PassPragmas& pragmas, const std::vector<std::string>& enabled) {
    for (const auto& a : pragmas.skip_variants) {
        if (std::find(enabled.begin(), enabled.end(), a.text) != enabled.end())
            return "'#pragma skip_variants' names '" + a.text + "'";
    }
    const KeywordRule* rule = BrokenRule(pragmas.rules, enabled);
    if (!rule)
        return "";
    auto list = [](const std::vector<std::string>& words) {
        std::string out;
        for (const std::string& w : words)
            out += (out.empty() ? "" : ", ") + w;
        return out;
    };
    std::string why = "'#pragma " + rule->pragma + "' never builds " + rule->keyword;
    if (!rule->any_of.empty())
        why += " without one of " + list(rule->any_of);
    if (!rule->none_of.empty())
        why += (rule->any_of.empty() ? " with any of " : ", or with any of ") + list(rule->none_of);
    return why;
}

std::optional<Expansion> ExpandRequested(const PassPragmas& pragmas,
                                         const std::vector<std::vector<std::string>>& requests,
                                         uint64_t max_variants,
                                         const std::string& pass_label,
                                         const std::string& file,
                                         SourceRange pass_range,
                                         DiagnosticList& diags,
                                         std::vector<ExcludedRequest>& excluded) {
    Expansion ex;
    auto layout = LayoutOrReport(pragmas, pass_label, file, pass_range, diags);
    if (!layout)
        return std::nullopt;
    ex.layout = *layout;
    ex.permutations = 1;
    for (const KeywordSet& set : pragmas.sets) {
        const uint64_t n = std::max<size_t>(set.keywords.size(), 1);
        ex.effective_sizes.push_back(set.keywords.size());
        ex.permutations = ex.permutations > UINT64_MAX / n ? UINT64_MAX : ex.permutations * n;
        if (n > 1)
            ex.formula += (ex.formula.empty() ? "" : " x ") + std::to_string(n);
    }
    if (ex.formula.empty())
        ex.formula = "1";
    for (size_t r = 0; r < requests.size(); ++r) {
        const pack::VariantKey key = KeyForKeywords(pragmas.sets, ex.layout, requests[r]);
        const std::vector<std::string> enabled = EnabledKeywords(pragmas.sets, ex.layout, key);
        if (std::string why = ExclusionReason(pragmas, enabled); !why.empty()) {
            excluded.push_back({r, enabled, std::move(why)});
            continue;
        }
        ex.keys.push_back(key);
    }
    std::sort(ex.keys.begin(), ex.keys.end());
    ex.keys.erase(std::unique(ex.keys.begin(), ex.keys.end()), ex.keys.end());
    if (ex.keys.size() > max_variants) {
        diags.Error(DiagCode::kTooManyVariants, file, pass_range,
                    std::to_string(ex.keys.size()) + " variants requested for pass " + pass_label +
                        ", over the limit of " + std::to_string(max_variants) +
                        " (--max-variants)");
        return std::nullopt;
    }
    return ex;
}

namespace {

// Per keyword set, per choice: whether the default profile (variants/strip_profile.h) strips it.
// Only multi_compile choices (shader_feature ones come from materials, which ask for them), never
// a keyword a feature combination names, and never every choice of a set. Records the stripped
// keywords in `ex`.
template <class IsFeature>
std::vector<std::vector<bool>> ProfileChoices(const PassPragmas& pragmas,
                                              const VariantRequest& request,
                                              IsFeature is_feature,
                                              Expansion& ex) {
    std::vector<std::vector<bool>> out(pragmas.sets.size());
    if (request.strict_variants)
        return out;
    for (size_t s = 0; s < pragmas.sets.size(); ++s) {
        if (is_feature(s))
            continue;
        const std::vector<std::string>& kws = pragmas.sets[s].keywords;
        std::vector<bool> strip(kws.size(), false);
        for (size_t i = 0; i < kws.size(); ++i) {
            strip[i] = !kws[i].empty() && StrippedByDefault(kws[i]) != nullptr &&
                       std::none_of(
                           request.feature_combinations.begin(), request.feature_combinations.end(),
                           [&](const std::set<std::string>& c) { return c.count(kws[i]); });
        }
        if (std::all_of(strip.begin(), strip.end(), [](bool b) { return b; }))
            continue;  // a set keeps a choice
        for (size_t i = 0; i < kws.size(); ++i) {
            if (strip[i] && std::find(ex.profile_keywords.begin(), ex.profile_keywords.end(),
                                      kws[i]) == ex.profile_keywords.end())
                ex.profile_keywords.push_back(kws[i]);
        }
        out[s] = std::move(strip);
    }
    return out;
}

}  // namespace

std::optional<Expansion> ExpandVariants(const PassPragmas& pragmas,
                                        const VariantRequest& request,
                                        const std::string& pass_label,
                                        const std::string& file,
                                        SourceRange pass_range,
                                        DiagnosticList& diags) {
    Expansion ex;
    auto layout = LayoutOrReport(pragmas, pass_label, file, pass_range, diags);
    if (!layout)
        return std::nullopt;
    ex.layout = *layout;

    // Choices: every index of a multi_compile set (and of shader_feature sets with
    // --all-features); shader_feature choices come as whole combinations otherwise.
    const size_t n = pragmas.sets.size();
    auto is_feature = [&](size_t s) {
        return !request.all_features &&
               pragmas.sets[s].kind == pack::KeywordSetKind::kShaderFeature;
    };
    std::vector<std::vector<uint32_t>> choices(n);
    for (size_t s = 0; s < n; ++s) {
        if (!is_feature(s)) {
            for (uint32_t i = 0; i < pragmas.sets[s].keywords.size(); ++i)
                choices[s].push_back(i);
        }
    }
    // One combination per material: in each shader_feature set, the first keyword the material
    // enables, else the set's first choice (what a material that enables none of them gets).
    std::set<std::vector<uint32_t>> combos = {std::vector<uint32_t>(n, 0)};
    for (const std::set<std::string>& enabled : request.feature_combinations) {
        std::vector<uint32_t> combo(n, 0);
        for (size_t s = 0; s < n; ++s) {
            const auto& kws = pragmas.sets[s].keywords;
            for (uint32_t i = 0; is_feature(s) && i < kws.size(); ++i) {
                if (!kws[i].empty() && enabled.count(kws[i])) {
                    combo[s] = i;
                    break;
                }
            }
        }
        combos.insert(combo);
    }
    ex.feature_combinations = combos.size();

    uint64_t product = combos.size();
    bool overflow = false;
    std::string formula;
    for (size_t s = 0; s < n; ++s) {
        std::set<uint32_t> used;
        if (is_feature(s)) {
            for (const auto& c : combos)
                used.insert(c[s]);
        }
        const size_t size = is_feature(s) ? used.size() : choices[s].size();
        ex.effective_sizes.push_back(size);
        if (is_feature(s) || size <= 1)
            continue;
        if (product > UINT64_MAX / size) {
            overflow = true;
        } else {
            product *= size;
        }
        formula += (formula.empty() ? "" : " x ") + std::to_string(size);
    }
    if (combos.size() > 1) {
        formula += (formula.empty() ? "" : " x ") + std::to_string(combos.size()) +
                   " shader_feature combinations";
    }
    ex.permutations = overflow ? UINT64_MAX : product;
    ex.formula = formula.empty() ? std::string("1") : formula;
    // The limit applies to the variants actually built: the product less what the shortcut rules
    // and skip_variants exclude. Enumerating is cheap up to a few million combinations; beyond
    // that (and beyond the limit itself) the product alone decides.
    const uint64_t enumerable = std::max<uint64_t>(uint64_t{1} << 22, request.max_variants);
    auto too_many = [&](uint64_t built) {
        std::string count = overflow ? std::string("more than 2^64") : std::to_string(product);
        std::string message = (formula.empty() ? std::string("1") : formula) + " = " + count +
                              " variants in pass " + pass_label;
        if (built != product) {
            message = std::to_string(built) + " variants in pass " + pass_label + " (" +
                      (formula.empty() ? std::string("1") : formula) + " = " + count +
                      " keyword combinations, less those the shortcut rules and skip_variants "
                      "exclude)";
        }
        auto& d = diags.Error(DiagCode::kTooManyVariants, file, pass_range,
                              message + ", over the limit of " +
                                  std::to_string(request.max_variants) + " (--max-variants)");
        for (size_t s = 0; s < n; ++s) {
            if (!is_feature(s) && pragmas.sets[s].keywords.size() > 1) {
                d.notes.push_back({file, pragmas.sets[s].range,
                                   std::to_string(pragmas.sets[s].keywords.size()) +
                                       " choices from '#pragma " + pragmas.sets[s].pragma + "'"});
            }
        }
    };
    if (overflow || product > enumerable) {
        too_many(product);
        return std::nullopt;
    }

    std::set<std::string> skip;
    for (const auto& a : pragmas.skip_variants)
        skip.insert(a.text);
    const std::vector<std::vector<bool>> profile = ProfileChoices(pragmas, request, is_feature, ex);
    // The multi_compile product (features fixed per combination), odometer order. Past the limit
    // keys are only counted, for the message.
    uint64_t built = 0;
    std::vector<std::string> enabled;
    for (const std::vector<uint32_t>& combo : combos) {
        std::vector<size_t> index(n, 0);
        while (true) {
            pack::VariantKey key;
            bool skipped = false, stripped = false;
            enabled.clear();
            for (size_t s = 0; s < n; ++s) {
                const uint32_t k = is_feature(s) ? combo[s] : choices[s][index[s]];
                key.Set(ex.layout[s].shift, ex.layout[s].bits, k);
                const std::string& kw = pragmas.sets[s].keywords[k];
                skipped = skipped || skip.count(kw) > 0;
                stripped = stripped || (!profile[s].empty() && profile[s][k]);
                if (!kw.empty())
                    enabled.push_back(kw);
            }
            if (!skipped && SatisfiesRules(pragmas.rules, enabled)) {
                if (stripped) {
                    ++ex.profile_stripped;
                } else if (++built <= request.max_variants) {
                    ex.keys.push_back(key);
                }
            }
            size_t s = 0;
            for (; s < n; ++s) {
                if (is_feature(s))
                    continue;
                if (++index[s] < choices[s].size())
                    break;
                index[s] = 0;
            }
            if (s == n)
                break;
        }
    }
    if (built > request.max_variants) {
        too_many(built);
        return std::nullopt;
    }
    std::sort(ex.keys.begin(), ex.keys.end());
    ex.keys.erase(std::unique(ex.keys.begin(), ex.keys.end()), ex.keys.end());
    if (ex.keys.empty()) {
        diags.Error(DiagCode::kNoVariantsLeft, file, pass_range,
                    std::string(ex.profile_stripped > 0
                                    ? "skip_variants and the default stripping profile remove "
                                      "(--strict-variants keeps the profile's)"
                                    : "skip_variants removes") +
                        " every variant of pass " + pass_label);
        return std::nullopt;
    }
    return ex;
}

}  // namespace kiln::variants
