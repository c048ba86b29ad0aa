// Phase 2 of a compile: each pass's pragmas and variant keys (shader_feature combinations from
// the materials and --keywords, budgets), then one StageTask per (variant, stage) with its
// assembled source.
#include <algorithm>
#include <set>

#include "driver/compile_state.h"
#include "hlsl/assemble.h"
#include "hlsl/identifier.h"
#include "kiln/pack/names.h"
#include "kiln/pack/property_keywords.h"

namespace kiln::driver {
namespace {

std::string LineName(const std::string& path) {
    return hlsl::IsLineSafeName(path) ? path : std::string("<unprintable path>");
}

// A material's keywords: those it lists and those its [Toggle]/[ToggleOff]/[KeywordEnum] property
// values enable (the property's default when the material does not set it), as in Unity.
std::set<std::string> MaterialKeywords(const shaderlab::Shader& shader, const MaterialRequest& m) {
    std::set<std::string> out = m.keywords;
    for (const shaderlab::Property& p : shader.properties) {
        for (const shaderlab::Attribute& a : p.attributes) {
            const pack::PropertyKeywords driven =
                pack::KeywordsDrivenBy(p.name, a.name, a.raw_args);
            if (driven.kind == pack::PropertyKeywords::Kind::kNone)
                continue;
            auto v = m.values.find(p.name);
            const double value = v != m.values.end()       ? v->second
                                 : p.default_value.empty() ? 0.0
                                                           : p.default_value[0];
            const std::string k = pack::KeywordEnabledBy(driven, value);
            if (!k.empty())
                out.insert(k);
        }
    }
    return out;
}

// --keywords names keywords some pass declares: a typo would otherwise build nothing more and
// exit 0.
void CheckRequestedKeywords(CompileState& st) {
    if (!st.options.keywords || st.diags.has_errors())
        return;
    std::set<std::string> declared;
    for (const PassUnit& pu : st.passes) {
        for (const variants::KeywordSet& set : pu.pragmas.sets)
            declared.insert(set.keywords.begin(), set.keywords.end());
    }
    const std::vector<std::string> names(declared.begin(), declared.end());
    for (const std::string& k : *st.options.keywords) {
        if (declared.count(k) || variants::IsNoKeyword(k))
            continue;
        st.diags.Error(DiagCode::kUnknownKeyword, "", kNoPosition,
                       "--keywords names '" + k +
                           "', which no pass of the compiled shaders "
                           "declares" +
                           pack::DidYouMean(k, names));
    }
}

}  // namespace

std::optional<PassUnit> ReadPass(CompileState& st, size_t shader, size_t flat) {
    const ShaderUnit& unit = st.shaders[shader];
    const FlatPass& fp = unit.passes[flat];
    PassUnit pu;
    pu.shader = shader;
    pu.flat = flat;
    const size_t errors_before = st.diags.error_count();
    pu.pragmas = variants::ReadPassPragmas(fp.blocks, unit.file->path(), fp.pass->range, st.diags);
    if (st.diags.error_count() != errors_before)
        return std::nullopt;
    return pu;
}

// Phase 2: pragmas and variant expansion (CompileOptions::requests: driver/requests.cpp).
void ExpandPasses(CompileState& st) {
    for (size_t s = 0; s < st.shaders.size(); ++s) {
        const ShaderUnit& unit = st.shaders[s];
        const std::string& path = unit.file->path();
        variants::VariantRequest request;
        request.all_features = st.options.all_features;
        request.strict_variants = st.options.strict_variants;
        request.max_variants = st.options.max_variants;
        if (st.options.keywords)
            request.feature_combinations.push_back(*st.options.keywords);
        if (auto it = st.options.materials.find(unit.ast ? unit.ast->name : "");
            unit.ast && it != st.options.materials.end()) {
            for (const MaterialRequest& m : it->second)
                request.feature_combinations.push_back(MaterialKeywords(*unit.ast, m));
        }
        for (size_t f = 0; f < unit.passes.size(); ++f) {
            const FlatPass& fp = unit.passes[f];
            if (fp.grab)
                continue;  // no program: pack_emit.cpp records it in its place
            std::optional<PassUnit> read = ReadPass(st, s, f);
            if (!read)
                continue;
            PassUnit& pu = *read;
            variants::VariantRequest budgeted = request;
            budgeted.max_variants = VariantBudget(fp, st.options.max_variants, path, st.diags);
            auto ex = variants::ExpandVariants(pu.pragmas, budgeted, "\"" + fp.label + "\"", path,
                                               fp.program->range, st.diags);
            if (!ex)
                continue;
            pu.expansion = std::move(*ex);
            st.passes.push_back(std::move(pu));
        }
    }
    CheckRequestedKeywords(st);
}

namespace {

// What a task's stage program is assembled from.
hlsl::AssembleInput InputOf(const CompileState& st,
                            size_t p,
                            pack::VariantKey key,
                            pack::Stage stage) {
    const PassUnit& pu = st.passes[p];
    const ShaderUnit& unit = st.shaders[pu.shader];
    const FlatPass& fp = unit.passes[pu.flat];
    hlsl::AssembleInput in;
    in.file_name = LineName((fp.source ? fp.source : unit.file)->path());
    in.blocks = fp.blocks;
    in.stage = stage;
    in.shader_target = pu.pragmas.shader_target;
    in.unity_version = st.options.unity_version;
    in.precision = st.options.precision;
    in.defines = st.options.defines;
    in.undefines = st.options.undefines;
    in.forced_includes = st.options.forced_includes;
    in.light_mode = fp.light_mode;
    // Unity's _vertex/_fragment keyword sets: the other stages (geometry, tessellation) see every
    // keyword, as Unity compiles them.
    const uint32_t skip_flag = stage == pack::Stage::kVertex     ? pack::kKeywordSetFragmentOnly
                               : stage == pack::Stage::kFragment ? pack::kKeywordSetVertexOnly
                                                                 : 0u;
    for (size_t i = 0; i < pu.pragmas.sets.size(); ++i) {
        const auto& set = pu.pragmas.sets[i];
        const auto& layout = pu.expansion.layout[i];
        const std::string& kw = set.keywords[key.Get(layout.shift, layout.bits)];
        if (!kw.empty() && !(set.flags & skip_flag))
            in.keywords.push_back(kw);
    }
    // Instancing needs shader model 3.5: Unity compiles the INSTANCING_ON variants of
    // multi_compile_instancing for at least that target (UnityInstancing.cginc tests
    // SHADER_TARGET >= 35).
    if (std::find(in.keywords.begin(), in.keywords.end(), "INSTANCING_ON") != in.keywords.end())
        in.shader_target = std::max(in.shader_target, 35);
    return in;
}

}  // namespace

std::string SourceOf(const CompileState& st, const StageTask& t) {
    return hlsl::AssembleSource(InputOf(st, t.pass, t.key, t.stage));
}

// One StageTask per (variant, stage) of every pass; its source is assembled when needed.
void CreateTasks(CompileState& st) {
    for (size_t p = 0; p < st.passes.size(); ++p) {
        PassUnit& pu = st.passes[p];
        for (pack::VariantKey key : pu.expansion.keys) {
            for (pack::Stage stage : pu.pragmas.Stages()) {
                StageTask task;
                task.pass = p;
                task.key = key;
                task.stage = stage;
                pu.tasks.push_back(st.tasks.size());
                st.tasks.push_back(std::move(task));
            }
        }
    }
}

}  // namespace kiln::driver
