// The compile driver: parse -> passes -> variants -> assemble -> preprocess -> reduce/dedup ->
// compile (or cache) -> bindings/reflection/validation -> pack.
#include "kiln/compile.h"

#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

#include "driver/cache.h"
#include "driver/compile_state.h"
#include "driver/isolation.h"
#include "driver/parallel.h"
#include "frontend/glslang_stage.h"
#include "hlsl/assemble.h"
#include "hlsl/identifier.h"
#include "hlsl/precheck.h"
#include "kiln/pack/names.h"
#include "kiln/pack/property_keywords.h"
#include "kiln/shaderlab/parse.h"
#include "spirv/optimize.h"

#ifndef KILN_VERSION
#define KILN_VERSION "0.0.0"
#endif

namespace kiln {
namespace fs = std::filesystem;
using driver::CompileState;

namespace {

std::string LineName(const std::string& path) {
    return hlsl::IsLineSafeName(path) ? path : std::string("<unprintable path>");
}

// Phase 1: read, parse and check every shader; flatten passes.
void LoadShaders(CompileState& st, const std::vector<std::string>& paths) {
    for (const std::string& path : paths) {
        driver::ShaderUnit unit;
        Result<SourceFile> read = ReadSourceFile(path);
        if (!read) {
            st.diags.Error(DiagCode::kCannotReadFile, path, kNoPosition, read.error().message);
            continue;
        }
        unit.file = std::make_shared<const SourceFile>(std::move(read).value());
        st.files.Put(unit.file);
        unit.ast = shaderlab::ParseAndCheck(*unit.file, st.diags);
        if (unit.ast)
            unit.passes = driver::FlattenPasses(*unit.ast, path, st.diags);
        hlsl::Prechecker precheck(*unit.file, {}, st.diags);
        for (const driver::FlatPass& fp : unit.passes)
            precheck.CheckPass(fp.blocks);
        st.shaders.push_back(std::move(unit));
    }
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
    for (const driver::PassUnit& pu : st.passes) {
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

// Phase 2: pragmas and variant expansion (CompileOptions::requests: driver/requests.cpp).
void ExpandPasses(CompileState& st) {
    for (size_t s = 0; s < st.shaders.size(); ++s) {
        const driver::ShaderUnit& unit = st.shaders[s];
        const std::string& path = unit.file->path();
        variants::VariantRequest request;
        request.all_features = st.options.all_features;
        request.max_variants = st.options.max_variants;
        if (st.options.keywords)
            request.feature_combinations.push_back(*st.options.keywords);
        if (auto it = st.options.materials.find(unit.ast ? unit.ast->name : "");
            unit.ast && it != st.options.materials.end()) {
            for (const MaterialRequest& m : it->second)
                request.feature_combinations.push_back(MaterialKeywords(*unit.ast, m));
        }
        for (size_t f = 0; f < unit.passes.size(); ++f) {
            const driver::FlatPass& fp = unit.passes[f];
            driver::PassUnit pu;
            pu.shader = s;
            pu.flat = f;
            const size_t errors_before = st.diags.error_count();
            pu.pragmas = variants::ReadPassPragmas(fp.blocks, path, fp.pass->range, st.diags);
            if (st.diags.error_count() != errors_before)
                continue;
            auto ex = variants::ExpandVariants(pu.pragmas, request, "\"" + fp.label + "\"", path,
                                               fp.program->range, st.diags);
            if (!ex)
                continue;
            pu.expansion = std::move(*ex);
            st.passes.push_back(std::move(pu));
        }
    }
    CheckRequestedKeywords(st);
}

// One StageTask per (variant, stage) of every pass: its assembled source.
void CreateTasks(CompileState& st) {
    for (size_t p = 0; p < st.passes.size(); ++p) {
        driver::PassUnit& pu = st.passes[p];
        const driver::ShaderUnit& unit = st.shaders[pu.shader];
        const driver::FlatPass& fp = unit.passes[pu.flat];
        for (pack::VariantKey key : pu.expansion.keys) {
            for (pack::Stage stage : {pack::Stage::kVertex, pack::Stage::kFragment}) {
                hlsl::AssembleInput in;
                in.file_name = LineName(unit.file->path());
                in.blocks = fp.blocks;
                in.stage = stage;
                in.shader_target = pu.pragmas.shader_target;
                in.unity_version = st.options.unity_version;
                in.defines = st.options.defines;
                in.undefines = st.options.undefines;
                in.forced_includes = st.options.forced_includes;
                in.light_mode = fp.light_mode;
                const uint32_t skip_flag = stage == pack::Stage::kVertex
                                               ? pack::kKeywordSetFragmentOnly
                                               : pack::kKeywordSetVertexOnly;
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
                if (std::find(in.keywords.begin(), in.keywords.end(), "INSTANCING_ON") !=
                    in.keywords.end()) {
                    in.shader_target = std::max(in.shader_target, 35);
                }
                driver::StageTask task;
                task.pass = p;
                task.key = key;
                task.stage = stage;
                task.source = hlsl::AssembleSource(in);
                pu.tasks.push_back(st.tasks.size());
                st.tasks.push_back(std::move(task));
            }
        }
    }
}

// Phase 3: preprocess every task (in the workers) and dedup the reduced texts into jobs.
void PreprocessAndDedup(CompileState& st) {
    driver::ParallelFor(
        st.tasks.size(), st.options.jobs,
        [&](size_t i) {
            driver::StageTask& t = st.tasks[i];
            worker::Request request = driver::StageRequest(st, t, worker::RequestKind::kPreprocess);
            request.source = t.source;
            worker::Outcome o = st.exec->Run(request);
            if ((t.failure = driver::OutcomeDiagnostic(st, t, o)))
                return;
            for (const std::string& f : o.response.files_read)
                st.files.Get(f);  // for diagnostics and the depfile (a no-op in-process)
            t.preprocess_ok = o.response.ok;
            t.preprocess_log = std::move(o.response.info_log);
            t.reduced = std::move(o.response.text);
            t.rewritten = std::move(o.response.rewritten);
            t.functions_if_entry_missing = std::move(o.response.functions);
        },
        [&](size_t done) { driver::Progress(st.options, "preprocessing", done, st.tasks.size()); });

    const std::string versions = ProducerVersion();
    const std::string options =
        "O" + std::to_string(int(st.options.opt_level)) + (st.options.debug_info ? "g" : "");
    std::map<std::string, size_t> by_key;
    for (size_t i = 0; i < st.tasks.size(); ++i) {
        driver::StageTask& t = st.tasks[i];
        if (!t.preprocess_ok) {
            // Each failing preprocess is its own job so its messages are reported per variant.
            driver::Job job;
            job.stage = t.stage;
            job.entry = driver::EntryOf(st, t);
            job.first_task = i;
            if (t.failure)
                job.diags.push_back(*t.failure);
            else
                driver::AppendGlslangLog(st, t.preprocess_log, job.diags, &t.source);
            t.job = st.jobs.size();
            st.jobs.push_back(std::move(job));
            continue;
        }
        const std::string key =
            driver::HashKey({versions, options, t.stage == pack::Stage::kVertex ? "vert" : "frag",
                             driver::EntryOf(st, t), t.reduced});
        auto [it, fresh] = by_key.emplace(key, st.jobs.size());
        if (fresh) {
            driver::Job job;
            job.stage = t.stage;
            job.entry = driver::EntryOf(st, t);
            job.first_task = i;
            job.cache_key = key;
            st.jobs.push_back(std::move(job));
        }
        t.job = it->second;
    }
}

void FillReports(const CompileState& st, CompileOutput& out) {
    for (const driver::PassUnit& pu : st.passes) {
        const driver::ShaderUnit& unit = st.shaders[pu.shader];
        const driver::FlatPass& fp = unit.passes[pu.flat];
        PassReport r;
        r.shader = unit.ast->name;
        r.pass = fp.label;
        r.light_mode = fp.light_mode;
        for (const auto& s : pu.pragmas.sets) {
            KeywordSetReport k;
            k.pragma = s.pragma;
            k.keywords = s.keywords;
            k.shader_feature = s.kind == pack::KeywordSetKind::kShaderFeature;
            k.stage = (s.flags & pack::kKeywordSetVertexOnly)     ? "vertex"
                      : (s.flags & pack::kKeywordSetFragmentOnly) ? "fragment"
                                                                  : "";
            r.sets.push_back(std::move(k));
        }
        r.permutations = pu.expansion.permutations;
        r.variants = pu.expansion.keys.size();
        std::set<size_t> vs, fs;
        for (size_t t : pu.tasks) {
            (st.tasks[t].stage == pack::Stage::kVertex ? vs : fs).insert(st.tasks[t].job);
        }
        r.unique_vertex = vs.size();
        r.unique_fragment = fs.size();
        out.passes.push_back(std::move(r));
        out.stats.permutations += pu.expansion.permutations;
        out.stats.variants += pu.expansion.keys.size();
    }
    out.stats.stage_programs = st.tasks.size();
    out.stats.unique_programs = st.jobs.size();
}

enum class Mode { kPack, kAnalyze, kSkeleton };

CompileOutput Run(const std::vector<std::string>& paths,
                  const CompileOptions& options,
                  DiagnosticList& diags,
                  Mode mode) {
    frontend::InitializeGlslang();  // before any thread starts
    CompileState st{options, diags, nullptr, {}, {}, {}, {}, {}, {}, {}};
    CompileOutput out;
    if (options.templates_dir.empty() && DefaultTemplatesDir().empty()) {
        // An installed kiln without its share/kiln folder, or a program linking the library
        // that names none: every Unity include would fail, one confusing error per program.
        diags.Error(DiagCode::kCannotReadFile, "", kNoPosition,
                    "cannot find Kiln's templates (UnityCG.cginc and the other built-in "
                    "includes): not in ../share/kiln/templates beside the program; set "
                    "KILN_TEMPLATES_DIR or --templates-dir");
        return out;
    }
    LoadShaders(st, paths);
    if (mode == Mode::kSkeleton) {
        if (!diags.has_errors())
            driver::ExpandRequestedPasses(st, true);
        if (!diags.has_errors())
            out.pack = driver::EmitPack(st, out.stats);
        FillReports(st, out);
        out.files = st.files.Files();
        out.ok = !diags.has_errors();
        if (!out.ok)
            out.pack.clear();
        return out;
    }
    std::unique_ptr<worker::Executor> exec;
    if (!diags.has_errors()) {
        exec = driver::MakeExecutor(st);
        st.exec = exec.get();
    }
    if (!diags.has_errors()) {
        if (options.requests) {
            driver::ExpandRequestedPasses(st, false);
        } else {
            ExpandPasses(st);
        }
    }
    if (!diags.has_errors())
        CreateTasks(st);
    bool preprocessed = false;
    if (!diags.has_errors()) {
        PreprocessAndDedup(st);
        preprocessed = true;
    }
    if (mode == Mode::kAnalyze) {
        if (preprocessed)
            driver::ReportJobDiagnostics(st);
    } else if (!diags.has_errors()) {
        driver::CompileJobs(st, out.stats);
        driver::ReportJobDiagnostics(st);
        if (!diags.has_errors())
            driver::FinishModules(st);
        if (!diags.has_errors())
            driver::CheckInterfaces(st);
        if (!diags.has_errors())
            out.pack = driver::EmitPack(st, out.stats);
    }
    FillReports(st, out);
    driver::FillStripReport(st, out);
    out.files = st.files.Files();
    out.ok = !diags.has_errors();
    if (!out.ok)
        out.pack.clear();
    return out;
}

}  // namespace

CompileOutput CompileShaders(const std::vector<std::string>& paths,
                             const CompileOptions& options,
                             DiagnosticList& diags) {
    return Run(paths, options, diags, Mode::kPack);
}

CompileOutput AnalyzeVariants(const std::vector<std::string>& paths,
                              const CompileOptions& options,
                              DiagnosticList& diags) {
    return Run(paths, options, diags, Mode::kAnalyze);
}

CompileOutput BuildSkeletonPack(const std::vector<std::string>& paths,
                                const CompileOptions& options,
                                DiagnosticList& diags) {
    return Run(paths, options, diags, Mode::kSkeleton);
}

std::string DefaultTemplatesDir() {
    if (const char* env = std::getenv("KILN_TEMPLATES_DIR"); env && *env)
        return env;
    // <prefix>/bin/<program> -> <prefix>/share/kiln/templates: an installed Kiln, and the build
    // tree, where CMake links build/share/kiln/templates to the source tree's templates/.
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec)
        return "";
    const std::filesystem::path dir = exe.parent_path().parent_path() / "share/kiln/templates";
    if (!std::filesystem::is_directory(dir, ec))
        return "";
    // The real folder (the build tree's is a link): what depfiles and messages name.
    const std::filesystem::path real = std::filesystem::canonical(dir, ec);
    return ec ? dir.string() : real.string();
}

std::string DefaultCacheDir() {
    if (const char* env = std::getenv("KILN_CACHE_DIR"); env && *env)
        return env;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return (fs::path(xdg) / "kiln").string();
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return (fs::path(home) / ".cache" / "kiln").string();
    }
    return "";
}

std::string ProducerVersion() {
    return std::string("kiln ") + KILN_VERSION + "; glslang " + frontend::GlslangVersion() +
           "; SPIRV-Tools " + spirv::SpirvToolsVersion();
}

}  // namespace kiln
