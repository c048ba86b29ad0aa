// kiln compile --scene ... --explain / --explain-json: per pass, the variants kept with who asked
// for them, those looked up but not built and why, and how many were left out; then the shaders
// left out and what the stripping saved.
#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "kiln/pack/variant_selector.h"

namespace kiln::cli {
namespace {

std::string Count(uint64_t n) {
    return n == UINT64_MAX ? std::string("more than 2^64") : std::to_string(n);
}

// What the stripping saved, estimated from this compile: the variants left out of the keyword
// combinations the passes declare, at this compile's bytes per variant (the pack less the same
// pack without variants, over the variants kept) and seconds per stage program. Estimates, and
// said to be.
struct Savings {
    uint64_t declared = 0, kept = 0;
    double bytes_per_variant = 0, seconds_per_program = 0;
};

Savings Estimate(const CompileOutput& out, double seconds, size_t skeleton_bytes) {
    Savings s;
    for (const PassReport& p : out.passes) {
        s.declared =
            s.declared > UINT64_MAX - p.permutations ? UINT64_MAX : s.declared + p.permutations;
        s.kept += p.variants;
    }
    if (s.kept > 0) {
        s.bytes_per_variant =
            double(out.pack.size() - std::min(out.pack.size(), skeleton_bytes)) / double(s.kept);
    }
    if (out.stats.stage_programs > 0) {
        s.seconds_per_program = seconds / double(out.stats.stage_programs);
    }
    return s;
}

void PrintText(const CompileOutput& out, double seconds, size_t skeleton_bytes) {
    for (const PassReport& p : out.passes) {
        std::printf("shader \"%s\" pass \"%s\": kept %zu of %s keyword combinations\n",
                    p.shader.c_str(), p.pass.c_str(), p.variants, Count(p.permutations).c_str());
        for (const RequestedVariantReport& v : p.kept) {
            std::printf("  kept %s: %llu lookup%s\n", pack::JoinKeywords(v.keywords).c_str(),
                        static_cast<unsigned long long>(v.requesters),
                        v.requesters == 1 ? "" : "s");
            for (const std::string& who : v.requested_by) {
                std::printf("    asked by %s\n", who.c_str());
            }
            if (v.requesters > v.requested_by.size()) {
                std::printf("    and %llu more lookups\n",
                            static_cast<unsigned long long>(v.requesters - v.requested_by.size()));
            }
        }
        for (const RequestedVariantReport& v : p.excluded) {
            std::printf("  not built %s: %s\n", pack::JoinKeywords(v.keywords).c_str(),
                        v.excluded_because.c_str());
        }
        if (p.variants == 0) {
            std::printf("  left out: no lookup of the scene draws this pass\n");
        }
    }
    for (const std::string& s : out.strip.shaders_left_out) {
        std::printf("shader \"%s\": left out, no material of the scene uses it\n", s.c_str());
    }
    for (const auto& [shader, n] : out.strip.other_shaders) {
        std::printf("shader \"%s\": %zu lookup%s, not in this compile (another pack's)\n",
                    shader.c_str(), n, n == 1 ? "" : "s");
    }
    const Savings s = Estimate(out, seconds, skeleton_bytes);
    const uint64_t left = s.declared == UINT64_MAX ? UINT64_MAX : s.declared - s.kept;
    std::printf(
        "kept %llu variants of %s declared keyword combinations; pack %zu bytes; "
        "%zu stage programs in %.2f s\n",
        static_cast<unsigned long long>(s.kept), Count(s.declared).c_str(), out.pack.size(),
        out.stats.stage_programs, seconds);
    if (left != UINT64_MAX && left > 0) {
        std::printf(
            "left out %llu variants: up to about %.0f KiB and %.1f s of compiling saved "
            "(estimated at this compile's %.1f KiB per variant and %.1f ms per stage "
            "program)\n",
            static_cast<unsigned long long>(left), double(left) * s.bytes_per_variant / 1024.0,
            double(left) * 2.0 * s.seconds_per_program, s.bytes_per_variant / 1024.0,
            s.seconds_per_program * 1000.0);
    }
}

nlohmann::ordered_json VariantsJson(const std::vector<RequestedVariantReport>& list) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const RequestedVariantReport& v : list) {
        nlohmann::ordered_json j = {
            {"keywords", v.keywords}, {"lookups", v.requesters}, {"requested_by", v.requested_by}};
        if (!v.excluded_because.empty()) {
            j["not_built_because"] = v.excluded_because;
        }
        out.push_back(std::move(j));
    }
    return out;
}

void PrintJson(const CompileOutput& out, double seconds, size_t skeleton_bytes) {
    nlohmann::ordered_json passes = nlohmann::ordered_json::array();
    for (const PassReport& p : out.passes) {
        passes.push_back({{"shader", p.shader},
                          {"pass", p.pass},
                          {"declared_combinations", p.permutations},
                          {"kept", VariantsJson(p.kept)},
                          {"not_built", VariantsJson(p.excluded)}});
    }
    nlohmann::ordered_json others = nlohmann::ordered_json::array();
    for (const auto& [shader, n] : out.strip.other_shaders) {
        others.push_back({{"shader", shader}, {"lookups", n}});
    }
    const Savings s = Estimate(out, seconds, skeleton_bytes);
    nlohmann::ordered_json doc = {{"passes", passes},
                                  {"shaders_left_out", out.strip.shaders_left_out},
                                  {"other_shaders", others},
                                  {"kept_variants", s.kept},
                                  {"declared_combinations", s.declared},
                                  {"pack_bytes", out.pack.size()},
                                  {"stage_programs", out.stats.stage_programs},
                                  {"seconds", seconds},
                                  {"estimated",
                                   {{"bytes_per_variant", s.bytes_per_variant},
                                    {"seconds_per_stage_program", s.seconds_per_program}}}};
    const std::string text = doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
    std::printf("%s\n", text.c_str());
}

}  // namespace

void PrintExplain(const SceneStripFlags& flags,
                  const CompileOutput& out,
                  double seconds,
                  size_t skeleton_bytes) {
    if (flags.explain_json) {
        PrintJson(out, seconds, skeleton_bytes);
    } else if (flags.explain) {
        PrintText(out, seconds, skeleton_bytes);
    }
}

}  // namespace kiln::cli
