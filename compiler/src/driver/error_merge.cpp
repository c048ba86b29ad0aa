// Reports compile diagnostics once per distinct message, however many variants share it, with
// notes naming the keywords every failing variant has ("fails in 12 of 48 variants of pass
// "FORWARD": SPOT") and the smallest failing keyword combination.
#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "driver/compile_state.h"

namespace kiln::driver {
namespace {

using Signature = std::tuple<int, int, std::string, uint32_t, uint32_t, std::string>;

struct Group {
    Diagnostic diag;
    std::set<std::pair<size_t, uint64_t>> variants;  // (pass, key bits)
};

}  // namespace

void ReportJobDiagnostics(CompileState& st) {
    std::map<Signature, size_t> index;
    std::vector<Group> groups;
    std::vector<std::vector<size_t>> tasks_of_job(st.jobs.size());
    for (size_t t = 0; t < st.tasks.size(); ++t)
        tasks_of_job[st.tasks[t].job].push_back(t);

    for (size_t j = 0; j < st.jobs.size(); ++j) {
        for (const Diagnostic& d : st.jobs[j].diags) {
            const Signature sig{int(d.severity),    int(d.code),          d.file,
                                d.range.begin.line, d.range.begin.column, d.message};
            auto [it, fresh] = index.emplace(sig, groups.size());
            if (fresh)
                groups.push_back({d, {}});
            for (size_t t : tasks_of_job[j]) {
                groups[it->second].variants.insert({st.tasks[t].pass, st.tasks[t].key.bits()});
            }
        }
    }

    for (Group& g : groups) {
        Diagnostic d = g.diag;
        std::map<size_t, std::vector<uint64_t>> by_pass;
        for (const auto& [pass, key] : g.variants)
            by_pass[pass].push_back(key);
        for (const auto& [p, keys] : by_pass) {
            const PassUnit& pu = st.passes[p];
            const ShaderUnit& unit = st.shaders[pu.shader];
            const FlatPass& fp = unit.passes[pu.flat];
            const size_t total = pu.expansion.keys.size();
            const std::string verb = d.severity == Severity::kWarning ? "occurs" : "fails";
            std::vector<std::string> common;
            std::vector<std::string> smallest;
            uint64_t smallest_key = 0;
            bool first = true;
            for (uint64_t k : keys) {
                auto kws = variants::EnabledKeywords(pu.pragmas.sets, pu.expansion.layout,
                                                     pack::VariantKey(k));
                if (first) {
                    common = kws;
                    smallest = kws;
                    smallest_key = k;
                    first = false;
                    continue;
                }
                std::vector<std::string> keep;
                for (const auto& c : common) {
                    if (std::find(kws.begin(), kws.end(), c) != kws.end())
                        keep.push_back(c);
                }
                common = std::move(keep);
                if (kws.size() < smallest.size() ||
                    (kws.size() == smallest.size() && k < smallest_key)) {
                    smallest = kws;
                    smallest_key = k;
                }
            }
            const std::string where = "shader \"" + unit.ast->name + "\" pass \"" + fp.label + "\"";
            if (d.severity == Severity::kInternal) {
                d.message +=
                    " (" + where + ", variant " + pack::JoinKeywords(smallest) + ")";
            }
            if (total <= 1) {
                // One variant: no counts, but which pass fails, where that is not plain from the
                // place (the error is in an include file, or the shader has several passes).
                if (d.file != unit.file->path() || unit.passes.size() > 1)
                    d.notes.push_back(
                        {unit.file->path(), fp.program->range, verb + " in " + where});
                continue;
            }
            std::string note;
            if (keys.size() == total) {
                note = verb + " in all " + std::to_string(total) + " variants of " + where;
            } else {
                note = verb + " in " + std::to_string(keys.size()) + " of " +
                       std::to_string(total) + " variants of " + where;
                if (!common.empty())
                    note += ": " + pack::JoinKeywords(common);
            }
            d.notes.push_back({unit.file->path(), fp.program->range, note});
            if (keys.size() < total) {
                d.notes.push_back({unit.file->path(), fp.program->range,
                                   "smallest failing keyword combination: " +
                                       pack::JoinKeywords(smallest)});
            }
        }
        Diagnostic& added = st.diags.Add(d.severity, d.code, d.file, d.range, d.message);
        added.notes = d.notes;
    }
}

}  // namespace kiln::driver
