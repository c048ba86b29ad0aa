// kiln diff OLD.kpack NEW.kpack [--max-added-variants N] [--max-added-bytes B] [--json]: variants
// and bytes added or removed per shader and pass, for CI: "+48 variants, +310 KiB", and which
// keyword sets those variants are ("+ POINT SHADOWS_CUBE"). A pass's bytes are the SPIR-V of the
// distinct modules its variants use; the total is the packs' file sizes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "kiln/base/text.h"
#include "kiln/pack/pass_id.h"
#include "kiln/pack/variant_selector.h"

namespace kiln::cli {
namespace {

using namespace kiln::pack;

struct PassSize {
    uint64_t variants = 0, bytes = 0;
    std::set<std::string> keyword_sets;  // each variant's, as kiln variants spells it
};

// Keyword sets listed per pass and direction in the text output; --json lists every one.
constexpr size_t kListedSets = 16;
using Sizes = std::map<std::pair<std::string, std::string>, PassSize>;  // (shader, pass)

Sizes SizesOf(const Pack& p) {
    Sizes out;
    for (uint32_t pass = 0; pass < p.Count(SectionTag::kPasses); ++pass) {
        const PassRec rec = p.Pass(pass).value();
        PassSize& size =
            out[{std::string(p.String(p.Shader(rec.shader).value().name)), PassLabel(p, pass)}];
        size.variants = rec.variant_count;
        std::set<uint32_t> modules;
        for (uint32_t v = rec.first_variant; v < rec.first_variant + rec.variant_count; ++v) {
            const VariantRec vr = p.Variant(v).value();
            modules.insert({vr.vertex_module, vr.fragment_module});
            // Pack strings are untrusted bytes: escaped as diagnostics escape them.
            size.keyword_sets.insert(
                base::EscapeForTerminal(JoinKeywords(p.KeywordsOf(pass, VariantKey(vr.key)))));
        }
        for (uint32_t m : modules)
            size.bytes += p.Module(m).value().spirv_size;
    }
    return out;
}

std::string Signed(int64_t n, const char* unit) {
    return (n > 0 ? "+" : "") + std::to_string(n) + unit;
}

// The sets in `a` and not in `b`, sorted.
std::vector<std::string> Minus(const std::set<std::string>& a, const std::set<std::string>& b) {
    std::vector<std::string> out;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

// "  + POINT\n" per set, at most kListedSets of them, then how many more.
std::string ListSets(const std::vector<std::string>& sets, char sign, const char* what) {
    std::string out;
    for (size_t i = 0; i < sets.size() && i < kListedSets; ++i)
        out += std::string("  ") + sign + " " + sets[i] + "\n";
    if (sets.size() > kListedSets) {
        out += "  ... " + std::to_string(sets.size() - kListedSets) + " more " + what +
               " (--json lists every one)\n";
    }
    return out;
}

// "+310 KiB", "-2.5 KiB", "+0 KiB".
std::string KiB(int64_t bytes) {
    char buf[64];
    const double k = double(bytes) / 1024.0;
    const bool whole = std::floor(k) == k || std::abs(k) >= 100;
    std::snprintf(buf, sizeof buf, whole ? "%+.0f KiB" : "%+.1f KiB", k);
    return buf;
}

}  // namespace

std::function<int()> AddDiffCommand(CLI::App* cmd, const GlobalOptions& global) {
    struct Options {
        std::string old_pack, new_pack;
        int64_t max_variants = -1, max_bytes = -1;
        bool json = false;
    };
    auto o = std::make_shared<Options>();
    cmd->add_option("old", o->old_pack, "The pack before")->required();
    cmd->add_option("new", o->new_pack, "The pack after")->required();
    cmd->add_option("--max-added-variants", o->max_variants,
                    "Fail (exit 1) when the new pack has more than N variants more in all")
        ->check(CLI::NonNegativeNumber.description(""))
        ->option_text("N");
    cmd->add_option("--max-added-bytes", o->max_bytes,
                    "Fail (exit 1) when the new pack file is more than B bytes larger")
        ->check(CLI::NonNegativeNumber.description(""))
        ->option_text("B");
    cmd->add_flag("--json", o->json, "Print JSON");
    return [o, &global]() {
        MappedFile old_file, new_file;
        Pack old_pack, new_pack;
        if (!OpenPack(o->old_pack, old_file, old_pack, global) ||
            !OpenPack(o->new_pack, new_file, new_pack, global)) {
            return int(kExitInputError);
        }
        const Sizes before = SizesOf(old_pack), after = SizesOf(new_pack);
        std::set<std::pair<std::string, std::string>> keys;
        for (const auto& [k, v] : before)
            keys.insert(k);
        for (const auto& [k, v] : after)
            keys.insert(k);
        nlohmann::ordered_json passes = nlohmann::ordered_json::array();
        int64_t added_variants = 0;
        std::string text;
        for (const auto& key : keys) {
            const auto b = before.find(key), a = after.find(key);
            const PassSize was = b == before.end() ? PassSize{} : b->second;
            const PassSize now = a == after.end() ? PassSize{} : a->second;
            const int64_t dv = int64_t(now.variants) - int64_t(was.variants);
            const int64_t db = int64_t(now.bytes) - int64_t(was.bytes);
            added_variants += dv;
            const std::vector<std::string> gained = Minus(now.keyword_sets, was.keyword_sets);
            const std::vector<std::string> lost = Minus(was.keyword_sets, now.keyword_sets);
            const char* status = b == before.end()                              ? "added"
                                 : a == after.end()                             ? "removed"
                                 : dv || db || !gained.empty() || !lost.empty() ? "changed"
                                                                                : "unchanged";
            // Pack strings are untrusted bytes: escaped as diagnostics escape them.
            const std::string shader = base::EscapeForTerminal(key.first);
            const std::string pass = base::EscapeForTerminal(key.second);
            passes.push_back({{"shader", shader},
                              {"pass", pass},
                              {"status", status},
                              {"variants", {{"old", was.variants}, {"new", now.variants}}},
                              {"bytes", {{"old", was.bytes}, {"new", now.bytes}}},
                              {"keyword_sets", {{"added", gained}, {"removed", lost}}}});
            if (std::string(status) == "unchanged")
                continue;
            text += "shader \"" + shader + "\" pass \"" + pass + "\": " + Signed(dv, " variants") +
                    ", " + KiB(db) + " (" + status + ", " + std::to_string(was.variants) + " -> " +
                    std::to_string(now.variants) + " variants)\n" + ListSets(gained, '+', "added") +
                    ListSets(lost, '-', "removed");
        }
        const int64_t added_bytes =
            int64_t(new_file.bytes().size()) - int64_t(old_file.bytes().size());
        DiagnosticList diags = global.NewDiagnostics();
        if (o->max_variants >= 0 && added_variants > o->max_variants) {
            diags.Error(DiagCode::kPackGrowthOverBudget, o->new_pack, kNoPosition,
                        "the new pack has " + std::to_string(added_variants) +
                            " variants more than the old one, over the budget of " +
                            std::to_string(o->max_variants) + " (--max-added-variants)");
        }
        if (o->max_bytes >= 0 && added_bytes > o->max_bytes) {
            diags.Error(DiagCode::kPackGrowthOverBudget, o->new_pack, kNoPosition,
                        "the new pack is " + std::to_string(added_bytes) +
                            " bytes larger than the old one, over the budget of " +
                            std::to_string(o->max_bytes) + " (--max-added-bytes)");
        }
        if (o->json) {
            const nlohmann::ordered_json doc = {
                {"passes", passes},
                {"total",
                 {{"variants",
                   {{"old", old_pack.Count(SectionTag::kVariants)},
                    {"new", new_pack.Count(SectionTag::kVariants)}}},
                  {"bytes", {{"old", old_file.bytes().size()}, {"new", new_file.bytes().size()}}}}},
                {"over_budget", diags.has_errors()}};
            std::printf("%s\n", doc.dump(2).c_str());
        } else {
            std::printf("%stotal: %s, %s (pack %zu -> %zu bytes)\n", text.c_str(),
                        Signed(added_variants, " variants").c_str(), KiB(added_bytes).c_str(),
                        old_file.bytes().size(), new_file.bytes().size());
        }
        PrintDiagnostics(diags, {}, global);
        return ExitCodeFor(diags);
    };
}

}  // namespace kiln::cli
