#include "kiln/runtime/variant_selector.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "base/atomic_file.h"

namespace kiln::runtime {
namespace {

using pack::SectionTag;

// Keyword sets whose chosen keyword differs between two keys of a pass.
uint32_t Distance(const pack::Pack& pack, uint32_t pass, pack::VariantKey a, pack::VariantKey b) {
    const pack::PassRec p = pack.Pass(pass);
    uint32_t d = 0;
    for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
        const pack::KeywordSetRec set = pack.KeywordSet(s);
        d += a.Get(set.key_shift, set.key_bits) != b.Get(set.key_shift, set.key_bits);
    }
    return d;
}

}  // namespace

std::string JoinKeywords(const std::vector<std::string>& keywords) {
    if (keywords.empty()) {
        return "(no keywords)";
    }
    std::string out;
    for (const std::string& k : keywords) {
        out += (out.empty() ? "" : " ") + k;
    }
    return out;
}

std::string PassLabel(const pack::Pack& pack, uint32_t pass) {
    const pack::PassRec p = pack.Pass(pass);
    if (p.name.length) {
        return std::string(pack.String(p.name));
    }
    for (uint32_t i = 0; i < p.tag_count; ++i) {
        const auto tag = pack.Get<pack::TagRec>(SectionTag::kTags, p.first_tag + i);
        if (pack.String(tag.key) == "LightMode") {
            return std::string(pack.String(tag.value));
        }
    }
    return "#" + std::to_string(pass - pack.Shader(p.shader).first_pass);
}

std::optional<Error> VariantSelector::Select(uint32_t pass,
                                             const std::vector<std::string>& keywords,
                                             VariantChoice& out) {
    const pack::Pack& pack = *pack_;
    const pack::VariantKey key = pack.KeyFor(pass, keywords);
    const pack::PassRec p = pack.Pass(pass);
    const std::string shader(pack.String(pack.Shader(p.shader).name));
    const std::vector<std::string> requested = pack.KeywordsOf(pass, key);
    Usage& usage = usage_[{shader, PassLabel(pack, pass), requested}];
    ++usage.count;

    if (std::optional<uint32_t> v = pack.FindVariant(pass, key)) {
        out = VariantChoice{*v, true, {}};
        return std::nullopt;
    }
    usage.found = false;
    // Closest present variants: fewest differing keyword sets, then lowest key.
    std::vector<std::pair<uint32_t, uint32_t>> ranked;  // (distance, variant)
    for (uint32_t v = p.first_variant; v < p.first_variant + p.variant_count; ++v) {
        ranked.emplace_back(Distance(pack, pass, key, pack::VariantKey(pack.Variant(v).key)), v);
    }
    std::sort(ranked.begin(), ranked.end());
    std::string closest;
    for (size_t i = 0; i < ranked.size() && i < 3; ++i) {
        closest += std::string(i ? ", " : "") + "'" +
                   JoinKeywords(pack.KeywordsOf(
                       pass, pack::VariantKey(pack.Variant(ranked[i].second).key))) +
                   "'";
    }
    const std::string what = "shader '" + shader + "' pass '" + PassLabel(pack, pass) +
                             "' has no variant for keywords '" + JoinKeywords(requested) + "'";
    if (ranked.empty()) {
        return Error{what + " and no variants at all", ErrorKind::kMissingVariant};
    }
    if (policy_ == MissingVariantPolicy::kClosest) {
        out = VariantChoice{ranked[0].second, false,
                            what + "; using the closest, " + closest.substr(0, closest.find(','))};
        return std::nullopt;
    }
    return Error{what + " (stripped or never compiled); closest present: " + closest,
                 ErrorKind::kMissingVariant};
}

std::optional<Error> WriteUsageFile(const std::string& path,
                                    const std::vector<const VariantSelector*>& selectors) {
    nlohmann::ordered_json lookups = nlohmann::ordered_json::array();
    for (const VariantSelector* s : selectors) {
        for (const auto& [key, usage] : s->usage()) {
            nlohmann::ordered_json entry;
            entry["shader"] = std::get<0>(key);
            entry["pass"] = std::get<1>(key);
            entry["keywords"] = std::get<2>(key);
            entry["count"] = usage.count;
            entry["found"] = usage.found;
            lookups.push_back(std::move(entry));
        }
    }
    nlohmann::ordered_json doc;
    doc["kiln_usage"] = 1;
    doc["lookups"] = std::move(lookups);
    const std::string text = doc.dump(2) + "\n";
    return WriteFileAtomically(path, {reinterpret_cast<const uint8_t*>(text.data()), text.size()});
}

}  // namespace kiln::runtime
