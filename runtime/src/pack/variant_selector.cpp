#include "kiln/pack/variant_selector.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <tuple>

#include "kiln/base/files.h"
#include "kiln/pack/pass_id.h"

namespace kiln::pack {
namespace {

// Keyword sets whose chosen keyword differs between two keys of a pass.
uint32_t Distance(const Pack& pack, uint32_t pass, VariantKey a, VariantKey b) {
    const PassRec p = pack.Pass(pass).value();
    uint32_t d = 0;
    for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
        const KeywordSetRec set = pack.KeywordSet(s).value();
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

const VariantSelector::PassTable& VariantSelector::TableFor(uint32_t pass) {
    if (tables_.empty()) {
        tables_.resize(pack_->Count(SectionTag::kPasses));
    }
    PassTable& t = tables_[pass];
    if (t.built) {
        return t;
    }
    t.built = true;
    const PassRec p = pack_->Pass(pass).value();
    for (uint32_t s = 0; s < p.keyword_set_count; ++s) {
        const KeywordSetRec set = pack_->KeywordSet(p.first_keyword_set + s).value();
        t.sets.push_back(set);
        for (uint32_t k = 0; k < set.keyword_count; ++k) {
            const std::string_view kw = pack_->KeywordName(set.first_keyword + k);
            if (!kw.empty()) {
                t.keywords.push_back({kw, s, k});
            }
        }
    }
    std::sort(t.keywords.begin(), t.keywords.end(), [](const Declared& a, const Declared& b) {
        return std::tie(a.keyword, a.set, a.index) < std::tie(b.keyword, b.set, b.index);
    });
    return t;
}

VariantKey VariantSelector::KeyFor(uint32_t pass, const std::vector<std::string>& keywords) {
    // As Pack::KeyFor: in each set, the first of its keywords (in set order) that is enabled.
    const PassTable& t = TableFor(pass);
    constexpr uint32_t kUnset = ~0u;
    constexpr size_t kSmall = 64;
    uint32_t small[kSmall];
    std::vector<uint32_t> large;  // only for a pass of more than kSmall sets
    uint32_t* chosen = small;
    if (t.sets.size() > kSmall) {
        large.assign(t.sets.size(), kUnset);
        chosen = large.data();
    } else {
        std::fill_n(small, t.sets.size(), kUnset);
    }
    for (const std::string& k : keywords) {
        auto it = std::lower_bound(
            t.keywords.begin(), t.keywords.end(), std::string_view(k),
            [](const Declared& d, std::string_view name) { return d.keyword < name; });
        for (; it != t.keywords.end() && it->keyword == k; ++it) {
            chosen[it->set] = std::min(chosen[it->set], it->index);
        }
    }
    VariantKey key;
    for (size_t s = 0; s < t.sets.size(); ++s) {
        if (chosen[s] != kUnset) {
            key.Set(t.sets[s].key_shift, t.sets[s].key_bits, chosen[s]);
        }
    }
    return key;
}

std::map<VariantSelector::UsageKey, VariantSelector::Usage> VariantSelector::usage() const {
    std::map<UsageKey, Usage> out;
    for (const auto& [at, u] : usage_) {
        const auto [pass, bits] = at;
        const PassRec p = pack_->Pass(pass).value();
        const std::string shader(pack_->String(pack_->Shader(p.shader).value().name));
        out[{shader, PassLabel(*pack_, pass), pack_->KeywordsOf(pass, VariantKey(bits))}] = u;
    }
    return out;
}

Result<VariantChoice> VariantSelector::Select(uint32_t pass,
                                              const std::vector<std::string>& keywords,
                                              const std::string& requester) {
    const Pack& pack = *pack_;
    if (pass >= pack.Count(SectionTag::kPasses)) {
        return Error{DiagCode::kIndexOutOfRange,
                     "pass index " + std::to_string(pass) + " is out of range (the pack has " +
                         std::to_string(pack.Count(SectionTag::kPasses)) + " passes)"};
    }
    // A pack whose variant data is checked on first use reports its damage here, before any
    // variant or module of it is read (once; later calls find it checked).
    if (Status checked = pack.CheckVariantData(); !checked.ok())
        return checked.error();
    const VariantKey key = KeyFor(pass, keywords);
    Usage& usage = usage_[{pass, key.bits()}];
    ++usage.count;
    if (!requester.empty()) {
        AddRequester(usage.requested_by, usage.requesters, requester);
    }

    if (std::optional<uint32_t> v = pack.FindVariant(pass, key)) {
        return VariantChoice{*v, true, {}};
    }
    usage.found = false;
    const PassRec p = pack.Pass(pass).value();
    const std::string shader(pack.String(pack.Shader(p.shader).value().name));
    const std::string label = PassLabel(pack, pass);
    const std::vector<std::string> requested = pack.KeywordsOf(pass, key);
    // Closest present variants: fewest differing keyword sets, then lowest key.
    std::vector<std::pair<uint32_t, uint32_t>> ranked;  // (distance, variant)
    for (uint32_t v = p.first_variant; v < p.first_variant + p.variant_count; ++v) {
        ranked.emplace_back(Distance(pack, pass, key, VariantKey(pack.Variant(v).value().key)), v);
    }
    std::sort(ranked.begin(), ranked.end());
    std::string closest;
    for (size_t i = 0; i < ranked.size() && i < 3; ++i) {
        closest += std::string(i ? ", " : "") + "'" +
                   JoinKeywords(pack.KeywordsOf(
                       pass, VariantKey(pack.Variant(ranked[i].second).value().key))) +
                   "'";
    }
    const std::string what = "shader '" + shader + "' pass '" + label +
                             "' has no variant for keywords '" + JoinKeywords(requested) + "'";
    if (ranked.empty()) {
        return Error{DiagCode::kMissingVariant, what + " and no variants at all"};
    }
    if (policy_ == MissingVariantPolicy::kClosest) {
        return VariantChoice{ranked[0].second, false,
                             what + "; using the closest, " + closest.substr(0, closest.find(','))};
    }
    return Error{DiagCode::kMissingVariant,
                 what + " (stripped or never compiled); closest present: " + closest};
}

std::vector<UsageEntry> UsageOf(const std::vector<const VariantSelector*>& selectors) {
    std::vector<UsageEntry> out;
    for (const VariantSelector* s : selectors) {
        for (const auto& [key, usage] : s->usage()) {
            out.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), usage.count,
                           usage.found, usage.requested_by, usage.requesters});
        }
    }
    return out;
}

void AddRequester(std::vector<std::string>& requested_by,
                  uint64_t& requesters,
                  const std::string& reason) {
    ++requesters;
    if (requested_by.size() < kMaxRequestedBy &&
        std::find(requested_by.begin(), requested_by.end(), reason) == requested_by.end()) {
        requested_by.push_back(reason);
    }
}

std::string UsageFileText(const UsageLog& log) {
    nlohmann::ordered_json lookups = nlohmann::ordered_json::array();
    for (const UsageEntry& e : log.lookups) {
        nlohmann::ordered_json entry;
        entry["shader"] = e.shader;
        entry["pass"] = e.pass;
        entry["keywords"] = e.keywords;
        entry["count"] = e.count;
        entry["found"] = e.found;
        if (!e.requested_by.empty()) {
            entry["requested_by"] = e.requested_by;
            entry["requesters"] = e.requesters;
        }
        lookups.push_back(std::move(entry));
    }
    nlohmann::ordered_json doc;
    doc["kiln_usage"] = 1;
    doc["lookups"] = std::move(lookups);
    if (!log.materials.empty()) {
        nlohmann::ordered_json materials = nlohmann::ordered_json::array();
        for (const UsageMaterial& m : log.materials) {
            materials.push_back({{"material", m.material}, {"shader", m.shader}});
        }
        doc["materials"] = std::move(materials);
    }
    return doc.dump(2) + "\n";
}

namespace {

// A list of strings under `key` of `j`, when present; an error naming `at` otherwise.
Status ReadStrings(const nlohmann::json& j,
                   const char* key,
                   const std::string& at,
                   std::vector<std::string>& out) {
    if (!j.contains(key)) {
        return {};
    }
    if (!j[key].is_array()) {
        return Error{DiagCode::kBadUsageFile, at + ": \"" + key + "\" must be an array"};
    }
    for (const nlohmann::json& k : j[key]) {
        if (!k.is_string()) {
            return Error{DiagCode::kBadUsageFile,
                         at + ": each of \"" + key + "\" must be a string"};
        }
        out.push_back(k.get<std::string>());
    }
    return {};
}

Status ReadCount(const nlohmann::json& j, const char* key, const std::string& at, uint64_t& out) {
    if (!j.contains(key)) {
        return {};
    }
    if (!j[key].is_number_unsigned()) {
        return Error{DiagCode::kBadUsageFile,
                     at + ": \"" + key + "\" must be a non-negative integer"};
    }
    out = j[key].get<uint64_t>();
    return {};
}

Result<UsageEntry> ReadLookup(const nlohmann::json& j, const std::string& at) {
    if (!j.is_object() || !j.contains("shader") || !j["shader"].is_string() ||
        !j.contains("pass") || !j["pass"].is_string() || !j.contains("keywords") ||
        !j["keywords"].is_array()) {
        return Error{DiagCode::kBadUsageFile,
                     at + " needs \"shader\" and \"pass\" strings and a \"keywords\" array"};
    }
    UsageEntry e{j["shader"].get<std::string>(), j["pass"].get<std::string>(), {}, 0, true, {}, 0};
    for (Status s : {ReadStrings(j, "keywords", at, e.keywords), ReadCount(j, "count", at, e.count),
                     ReadStrings(j, "requested_by", at, e.requested_by),
                     ReadCount(j, "requesters", at, e.requesters)}) {
        if (!s.ok()) {
            return s.error();
        }
    }
    if (j.contains("found")) {
        if (!j["found"].is_boolean()) {
            return Error{DiagCode::kBadUsageFile, at + ": \"found\" must be true or false"};
        }
        e.found = j["found"].get<bool>();
    }
    return e;
}

}  // namespace

Result<UsageLog> ParseUsageFile(std::string_view text) {
    const nlohmann::json doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !doc.is_object()) {
        return Error{DiagCode::kBadUsageFile, "a usage file must be a JSON object"};
    }
    if (!doc.contains("kiln_usage") || doc["kiln_usage"] != 1) {
        return Error{DiagCode::kBadUsageFile,
                     "not a usage file of version 1 (no \"kiln_usage\": 1)"};
    }
    if (!doc.contains("lookups") || !doc["lookups"].is_array()) {
        return Error{DiagCode::kBadUsageFile, "a usage file needs a \"lookups\" array"};
    }
    UsageLog out;
    for (const nlohmann::json& j : doc["lookups"]) {
        Result<UsageEntry> e = ReadLookup(j, "lookup " + std::to_string(out.lookups.size() + 1));
        if (!e) {
            return e.error();
        }
        out.lookups.push_back(std::move(e).value());
    }
    if (doc.contains("materials")) {
        if (!doc["materials"].is_array()) {
            return Error{DiagCode::kBadUsageFile, "\"materials\" must be an array"};
        }
        for (const nlohmann::json& m : doc["materials"]) {
            if (!m.is_object() || !m.contains("material") || !m["material"].is_string() ||
                !m.contains("shader") || !m["shader"].is_string()) {
                return Error{DiagCode::kBadUsageFile,
                             "material " + std::to_string(out.materials.size() + 1) +
                                 " needs \"material\" and \"shader\" strings"};
            }
            out.materials.push_back(
                {m["material"].get<std::string>(), m["shader"].get<std::string>()});
        }
    }
    return out;
}

Status WriteUsageFile(const std::string& path, const UsageLog& log) {
    const std::string text = UsageFileText(log);
    return base::WriteFileAtomically(path, std::string_view(text));
}

}  // namespace kiln::pack
