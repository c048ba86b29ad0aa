#include "variants/pass_pragmas.h"

#include <algorithm>
#include <map>
#include <set>

#include "kiln/base/text.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/names.h"

namespace kiln::variants {
namespace {

using shaderlab::Pragma;
using shaderlab::PragmaArg;

// Unity pragmas Kiln accepts and ignores: they change nothing for Vulkan.
const std::set<std::string> kIgnoredPragmas = {
    "fragmentoption", "glsl_no_auto_normalization", "enable_d3d11_debug_symbols",
    "hardware_tier_variants", "editor_sync_compilation", "instancing_options", "prefer_hlslcc",
    "never_use_dxc", "use_dxc", "glsl_es", "glsl_es2", "glsl", "enable_cbuffer", "dynamic_branch",
    "pack_matrix", "warning", "once", "debug", "vertex_format",
    // read by the surface-shader generator
    // (driver/surface_passes.h)
    "surface"};

// Unity's built-in keyword shortcuts (BuiltinShortcut).
const char* const kShortcutNames[] = {
    "multi_compile_fwdbase",      "multi_compile_fwdbasealpha",
    "multi_compile_fwdadd",       "multi_compile_fwdadd_fullshadows",
    "multi_compile_lightpass",    "multi_compile_prepassfinal",
    "multi_compile_shadowcaster", "multi_compile_shadowcollector",
    "multi_compile_fog",          "multi_compile_instancing",
    "multi_compile_particles"};

// Entry-point pragmas of stages Kiln does not compile.
const std::set<std::string> kOtherStages = {"kernel", "raytracing"};

bool IsIdentifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) {
        return false;
    }
    return std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
}

struct State {
    std::string file;        // of the block being read (a generated block names its own)
    bool generated = false;  // the block being read is generated code
    DiagnosticList& diags;
    PassPragmas out;
    std::map<std::string, std::pair<std::string, SourceRange>> keyword_origin;  // file, range
    int required_target = 0;  // from #pragma require

    void Entry(const Pragma& p, std::optional<EntryPoint>& slot) {
        if (p.args.empty()) {
            diags.Error(DiagCode::kPragmaMissingArgument, file, p.range,
                        "'#pragma " + p.name + "' needs a function name");
            return;
        }
        if (slot) {
            diags
                .Error(DiagCode::kDuplicateEntryPoint, file, p.range,
                       "second '#pragma " + p.name + "' in one program")
                .notes.push_back({file, slot->range, "first entry point given here"});
            return;
        }
        slot = EntryPoint{p.args[0].text, p.args[0].range};  // the name: diagnostics point at it
    }

    void Target(const Pragma& p) {
        static const std::map<std::string, int> kTargets = {
            {"2.0", 20}, {"2.5", 25}, {"3.0", 30},   {"3.5", 35},   {"4.0", 40},  {"4.5", 45},
            {"4.6", 46}, {"5.0", 50}, {"gl4.1", 46}, {"es3.0", 35}, {"es3.1", 45}};
        if (p.args.empty()) {
            diags.Error(DiagCode::kPragmaMissingArgument, file, p.range,
                        "'#pragma target' needs a shader model such as 3.0");
            return;
        }
        auto it = kTargets.find(p.args[0].text);
        if (it == kTargets.end()) {
            diags.Error(DiagCode::kBadShaderTarget, file, p.args[0].range,
                        "unknown shader target '" + p.args[0].text +
                            "'; expected 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 4.6 or 5.0");
            return;
        }
        out.shader_target = it->second;
    }

    // `#pragma require FEATURE...` raises SHADER_TARGET to the shader model that has the features,
    // as Unity does (Unity manual, "Targeting shader models and GPU features").
    void Require(const Pragma& p) {
        static const std::map<std::string, int, std::less<>> kFeatureTargets = {
            {"derivatives", 25},  {"samplelod", 25},
            {"fragcoord", 25},    {"interpolators10", 30},
            {"samplegrad", 30},   {"interpolators15", 35},
            {"mrt4", 35},         {"integers", 35},
            {"2darray", 35},      {"instancing", 35},
            {"geometry", 40},     {"compute", 45},
            {"randomwrite", 45},  {"msaatex", 45},
            {"cubearray", 46},    {"tesshw", 46},
            {"tessellation", 46}, {"interpolators32", 50},
            {"mrt8", 50},         {"setrtarrayindexfromanyshader", 50}};
        for (const auto& a : p.args) {
            const std::string feature = base::ToLower(a.text);
            if (auto it = kFeatureTargets.find(feature); it != kFeatureTargets.end())
                required_target = std::max(required_target, it->second);
        }
    }

    // Whether the pass has a set of this kind with these keywords already: a generated surface
    // pass's shortcut and the shader's own `multi_compile_instancing`, or a keyword set written
    // twice, declare the same variants once, as in Unity.
    bool Repeats(const KeywordSet& set) const {
        std::set<std::string> mine;
        for (const std::string& k : set.keywords)
            mine.insert(IsNoKeyword(k) ? std::string() : k);
        if (set.kind == pack::KeywordSetKind::kShaderFeature && mine.size() == 1)
            mine.insert("");
        return std::any_of(out.sets.begin(), out.sets.end(), [&](const KeywordSet& s) {
            return s.kind == set.kind && s.flags == set.flags &&
                   std::set<std::string>(s.keywords.begin(), s.keywords.end()) == mine;
        });
    }

    void AddSet(KeywordSet set, const Pragma& p) {
        if (Repeats(set))
            return;
        set.generated = generated;
        std::set<std::string> in_set;
        std::vector<std::string> cleaned;
        for (size_t i = 0; i < set.keywords.size(); ++i) {
            std::string kw = set.keywords[i];
            const SourceRange r = i < p.args.size() ? p.args[i].range : p.range;
            if (IsNoKeyword(kw))
                kw.clear();
            if (!kw.empty() && !IsIdentifier(kw)) {
                diags.Error(DiagCode::kBadKeyword, file, r,
                            "keyword '" + kw + "' is not an identifier");
                continue;
            }
            if (!in_set.insert(kw).second) {
                diags.Error(DiagCode::kDuplicateKeyword, file, r,
                            kw.empty() ? std::string("'_' appears twice in one keyword set")
                                       : "keyword '" + kw + "' appears twice in one keyword set");
                continue;
            }
            if (!kw.empty()) {
                auto [it, fresh] = keyword_origin.emplace(kw, std::pair(file, r));
                if (!fresh) {
                    diags
                        .Error(
                            DiagCode::kDuplicateKeyword, file, r,
                            "keyword '" + kw + "' is already in another keyword set of this pass")
                        .notes.push_back(
                            {it->second.first, it->second.second, "first declared here"});
                    continue;
                }
            }
            cleaned.push_back(kw);
        }
        if (cleaned.empty())
            return;
        // shader_feature A means shader_feature _ A.
        if (set.kind == pack::KeywordSetKind::kShaderFeature && cleaned.size() == 1 &&
            !cleaned[0].empty()) {
            cleaned.insert(cleaned.begin(), "");
        }
        set.keywords = std::move(cleaned);
        out.sets.push_back(std::move(set));
    }

    // The keywords a shortcut's modifiers remove (`#pragma multi_compile_fwdbase nolightmap`, as
    // Unity's generated surface passes and some built-in shaders write it); an unknown modifier is
    // a warning naming the closest one, and is ignored.
    std::set<std::string> ShortcutModifiers(const Pragma& p) {
        static const std::map<std::string, std::vector<std::string>> kModifiers = {
            {"nolightmap", {"LIGHTMAP_ON"}},
            {"nodirlightmap", {"DIRLIGHTMAP_COMBINED"}},
            {"nodynlightmap", {"DYNAMICLIGHTMAP_ON"}},
            {"novertexlight", {pack::kKeywordVertexLight}},
            {"novertexlights", {pack::kKeywordVertexLight}},
            {"noshadowmask", {"SHADOWS_SHADOWMASK"}},
            {"noshadow", {"SHADOWS_SCREEN", "SHADOWS_DEPTH", "SHADOWS_CUBE", "SHADOWS_SOFT"}},
        };
        std::set<std::string> removed;
        for (const PragmaArg& a : p.args) {
            if (auto it = kModifiers.find(a.text); it != kModifiers.end()) {
                removed.insert(it->second.begin(), it->second.end());
                continue;
            }
            std::vector<std::string> names;
            for (const auto& [modifier, keywords] : kModifiers)
                names.push_back(modifier);
            diags.Warning(DiagCode::kUnknownPragma, file, a.range,
                          "'#pragma " + p.name + "' has no modifier '" + a.text +
                              "'; it is ignored" + pack::DidYouMean(a.text, names));
        }
        return removed;
    }

    // multi_compile[_local][_vertex|_fragment], shader_feature[...]: true when handled.
    bool KeywordPragma(const Pragma& p) {
        std::string name = p.name;
        KeywordSet set;
        set.pragma = p.name;
        set.range = p.range;
        if (const auto shortcut = BuiltinShortcut(name)) {
            const std::set<std::string> removed = ShortcutModifiers(p);
            for (const auto& keywords : shortcut->sets) {
                KeywordSet s = set;
                for (const std::string& k : keywords) {
                    if (!removed.count(k))
                        s.keywords.push_back(k);
                }
                if (s.keywords.empty() || (s.keywords.size() == 1 && s.keywords[0].empty()))
                    continue;  // every keyword of the set removed
                AddSet(std::move(s), Pragma{p.name, {}, p.range});
            }
            for (KeywordRule rule : shortcut->rules) {
                rule.pragma = p.name;
                out.rules.push_back(std::move(rule));
            }
            return true;
        }
        if (name.rfind("multi_compile", 0) == 0) {
            set.kind = pack::KeywordSetKind::kMultiCompile;
            name.erase(0, 13);
        } else if (name.rfind("shader_feature", 0) == 0) {
            set.kind = pack::KeywordSetKind::kShaderFeature;
            name.erase(0, 14);
        } else {
            return false;
        }
        if (name.rfind("_local", 0) == 0) {
            set.flags |= pack::kKeywordSetLocal;
            name.erase(0, 6);
        }
        if (name == "_vertex") {
            set.flags |= pack::kKeywordSetVertexOnly;
        } else if (name == "_fragment") {
            set.flags |= pack::kKeywordSetFragmentOnly;
        } else if (!name.empty()) {
            return false;
        }
        if (p.args.empty()) {
            diags.Error(DiagCode::kPragmaMissingArgument, file, p.range,
                        "'#pragma " + p.name + "' needs at least one keyword");
            return true;
        }
        for (const auto& a : p.args)
            set.keywords.push_back(a.text);
        AddSet(std::move(set), p);
        return true;
    }

    void Renderers(const Pragma& p, std::vector<std::string>& list) {
        for (const auto& a : p.args)
            list.push_back(a.text);
    }

    void One(const Pragma& p) {
        if (p.name == "vertex")
            return Entry(p, out.vertex);
        if (p.name == "fragment")
            return Entry(p, out.fragment);
        // As in Unity, a geometry stage needs shader model 4.0 and tessellation 4.6: the pragma
        // raises SHADER_TARGET to it.
        if (p.name == "geometry") {
            required_target = std::max(required_target, 40);
            return Entry(p, out.geometry);
        }
        if (p.name == "hull" || p.name == "domain") {
            required_target = std::max(required_target, 46);
            return Entry(p, p.name == "hull" ? out.hull : out.domain);
        }
        if (p.name == "target")
            return Target(p);
        if (p.name == "require")
            return Require(p);
        if (p.name == "skip_variants") {
            out.skip_variants.insert(out.skip_variants.end(), p.args.begin(), p.args.end());
            return;
        }
        if (p.name == "only_renderers")
            return Renderers(p, out.only_renderers);
        if (p.name == "exclude_renderers")
            return Renderers(p, out.exclude_renderers);
        if (kOtherStages.count(p.name)) {
            diags.Error(
                DiagCode::kUnsupportedStage, file, p.range,
                "'#pragma " + p.name +
                    "' is not supported: Kiln compiles vertex, fragment, geometry, hull and "
                    "domain stages");
            return;
        }
        if (KeywordPragma(p) || kIgnoredPragmas.count(p.name))
            return;
        // As in Unity an unknown pragma is ignored, but one spelled like a pragma Kiln reads is
        // a typo whose variants or entry point would silently disappear: an error.
        const std::string near = pack::ClosestName(p.name, KnownPragmas());
        if (!near.empty()) {
            diags.Error(DiagCode::kMisspelledPragma, file, p.range,
                        "unknown pragma '" + p.name + "'; did you mean '" + near + "'?");
            return;
        }
        diags.Warning(DiagCode::kUnknownPragma, file, p.range,
                      "unknown pragma '" + p.name + "' is ignored");
    }

    // Every pragma name Kiln reads, for the typo check.
    static const std::vector<std::string>& KnownPragmas() {
        static const std::vector<std::string> names = [] {
            std::vector<std::string> n = {
                "vertex", "fragment", "geometry",      "hull",           "domain",
                "target", "require",  "skip_variants", "only_renderers", "exclude_renderers"};
            n.insert(n.end(), kIgnoredPragmas.begin(), kIgnoredPragmas.end());
            n.insert(n.end(), kOtherStages.begin(), kOtherStages.end());
            for (const char* base : {"multi_compile", "shader_feature"}) {
                for (const char* local : {"", "_local"}) {
                    for (const char* stage : {"", "_vertex", "_fragment"})
                        n.push_back(std::string(base) + local + stage);
                }
            }
            n.insert(n.end(), std::begin(kShortcutNames), std::end(kShortcutNames));
            return n;
        }();
        return names;
    }
};

}  // namespace

bool IsBuiltinKeyword(const std::string& word) {
    static const std::set<std::string> all = [] {
        std::set<std::string> out;
        for (const char* name : kShortcutNames) {
            const std::optional<Shortcut> shortcut = BuiltinShortcut(name);
            for (const auto& set : shortcut->sets)
                out.insert(set.begin(), set.end());
        }
        out.erase("");
        return out;
    }();
    return all.count(word) > 0;
}

bool IsNoKeyword(const std::string& word) {
    return !word.empty() && word.find_first_not_of('_') == std::string::npos;
}

std::optional<Shortcut> BuiltinShortcut(const std::string& name) {
    // Unity's keyword lists for its built-in pipeline (Unity manual, "Shader variant shortcuts"),
    // as sets whose product the rules cut down to the combinations Unity builds. The rules were
    // read off Unity's compiled output for these shortcuts; docs/variants.md has the tables.
    using Sets = std::vector<std::vector<std::string>>;
    using Rules = std::vector<KeywordRule>;
    // A light pass with real-time shadows: each light type with the shadow kinds it can have,
    // soft shadows for depth and cube shadows, and the mixed-lighting (shadowmask) keywords.
    const Sets light_shadow_sets = {
        {pack::kKeywordPoint, pack::kKeywordDirectional, pack::kKeywordSpot,
         pack::kKeywordPointCookie, pack::kKeywordDirectionalCookie},
        {"", "SHADOWS_DEPTH", "SHADOWS_SCREEN", "SHADOWS_CUBE"},
        {"", "SHADOWS_SOFT"},
        {"", "SHADOWS_SHADOWMASK"},
        {"", "LIGHTMAP_SHADOW_MIXING"}};
    const Rules light_shadow_rules = {
        {"SHADOWS_DEPTH", {pack::kKeywordSpot}, {}, {}},
        {"SHADOWS_SCREEN", {pack::kKeywordDirectional, pack::kKeywordDirectionalCookie}, {}, {}},
        {"SHADOWS_CUBE", {pack::kKeywordPoint, pack::kKeywordPointCookie}, {}, {}},
        {"SHADOWS_SOFT", {"SHADOWS_DEPTH", "SHADOWS_CUBE"}, {}, {}},
        {"LIGHTMAP_SHADOW_MIXING",
         {"SHADOWS_DEPTH", "SHADOWS_SCREEN", "SHADOWS_CUBE", "SHADOWS_SHADOWMASK"},
         {},
         {}}};
    const KeywordRule dirlightmap = {
        "DIRLIGHTMAP_COMBINED", {"LIGHTMAP_ON", "DYNAMICLIGHTMAP_ON"}, {}, {}};
    const KeywordRule vertexlights = {
        pack::kKeywordVertexLight, {}, {"LIGHTMAP_ON", "DYNAMICLIGHTMAP_ON"}, {}};

    if (name == "multi_compile_fwdbase") {
        return Shortcut{{{pack::kKeywordDirectional},
                         {"", "LIGHTMAP_ON"},
                         {"", "DIRLIGHTMAP_COMBINED"},
                         {"", "DYNAMICLIGHTMAP_ON"},
                         {"", "SHADOWS_SCREEN"},
                         {"", "SHADOWS_SHADOWMASK"},
                         {"", "LIGHTMAP_SHADOW_MIXING"},
                         {"", pack::kKeywordLightProbeSH},
                         {"", pack::kKeywordVertexLight}},
                        {dirlightmap,
                         vertexlights,
                         {"LIGHTMAP_SHADOW_MIXING", {"LIGHTMAP_ON", "SHADOWS_SCREEN"}, {}, {}}}};
    }
    if (name == "multi_compile_fwdbasealpha") {
        return Shortcut{
            {{pack::kKeywordDirectional},
             {"", "LIGHTMAP_ON"},
             {"", "DIRLIGHTMAP_COMBINED"},
             {"", "DYNAMICLIGHTMAP_ON"},
             {"", "LIGHTMAP_SHADOW_MIXING"},
             {"", pack::kKeywordLightProbeSH},
             {"", pack::kKeywordVertexLight}},
            {dirlightmap, vertexlights, {"LIGHTMAP_SHADOW_MIXING", {"LIGHTMAP_ON"}, {}, {}}}};
    }
    if (name == "multi_compile_fwdadd") {
        return Shortcut{{{pack::kKeywordPoint, pack::kKeywordDirectional, pack::kKeywordSpot,
                          pack::kKeywordPointCookie, pack::kKeywordDirectionalCookie}},
                        {}};
    }
    if (name == "multi_compile_fwdadd_fullshadows" || name == "multi_compile_lightpass") {
        return Shortcut{light_shadow_sets, light_shadow_rules};
    }
    if (name == "multi_compile_prepassfinal") {
        return Shortcut{{{"", "LIGHTMAP_ON"},
                         {"", "DIRLIGHTMAP_COMBINED"},
                         {"", "DYNAMICLIGHTMAP_ON"},
                         {"", "UNITY_HDR_ON"},
                         {"", "SHADOWS_SHADOWMASK"},
                         {"", "LIGHTMAP_SHADOW_MIXING"},
                         {"", pack::kKeywordLightProbeSH}},
                        {dirlightmap, {"LIGHTMAP_SHADOW_MIXING", {"LIGHTMAP_ON"}, {}, {}}}};
    }
    if (name == "multi_compile_shadowcaster") {
        return Shortcut{{{"SHADOWS_DEPTH", "SHADOWS_CUBE"}}, {}};
    }
    if (name == "multi_compile_shadowcollector") {
        return Shortcut{{{"", "SHADOWS_SPLIT_SPHERES"}, {"", "SHADOWS_SINGLE_CASCADE"}}, {}};
    }
    if (name == "multi_compile_fog") {
        return Shortcut{{{"", "FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}}, {}};
    }
    if (name == "multi_compile_instancing") {
        return Shortcut{{{"", "INSTANCING_ON"}}, {}};
    }
    if (name == "multi_compile_particles") {
        return Shortcut{{{"", "SOFTPARTICLES_ON"}}, {}};
    }
    return std::nullopt;
}

const KeywordRule* BrokenRule(const std::vector<KeywordRule>& rules,
                              const std::vector<std::string>& keywords) {
    auto on = [&](const std::string& k) {
        return std::find(keywords.begin(), keywords.end(), k) != keywords.end();
    };
    for (const KeywordRule& r : rules) {
        if (!on(r.keyword)) {
            continue;
        }
        if (!r.any_of.empty() && std::none_of(r.any_of.begin(), r.any_of.end(), on)) {
            return &r;
        }
        if (std::any_of(r.none_of.begin(), r.none_of.end(), on)) {
            return &r;
        }
    }
    return nullptr;
}

bool SatisfiesRules(const std::vector<KeywordRule>& rules,
                    const std::vector<std::string>& keywords) {
    return BrokenRule(rules, keywords) == nullptr;
}

PassPragmas ReadPassPragmas(const std::vector<const shaderlab::ProgramBlock*>& blocks,
                            const std::string& file,
                            SourceRange pass_range,
                            DiagnosticList& diags) {
    State st{file, false, diags, {}, {}, 0};
    for (const shaderlab::ProgramBlock* block : blocks) {
        st.file = block->file.empty() ? file : block->file;
        st.generated = !block->file.empty();
        for (const Pragma& p : block->pragmas)
            st.One(p);
    }
    st.out.shader_target = std::max(st.out.shader_target, st.required_target);
    const SourceRange where = blocks.empty() ? pass_range : blocks.back()->range;
    if (!st.out.vertex) {
        diags.Error(DiagCode::kMissingEntryPoint, file, where,
                    "program has no '#pragma vertex' naming its vertex shader");
    }
    if (!st.out.fragment) {
        diags.Error(DiagCode::kMissingEntryPoint, file, where,
                    "program has no '#pragma fragment' naming its fragment shader");
    }
    if (st.out.hull.has_value() != st.out.domain.has_value()) {
        const EntryPoint& given = st.out.hull ? *st.out.hull : *st.out.domain;
        diags.Error(DiagCode::kMissingEntryPoint, file, given.range,
                    std::string("tessellation needs both stages: program has '#pragma ") +
                        (st.out.hull ? "hull" : "domain") + "' but no '#pragma " +
                        (st.out.hull ? "domain" : "hull") + "'");
    }
    for (const auto& a : st.out.skip_variants) {
        if (!st.keyword_origin.count(a.text)) {
            diags.Warning(DiagCode::kUnknownSkipKeyword, file, a.range,
                          "skip_variants names '" + a.text + "', which no keyword set declares");
        }
    }
    auto has_vulkan = [](const std::vector<std::string>& list) {
        return std::find(list.begin(), list.end(), "vulkan") != list.end();
    };
    if ((!st.out.only_renderers.empty() && !has_vulkan(st.out.only_renderers)) ||
        has_vulkan(st.out.exclude_renderers)) {
        diags.Warning(DiagCode::kRendererRestricted, file, where,
                      "program excludes the vulkan renderer; Kiln compiles it for Vulkan anyway");
    }
    return std::move(st.out);
}

}  // namespace kiln::variants
