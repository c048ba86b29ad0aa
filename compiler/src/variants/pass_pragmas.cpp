#include "variants/pass_pragmas.h"

#include <algorithm>
#include <map>
#include <set>

namespace kiln::variants {
namespace {

using shaderlab::Pragma;

// Unity pragmas Kiln accepts and ignores: they change nothing for Vulkan.
const std::set<std::string> kIgnoredPragmas = {"fragmentoption",
                                               "glsl_no_auto_normalization",
                                               "enable_d3d11_debug_symbols",
                                               "hardware_tier_variants",
                                               "require",
                                               "editor_sync_compilation",
                                               "instancing_options",
                                               "multi_compile_prepassfinal",
                                               "prefer_hlslcc",
                                               "pack_matrix",
                                               "warning",
                                               "once",
                                               "debug",
                                               "vertex_format"};

// Entry-point pragmas of stages Kiln does not compile.
const std::set<std::string> kOtherStages = {"geometry", "hull",   "domain",
                                            "surface",  "kernel", "raytracing"};

bool IsIdentifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) {
        return false;
    }
    return std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
}

struct State {
    const std::string& file;
    DiagnosticList& diags;
    PassPragmas out;
    std::map<std::string, SourceRange> keyword_origin;

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
        slot = EntryPoint{p.args[0].text, p.range};
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

    void AddSet(KeywordSet set, const Pragma& p) {
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
                auto [it, fresh] = keyword_origin.emplace(kw, r);
                if (!fresh) {
                    diags
                        .Error(
                            DiagCode::kDuplicateKeyword, file, r,
                            "keyword '" + kw + "' is already in another keyword set of this pass")
                        .notes.push_back({file, it->second, "first declared here"});
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

    // multi_compile[_local][_vertex|_fragment], shader_feature[...]: true when handled.
    bool KeywordPragma(const Pragma& p) {
        std::string name = p.name;
        KeywordSet set;
        set.pragma = p.name;
        set.range = p.range;
        const auto shortcut = BuiltinShortcut(name);
        if (!shortcut.empty()) {
            for (const auto& keywords : shortcut) {
                KeywordSet s = set;
                s.keywords = keywords;
                AddSet(std::move(s), Pragma{p.name, {}, p.range});
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
        if (p.name == "target")
            return Target(p);
        if (p.name == "skip_variants") {
            out.skip_variants.insert(out.skip_variants.end(), p.args.begin(), p.args.end());
            return;
        }
        if (p.name == "only_renderers")
            return Renderers(p, out.only_renderers);
        if (p.name == "exclude_renderers")
            return Renderers(p, out.exclude_renderers);
        if (kOtherStages.count(p.name)) {
            diags.Error(DiagCode::kUnsupportedStage, file, p.range,
                        "'#pragma " + p.name +
                            "' is not supported: Kiln compiles vertex and fragment stages only");
            return;
        }
        if (KeywordPragma(p) || kIgnoredPragmas.count(p.name))
            return;
        diags.Warning(DiagCode::kUnknownPragma, file, p.range,
                      "unknown pragma '" + p.name + "' is ignored");
    }
};

}  // namespace

bool IsNoKeyword(const std::string& word) {
    return !word.empty() && word.find_first_not_of('_') == std::string::npos;
}

std::vector<std::vector<std::string>> BuiltinShortcut(const std::string& name) {
    // Kiln has no lightmaps or light cookies: the Unity keywords for those are left out.
    static const std::map<std::string, std::vector<std::vector<std::string>>> kShortcuts = {
        {"multi_compile_fwdbase",
         {{"DIRECTIONAL"}, {"", "SHADOWS_SCREEN"}, {"", "LIGHTPROBE_SH"}, {"", "VERTEXLIGHT_ON"}}},
        {"multi_compile_fwdadd", {{"DIRECTIONAL", "POINT", "SPOT"}}},
        {"multi_compile_fwdadd_fullshadows",
         {{"DIRECTIONAL", "POINT", "SPOT"},
          {"", "SHADOWS_DEPTH", "SHADOWS_SCREEN", "SHADOWS_CUBE"},
          {"", "SHADOWS_SOFT"}}},
        {"multi_compile_shadowcaster", {{"SHADOWS_DEPTH", "SHADOWS_CUBE"}}},
        {"multi_compile_lightpass",
         {{"DIRECTIONAL", "POINT", "SPOT"},
          {"", "SHADOWS_DEPTH", "SHADOWS_SCREEN", "SHADOWS_CUBE"},
          {"", "SHADOWS_SOFT"}}},
        {"multi_compile_fog", {{"", "FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}}},
        {"multi_compile_instancing", {{"", "INSTANCING_ON"}}},
    };
    auto it = kShortcuts.find(name);
    return it == kShortcuts.end() ? std::vector<std::vector<std::string>>{} : it->second;
}

PassPragmas ReadPassPragmas(const std::vector<const shaderlab::ProgramBlock*>& blocks,
                            const std::string& file,
                            SourceRange pass_range,
                            DiagnosticList& diags) {
    State st{file, diags, {}, {}};
    for (const shaderlab::ProgramBlock* block : blocks) {
        for (const Pragma& p : block->pragmas)
            st.One(p);
    }
    const SourceRange where = blocks.empty() ? pass_range : blocks.back()->range;
    if (!st.out.vertex) {
        diags.Error(DiagCode::kMissingEntryPoint, file, where,
                    "program has no '#pragma vertex' naming its vertex shader");
    }
    if (!st.out.fragment) {
        diags.Error(DiagCode::kMissingEntryPoint, file, where,
                    "program has no '#pragma fragment' naming its fragment shader");
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
