// Stripped compiles (CompileOptions::requests): lookups recorded by the runtime, or planned for a
// scene, become the exact variants of each pass; shaders nobody uses are left out. Skeleton packs
// are the same expansion with no requests.
#include <algorithm>
#include <map>
#include <set>

#include "driver/compile_state.h"
#include "kiln/pack/names.h"

namespace kiln::driver {
namespace {

// Lookups by shader name, then pass name.
using LookupIndex =
    std::map<std::string, std::map<std::string, std::vector<const pack::UsageEntry*>>>;

LookupIndex IndexLookups(const pack::UsageLog& log) {
    LookupIndex index;
    for (const pack::UsageEntry& e : log.lookups)
        index[e.shader][e.pass].push_back(&e);
    return index;
}

// A lookup naming a pass the shader does not have: the usage file is stale, or the pass was
// renamed. Building without it would silently leave that pass's variants out.
void ReportUnknownPasses(
    CompileState& st,
    const ShaderUnit& unit,
    const std::map<std::string, std::vector<const pack::UsageEntry*>>& lookups) {
    std::vector<std::string> labels;
    for (const FlatPass& fp : unit.passes)
        labels.push_back(fp.label);
    for (const auto& [pass, entries] : lookups) {
        if (std::find(labels.begin(), labels.end(), pass) != labels.end())
            continue;
        std::string known;
        for (const std::string& l : labels)
            known += (known.empty() ? "" : ", ") + l;
        st.diags.Error(DiagCode::kUnknownRequestedPass, unit.file->path(), unit.ast->name_range,
                       "the scene or usage file looks up pass '" + pass + "' of shader '" +
                           unit.ast->name + "', which has no such pass" +
                           pack::DidYouMean(pass, labels) + " (its passes: " + known + ")");
    }
}

}  // namespace

void ExpandRequestedPasses(CompileState& st, bool skeleton) {
    static const pack::UsageLog kNone;
    const pack::UsageLog& log = skeleton || !st.options.requests ? kNone : *st.options.requests;
    const LookupIndex index = IndexLookups(log);
    std::set<std::string> used;
    for (const pack::UsageMaterial& m : log.materials)
        used.insert(m.shader);
    static const std::map<std::string, std::vector<const pack::UsageEntry*>> kNoPasses;
    for (size_t s = 0; s < st.shaders.size(); ++s) {
        ShaderUnit& unit = st.shaders[s];
        if (!unit.ast)
            continue;
        const auto found = index.find(unit.ast->name);
        unit.emit = skeleton || found != index.end() || used.count(unit.ast->name);
        if (!unit.emit)
            continue;
        const auto& lookups = found != index.end() ? found->second : kNoPasses;
        ReportUnknownPasses(st, unit, lookups);
        const std::string& path = unit.file->path();
        for (size_t f = 0; f < unit.passes.size(); ++f) {
            const FlatPass& fp = unit.passes[f];
            if (fp.grab)
                continue;  // no program: pack_emit.cpp records it in its place
            std::optional<PassUnit> read = ReadPass(st, s, f);
            if (!read)
                continue;
            PassUnit& pu = *read;
            std::vector<std::vector<std::string>> requests;
            if (auto it = lookups.find(fp.label); it != lookups.end()) {
                pu.requests = it->second;
                for (const pack::UsageEntry* e : pu.requests)
                    requests.push_back(e->keywords);
            }
            auto ex = variants::ExpandRequested(
                pu.pragmas, requests, VariantBudget(fp, st.options.max_variants, path, st.diags),
                "\"" + fp.label + "\"", path, fp.program->range, st.diags, pu.excluded);
            if (!ex)
                continue;
            pu.expansion = std::move(*ex);
            st.passes.push_back(std::move(pu));
        }
    }
    for (const PassUnit& pu : st.passes) {
        const ShaderUnit& unit = st.shaders[pu.shader];
        for (const variants::ExcludedRequest& x : pu.excluded) {
            st.diags.Warning(DiagCode::kRequestedVariantNotBuilt, unit.file->path(),
                             unit.passes[pu.flat].program->range,
                             "variant '" + pack::JoinKeywords(x.keywords) + "' of pass \"" +
                                 unit.passes[pu.flat].label + "\" is looked up but not built: " +
                                 x.reason + "; the runtime will not find it");
        }
    }
}

void FillStripReport(const CompileState& st, CompileOutput& out) {
    if (!st.options.requests)
        return;
    out.strip.active = true;
    std::set<std::string> compiled;
    for (const ShaderUnit& unit : st.shaders) {
        if (!unit.ast)
            continue;
        compiled.insert(unit.ast->name);
        if (!unit.emit)
            out.strip.shaders_left_out.push_back(unit.ast->name);
    }
    std::map<std::string, size_t> other;
    for (const pack::UsageEntry& e : st.options.requests->lookups) {
        if (!compiled.count(e.shader))
            ++other[e.shader];
    }
    out.strip.other_shaders.assign(other.begin(), other.end());
    // PassReports are in st.passes order (FillReports).
    for (size_t p = 0; p < st.passes.size() && p < out.passes.size(); ++p) {
        const PassUnit& pu = st.passes[p];
        PassReport& r = out.passes[p];
        std::map<uint64_t, RequestedVariantReport> kept;
        for (pack::VariantKey key : pu.expansion.keys) {
            kept[key.bits()].keywords =
                variants::EnabledKeywords(pu.pragmas.sets, pu.expansion.layout, key);
        }
        for (const pack::UsageEntry* e : pu.requests) {
            const pack::VariantKey key =
                variants::KeyForKeywords(pu.pragmas.sets, pu.expansion.layout, e->keywords);
            auto it = kept.find(key.bits());
            if (it == kept.end())
                continue;
            for (const std::string& who : e->requested_by) {
                if (it->second.requested_by.size() < pack::kMaxRequestedBy &&
                    std::count(it->second.requested_by.begin(), it->second.requested_by.end(),
                               who) == 0) {
                    it->second.requested_by.push_back(who);
                }
            }
            it->second.requesters += std::max<uint64_t>(e->requesters, e->count);
        }
        for (auto& [bits, v] : kept)
            r.kept.push_back(std::move(v));
        for (const variants::ExcludedRequest& x : pu.excluded) {
            RequestedVariantReport v;
            v.keywords = x.keywords;
            v.excluded_because = x.reason;
            const pack::UsageEntry* e = pu.requests[x.request];
            v.requested_by = e->requested_by;
            v.requesters = std::max<uint64_t>(e->requesters, e->count);
            r.excluded.push_back(std::move(v));
        }
    }
}

}  // namespace kiln::driver
