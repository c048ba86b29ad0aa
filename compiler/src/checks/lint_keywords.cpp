// kiln lint's keyword checks (checks.cpp's table): what each keyword changes (keyword-effect,
// K7001-K7003), how keywords are declared (keyword-declarations, K7004-K7007) and how many there
// are (keyword-limits, K7008).
#include <array>
#include <map>
#include <set>

#include "checks/check_functions.h"
#include "kiln/pack/property_keywords.h"

namespace kiln::checks {
namespace {

using driver::CompileState;
using driver::PassUnit;
using driver::ShaderUnit;

using Ids = std::array<size_t, 2>;  // (vertex, fragment) module identity of a variant

// Every variant of pass `p` by key, with its stages' final SPIR-V as small identities.
std::map<uint64_t, Ids> ModulesOf(const CompileState& st,
                                  size_t p,
                                  std::map<std::vector<uint32_t>, size_t>& ids) {
    std::map<uint64_t, Ids> out;
    const PassUnit& pu = st.passes[p];
    for (size_t v = 0; v < pu.expansion.keys.size(); ++v) {
        Ids m{};
        for (size_t stage = 0; stage < 2; ++stage) {
            const std::vector<uint32_t>& words =
                st.finals[p].at(st.tasks[pu.TaskOf(v, stage)].job).words;
            m[stage] = ids.emplace(words, ids.size()).first->second;
        }
        out[pu.expansion.keys[v].bits()] = m;
    }
    return out;
}

// Whether some variant of a set's keyword `k` has a twin with another keyword of the set whose
// module for `stage` differs: the keyword changes that stage. `compared` says whether any twin
// existed at all.
bool ChangesStage(const std::map<uint64_t, Ids>& variants,
                  const variants::SetLayout& layout,
                  uint32_t k,
                  uint32_t choices,
                  size_t stage,
                  bool& compared) {
    for (const auto& [bits, ids] : variants) {
        pack::VariantKey key(bits);
        if (key.Get(layout.shift, layout.bits) != k)
            continue;
        for (uint32_t other = 0; other < choices; ++other) {
            if (other == k)
                continue;
            key.Set(layout.shift, layout.bits, other);
            const auto twin = variants.find(key.bits());
            if (twin == variants.end())
                continue;
            compared = true;
            if (twin->second[stage] != ids[stage])
                return true;
        }
    }
    return false;
}

std::string Quoted(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words)
        out += (out.empty() ? "" : " ") + (w.empty() ? std::string("_") : w);
    return out;
}

// K7001, K7003 from the pack's aliases; K7002 for sets that change one stage only.
void LintKeywordUse(CompileState& st, size_t p, const std::map<uint64_t, Ids>& variants) {
    const PassUnit& pu = st.passes[p];
    const ShaderUnit& unit = st.shaders[pu.shader];
    const std::string& file = unit.file->path();
    const std::string pass = "\"" + unit.passes[pu.flat].label + "\"";
    for (const auto& [alias_pass, a] : st.aliases) {
        if (alias_pass != p)
            continue;
        const variants::KeywordSet& set = pu.pragmas.sets[a.set];
        if (set.generated)
            continue;  // a surface shader's generated pragma: nothing the user can change
        const std::string& from = set.keywords[a.from];
        const std::string& to = set.keywords[a.to];
        if (to.empty()) {
            st.diags.Warning(DiagCode::kLintKeywordChangesNothing, file, set.range,
                             "keyword '" + from + "' of pass " + pass +
                                 " changes no code: every variant with it compiles to the same "
                                 "SPIR-V as without it (the pack stores it as an alias); remove "
                                 "it");
        } else {
            st.diags.Warning(DiagCode::kLintRedundantKeywords, file, set.range,
                             "keywords '" + to + "' and '" + from + "' of pass " + pass +
                                 " give identical SPIR-V in every variant (the pack stores '" +
                                 from + "' as an alias of '" + to + "'); one keyword would do");
        }
    }
    for (size_t s = 0; s < pu.pragmas.sets.size(); ++s) {
        const variants::KeywordSet& set = pu.pragmas.sets[s];
        const uint32_t n = static_cast<uint32_t>(set.keywords.size());
        if (n < 2 || set.generated || variants::BuiltinShortcut(set.pragma) ||
            (set.flags & (pack::kKeywordSetVertexOnly | pack::kKeywordSetFragmentOnly))) {
            continue;  // a shortcut's sets, or already one stage
        }
        bool compared = false, vertex = false, fragment = false;
        for (uint32_t k = 0; k < n; ++k) {
            vertex = ChangesStage(variants, pu.expansion.layout[s], k, n, 0, compared) || vertex;
            fragment =
                ChangesStage(variants, pu.expansion.layout[s], k, n, 1, compared) || fragment;
        }
        if (!compared || vertex == fragment)
            continue;
        const char* stage = vertex ? "vertex" : "fragment";
        std::string args;
        for (const std::string& k : set.keywords)
            args += " " + (k.empty() ? std::string("_") : k);
        st.diags.Warning(DiagCode::kLintKeywordOneStage, file, set.range,
                         "keywords " + Quoted(set.keywords) + " of pass " + pass +
                             " change only its " + stage + " stage; '#pragma " + set.pragma + "_" +
                             stage + args + "' keeps them out of the other stage's variants");
    }
}

// Keywords [Toggle]/[ToggleOff]/[KeywordEnum] properties of the shader switch.
std::set<std::string> PropertyDrivenKeywords(const shaderlab::Shader& shader) {
    std::set<std::string> out;
    for (const shaderlab::Property& prop : shader.properties) {
        for (const shaderlab::Attribute& a : prop.attributes) {
            const auto driven = pack::KeywordsDrivenBy(prop.name, a.name, a.raw_args);
            out.insert(driven.keywords.begin(), driven.keywords.end());
        }
    }
    return out;
}

// K7004-K7007 for one shader's passes.
void LintShaderDeclarations(CompileState& st, size_t s) {
    const ShaderUnit& unit = st.shaders[s];
    const std::string& file = unit.file->path();
    const std::set<std::string> driven = PropertyDrivenKeywords(*unit.ast);
    // keyword -> (pass label, set) of its first declaration, for K7007
    std::map<std::string, std::pair<std::string, const variants::KeywordSet*>> first;
    std::set<std::string> reported;
    for (const PassUnit& pu : st.passes) {
        if (pu.shader != s)
            continue;
        const std::string pass = unit.passes[pu.flat].label;
        for (const variants::KeywordSet& set : pu.pragmas.sets) {
            if (set.generated)
                continue;
            const bool feature = set.kind == pack::KeywordSetKind::kShaderFeature;
            bool all_material = !feature;
            for (const std::string& k : set.keywords) {
                if (k.empty())
                    continue;
                const bool engine = variants::IsBuiltinKeyword(k);
                all_material = all_material && driven.count(k) && !engine;
                if (feature && engine && reported.insert("7004" + k).second) {
                    st.diags.Warning(DiagCode::kLintEngineShaderFeature, file, set.range,
                                     "'" + k +
                                         "' is set by the engine for each draw, but '#pragma " +
                                         set.pragma +
                                         "' builds it only where a material enables "
                                         "it, so the engine's lookups miss; use multi_compile");
                }
                if (feature && !engine && !driven.count(k) && k[0] != '_' &&
                    !(set.flags & pack::kKeywordSetLocal) && reported.insert("7006" + k).second) {
                    st.diags.Warning(
                        DiagCode::kLintShaderFeatureLooksGlobal, file, set.range,
                        "'" + k +
                            "' looks like a global keyword set from code (no "
                            "property drives it, and material keywords start with '_'); "
                            "'#pragma " +
                            set.pragma +
                            "' builds it only where a "
                            "material enables it: use multi_compile if code sets it");
                }
                // The engine's keywords (light types, shadows) have their companions per pass
                // by design: Unity's own shortcuts declare SHADOWS_SCREEN with other sets in
                // ForwardBase and ForwardAdd.
                auto [it, fresh] = first.emplace(k, std::make_pair(pass, &set));
                const variants::KeywordSet& other = *it->second.second;
                if (!fresh && !engine &&
                    (other.kind != set.kind || other.keywords != set.keywords) &&
                    reported.insert("7007" + k).second) {
                    st.diags
                        .Warning(DiagCode::kLintKeywordDeclaredTwoWays, file, set.range,
                                 "keyword '" + k + "' is declared by '#pragma " + set.pragma + " " +
                                     Quoted(set.keywords) + "' in pass \"" + pass +
                                     "\" and by '#pragma " + other.pragma + " " +
                                     Quoted(other.keywords) + "' in pass \"" + it->second.first +
                                     "\": the sets overlap but differ, so one keyword has two "
                                     "sets of companions")
                        .notes.push_back({file, other.range, "the other declaration"});
                }
            }
            if (all_material && set.keywords.size() > 1) {
                st.diags.Warning(DiagCode::kLintMaterialMultiCompile, file, set.range,
                                 "only material properties set " + Quoted(set.keywords) +
                                     " ([Toggle]/[KeywordEnum]), yet '#pragma " + set.pragma +
                                     "' builds every combination; shader_feature builds only "
                                     "those materials use");
            }
        }
    }
}

// K7008: Unity's documented limits (Unity 2021.1 and older, the built-in render pipeline): 64
// local keywords per shader, 256 global keywords in all, Unity's own included.
void LintLimits(CompileState& st) {
    std::set<std::string> global;
    for (size_t s = 0; s < st.shaders.size(); ++s) {
        std::set<std::string> local;
        for (const PassUnit& pu : st.passes) {
            if (pu.shader != s)
                continue;
            for (const variants::KeywordSet& set : pu.pragmas.sets) {
                for (const std::string& k : set.keywords) {
                    if (!k.empty())
                        ((set.flags & pack::kKeywordSetLocal) ? local : global).insert(k);
                }
            }
        }
        if (local.size() > 64 && st.shaders[s].ast) {
            st.diags.Warning(DiagCode::kLintTooManyKeywords, st.shaders[s].file->path(),
                             st.shaders[s].ast->name_range,
                             "shader '" + st.shaders[s].ast->name + "' declares " +
                                 std::to_string(local.size()) +
                                 " local keywords; Unity before 2021.2 allows 64 per shader");
        }
    }
    if (global.size() > 256 && !st.shaders.empty() && st.shaders[0].ast) {
        st.diags.Warning(DiagCode::kLintTooManyKeywords, st.shaders[0].file->path(),
                         st.shaders[0].ast->name_range,
                         "the shaders declare " + std::to_string(global.size()) +
                             " global keywords; Unity before 2021.2 allows 256 in all");
    }
}

}  // namespace

void LintKeywordEffects(Inputs& in) {
    std::map<std::vector<uint32_t>, size_t> ids;
    for (size_t p = 0; p < in.st->passes.size(); ++p)
        LintKeywordUse(*in.st, p, ModulesOf(*in.st, p, ids));
}

void LintKeywordDeclarations(Inputs& in) {
    for (size_t s = 0; s < in.st->shaders.size(); ++s) {
        if (in.st->shaders[s].ast)
            LintShaderDeclarations(*in.st, s);
    }
}

void LintKeywordLimits(Inputs& in) {
    LintLimits(*in.st);
}

}  // namespace kiln::checks
