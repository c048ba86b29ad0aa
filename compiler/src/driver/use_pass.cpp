#include "driver/use_pass.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "driver/isolation.h"
#include "kiln/base/text.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/names.h"
#include "kiln/shaderlab/parse.h"

namespace kiln::driver {
namespace {

namespace fs = std::filesystem;

using base::ToUpper;

// Whether Shader "declared" answers to `name`: the same, or, as Unity finds the built-in shaders
// it moved under "Legacy Shaders/" by their old names (Reflect-BumpVertexLit's
// `UsePass "Reflective/Bumped Unlit/BASE"`), that prefix and the name.
bool Answers(const std::string& declared, const std::string& name) {
    static const std::string kLegacy = "Legacy Shaders/";
    return declared == name || (declared.size() == kLegacy.size() + name.size() &&
                                declared.compare(0, kLegacy.size(), kLegacy) == 0 &&
                                declared.compare(kLegacy.size(), std::string::npos, name) == 0);
}

const ShaderUnit* FindLoaded(const CompileState& st, const std::string& name) {
    for (const ShaderUnit& u : st.shaders) {
        if (u.ast && Answers(u.ast->name, name))
            return &u;
    }
    for (const ShaderUnit& u : st.libraries) {
        if (u.ast && Answers(u.ast->name, name))
            return &u;
    }
    return nullptr;
}

// A .shader file beside `using_file` or in an -I folder that declares Shader "name", loaded into
// st.libraries (parsed and flattened, never compiled on its own), or nullptr.
const ShaderUnit* LoadFromPath(CompileState& st,
                               const std::string& using_file,
                               const std::string& name) {
    std::vector<fs::path> dirs = {fs::path(using_file).parent_path()};
    for (const std::string& d : st.options.include_dirs)
        dirs.emplace_back(d);
    const std::string quoted = name + "\"";  // the end of Shader "[Legacy Shaders/]name"
    for (const fs::path& dir : dirs) {
        std::error_code ec;
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(dir.empty() ? "." : dir, ec)) {
            if (e.is_regular_file(ec) && e.path().extension() == ".shader")
                files.push_back(e.path());
        }
        std::sort(files.begin(), files.end());
        for (const fs::path& f : files) {
            Result<SourceFile> read = ReadSourceFile(f.string());
            if (!read || read.value().text().find(quoted) == std::string_view::npos)
                continue;
            ShaderUnit unit;
            unit.file = std::make_shared<const SourceFile>(std::move(read).value());
            // Parsed only: its own problems are reported, by the checks table, when it is
            // compiled itself; what UsePass takes from it is its passes.
            DiagnosticList ignored;
            unit.ast = shaderlab::Parse(*unit.file, ignored);
            if (!unit.ast || !Answers(unit.ast->name, name))
                continue;
            st.files.Put(unit.file);
            ExpandSurfaceShaders(*unit.ast, *unit.file, IncludePathsFor(st.options), st.files,
                                 st.generated, ignored);
            unit.passes = FlattenPasses(*unit.ast, unit.file->path(), ignored);
            unit.emit = false;
            st.libraries.push_back(std::move(unit));
            return &st.libraries.back();
        }
    }
    return nullptr;
}

// Resolves one placeholder of `unit`; false when it is reported and must be dropped.
bool Resolve(CompileState& st, const ShaderUnit& unit, FlatPass& fp) {
    const shaderlab::UsePass& use = *fp.use_pass;
    const size_t slash = use.target.rfind('/');
    const std::string shader = slash == std::string::npos ? "" : use.target.substr(0, slash);
    const std::string pass = slash == std::string::npos ? use.target : use.target.substr(slash + 1);
    const std::string& file = unit.file->path();
    if (shader.empty() || pass.empty()) {
        st.diags.Error(
            DiagCode::kUnknownUsePass, file, use.range,
            "UsePass needs \"Shader/PASSNAME\", the shader's name and a pass Name; got \"" +
                use.target + "\"");
        return false;
    }
    const ShaderUnit* from = FindLoaded(st, shader);
    if (from == nullptr)
        from = LoadFromPath(st, file, shader);
    if (from == nullptr) {
        std::vector<std::string> names;
        for (const ShaderUnit& u : st.shaders) {
            if (u.ast)
                names.push_back(u.ast->name);
        }
        st.diags.Error(DiagCode::kUnknownUsePass, file, use.range,
                       "UsePass names shader \"" + shader +
                           "\", which is neither in this compile nor a .shader file beside this "
                           "one or in an -I folder" +
                           pack::DidYouMean(shader, names));
        return false;
    }
    std::vector<std::string> pass_names;
    for (const FlatPass& other : from->passes) {
        if (other.pass == nullptr || other.pass->name.empty())
            continue;
        pass_names.push_back(other.pass->name);
        if (ToUpper(other.pass->name) != ToUpper(pass))
            continue;
        const uint32_t subshader = fp.subshader;
        fp = other;
        fp.subshader = subshader;
        if (!fp.source)
            fp.source = from->file;
        return true;
    }
    st.diags.Error(DiagCode::kUnknownUsePass, file, use.range,
                   "UsePass names pass \"" + pass + "\" of shader \"" + shader +
                       "\", which has no pass of that Name" + pack::DidYouMean(pass, pass_names));
    return false;
}

bool IsShadowCaster(const FlatPass& fp) {
    return fp.pass != nullptr &&
           base::EqualsIgnoreCase(fp.light_mode, pack::kLightModeShadowCaster);
}

// The first ShadowCaster pass along the Fallback chain that starts at `unit`'s Fallback, or null.
const FlatPass* FallbackShadowCaster(CompileState& st,
                                     const ShaderUnit& unit,
                                     const ShaderUnit*& owner) {
    const ShaderUnit* at = &unit;
    for (int depth = 0; depth < 8; ++depth) {  // a cycle of fallbacks ends here
        if (!at->ast || !at->ast->fallback || at->ast->fallback->off)
            return nullptr;
        const std::string& name = at->ast->fallback->name;
        const ShaderUnit* next = FindLoaded(st, name);
        if (next == nullptr)
            next = LoadFromPath(st, unit.file->path(), name);
        if (next == nullptr || next == &unit)
            return nullptr;
        for (const FlatPass& fp : next->passes) {
            if (IsShadowCaster(fp)) {
                owner = next;
                return &fp;
            }
        }
        at = next;
    }
    return nullptr;
}

}  // namespace

void AddFallbackShadowCasters(CompileState& st) {
    for (ShaderUnit& unit : st.shaders) {
        if (unit.passes.empty() ||
            std::any_of(unit.passes.begin(), unit.passes.end(), IsShadowCaster))
            continue;
        const ShaderUnit* owner = nullptr;
        const FlatPass* caster = FallbackShadowCaster(st, unit, owner);
        if (caster == nullptr)
            continue;
        FlatPass fp = *caster;
        fp.subshader = unit.passes.front().subshader;
        if (!fp.source)
            fp.source = owner->file;
        // After the first SubShader's passes: the SubShader a renderer picks draws it.
        auto at = std::find_if(unit.passes.begin(), unit.passes.end(),
                               [&](const FlatPass& p) { return p.subshader != fp.subshader; });
        unit.passes.insert(at, std::move(fp));
        LabelPasses(unit.passes);
    }
}

void ResolveUsePasses(CompileState& st) {
    for (ShaderUnit& unit : st.shaders) {
        bool any = false;
        for (const FlatPass& fp : unit.passes)
            any = any || fp.use_pass != nullptr;
        if (!any)
            continue;
        std::vector<FlatPass> kept;
        for (FlatPass& fp : unit.passes) {
            if (fp.use_pass == nullptr || Resolve(st, unit, fp))
                kept.push_back(std::move(fp));
        }
        unit.passes = std::move(kept);
        LabelPasses(unit.passes);
    }
}

}  // namespace kiln::driver
