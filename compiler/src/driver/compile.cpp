// The compile driver: parse -> passes -> variants -> assemble -> preprocess -> reduce/dedup ->
// compile (or cache) -> bindings/reflection/validation -> pack.
#include "kiln/compile.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

#include "checks/checks.h"
#include "driver/cache.h"
#include "driver/compile_state.h"
#include "driver/isolation.h"
#include "driver/module_store.h"
#include "driver/parallel.h"
#include "driver/use_pass.h"
#include "frontend/glslang_stage.h"
#include "hlsl/unity_versions.h"
#include "kiln/shaderlab/parse.h"
#include "spirv/optimize.h"

#ifndef KILN_VERSION
#define KILN_VERSION "0.0.0"
#endif

namespace kiln {
namespace fs = std::filesystem;
using driver::CompileState;

namespace {

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
        unit.ast = shaderlab::Parse(*unit.file, st.diags);
        checks::Inputs in{st.diags};
        in.file = unit.file.get();
        if (unit.ast) {
            in.ast = &*unit.ast;
            checks::RunChecks(checks::Input::kAst, false, in);
            driver::ExpandSurfaceShaders(*unit.ast, *unit.file, driver::IncludePathsFor(st.options),
                                         st.files, st.generated, st.diags);
            unit.passes = driver::FlattenPasses(*unit.ast, path, st.diags);
        }
        in.passes = &unit.passes;
        checks::RunChecks(checks::Input::kPrograms, false, in);
        st.shaders.push_back(std::move(unit));
    }
    driver::ResolveUsePasses(st);
    driver::AddFallbackShadowCasters(st);
}

void FillReports(const CompileState& st, CompileOutput& out) {
    DiagnosticList ignored;  // a bad budget tag was reported at expansion
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
        r.profile_stripped = pu.expansion.profile_stripped;
        r.profile_keywords = pu.expansion.profile_keywords;
        r.formula = pu.expansion.formula;
        r.budget = driver::VariantBudget(fp, st.options.max_variants, "", ignored);
        r.variants = pu.expansion.keys.size();
        for (pack::VariantKey key : pu.expansion.keys) {
            r.aliased += std::any_of(st.aliases.begin(), st.aliases.end(), [&](const auto& a) {
                if (&st.passes[a.first] != &pu) {
                    return false;  // another pass's alias: its set indexes that pass's layout
                }
                const variants::SetLayout& l = pu.expansion.layout[a.second.set];
                return key.Get(l.shift, l.bits) == a.second.from;
            });
        }
        std::set<size_t> vs, fs;
        for (size_t t : pu.tasks) {
            if (st.tasks[t].stage == pack::Stage::kVertex)
                vs.insert(st.tasks[t].job);
            else if (st.tasks[t].stage == pack::Stage::kFragment)
                fs.insert(st.tasks[t].job);
        }
        r.unique_vertex = vs.size();
        r.unique_fragment = fs.size();
        out.passes.push_back(std::move(r));
        out.stats.permutations += pu.expansion.permutations;
        out.stats.variants += pu.expansion.keys.size();
        out.stats.profile_stripped += pu.expansion.profile_stripped;
    }
    out.stats.stage_programs = st.tasks.size();
    out.stats.unique_programs = st.jobs.size();
}

// kiln lint's checks over a built pack (checks/checks.h, Input::kPack).
void Lint(CompileState& st, const std::vector<uint8_t>& bytes) {
    Result<pack::Pack> pack = pack::Pack::Open(bytes);
    if (!pack) {
        st.diags.Add(Severity::kInternal, DiagCode::kInternalError, "", kNoPosition,
                     "the pack just built does not open: " + pack.error().message);
        return;
    }
    checks::Inputs in{st.diags};
    in.st = &st;
    in.pack = &pack.value();
    checks::RunChecks(checks::Input::kPack, true, in);
}

// CompileOptions::keep_programs: each job's text, as its first task (the one that keeps it) names
// it, with the number of stage programs that share it.
void KeepPrograms(const CompileState& st, CompileOutput& out) {
    std::vector<size_t> sharing(st.jobs.size(), 0);
    for (const driver::StageTask& t : st.tasks) {
        if (t.preprocess_ok && t.job < sharing.size())
            ++sharing[t.job];
    }
    for (size_t j = 0; j < st.jobs.size(); ++j) {
        const driver::Job& job = st.jobs[j];
        const driver::StageTask& t = st.tasks[job.first_task];
        const driver::PassUnit& pu = st.passes[t.pass];
        const driver::ShaderUnit& unit = st.shaders[pu.shader];
        ProgramText p;
        p.shader = unit.ast ? unit.ast->name : unit.file->path();
        p.pass = unit.passes[pu.flat].label;
        p.keywords = variants::EnabledKeywords(pu.pragmas.sets, pu.expansion.layout, t.key);
        p.stage = t.stage;
        p.entry = job.entry;
        p.variants = sharing[j];
        p.text = t.reduced;
        out.programs.push_back(std::move(p));
    }
}

enum class Mode { kPack, kAnalyze, kSkeleton, kLint };

// Adds the milliseconds since the last call (or construction) to a phase.
class PhaseClock {
  public:
    void Into(double& phase) {
        const auto now = std::chrono::steady_clock::now();
        phase += std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
    }

  private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

void RecordPeakMemory(CompileStats& stats) {
    rusage self{}, children{};
    if (getrusage(RUSAGE_SELF, &self) == 0)
        stats.peak_rss_kib = uint64_t(self.ru_maxrss);  // KiB on Linux
    if (getrusage(RUSAGE_CHILDREN, &children) == 0)
        stats.peak_worker_rss_kib = uint64_t(children.ru_maxrss);
}

// The reports, the workers' end and peak memory, and the files read: the end of every compile.
CompileOutput Finish(CompileState& st,
                     CompileOutput& out,
                     std::unique_ptr<worker::Executor>& exec,
                     PhaseClock& whole) {
    FillReports(st, out);
    driver::FillStripReport(st, out);
    // The workers end (and are waited for) with the executor: only then does the kernel count
    // their peak memory among this process's children.
    st.exec = nullptr;
    exec.reset();
    whole.Into(out.stats.ms.total);
    auto ms_of = [&st](worker::RequestKind k) {
        return double(st.work_ns[size_t(k)].load()) / 1e6;
    };
    out.stats.work_ms = {
        ms_of(worker::RequestKind::kPreprocess),
        ms_of(worker::RequestKind::kCompile) + ms_of(worker::RequestKind::kValidate),
        ms_of(worker::RequestKind::kFinish)};
    RecordPeakMemory(out.stats);
    out.files = st.files.Files();
    for (const driver::GeneratedSource& g : st.generated)
        out.generated.push_back(g.file);
    out.ok = !st.diags.has_errors();
    if (!out.ok)
        out.pack.clear();
    return std::move(out);
}

CompileOutput Run(const std::vector<std::string>& paths,
                  const CompileOptions& options,
                  DiagnosticList& diags,
                  Mode mode) {
    frontend::InitializeGlslang();  // before any thread starts
    CompileState st{options, diags, nullptr, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
    CompileOutput out;
    PhaseClock clock, whole;
    CompileStats::Phases& ms = out.stats.ms;
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
    clock.Into(ms.load);
    if (mode == Mode::kSkeleton) {
        if (!diags.has_errors())
            driver::ExpandRequestedPasses(st, true);
        if (!diags.has_errors())
            out.pack = driver::EmitPack(st, out.stats);
        FillReports(st, out);
        out.files = st.files.Files();
        for (const driver::GeneratedSource& g : st.generated)
            out.generated.push_back(g.file);
        out.ok = !diags.has_errors();
        if (!out.ok)
            out.pack.clear();
        return out;
    }
    std::unique_ptr<worker::Executor> exec;
    if (!diags.has_errors()) {
        exec = driver::MakeExecutor(st);
        st.exec = exec.get();
        if (!options.cache_dir.empty()) {
            std::vector<std::string> shaders;
            for (const auto& shader : st.shaders)
                shaders.push_back(shader.file->path());
            st.modules = std::make_shared<driver::ModuleStore>(driver::Cache(options.cache_dir),
                                                               std::move(shaders));
        }
    }
    if (!diags.has_errors()) {
        if (options.requests) {
            driver::ExpandRequestedPasses(st, false);
        } else {
            driver::ExpandPasses(st);
        }
    }
    if (!diags.has_errors())
        driver::CreateTasks(st);
    clock.Into(ms.expand);
    // Loading and expansion run every time, so their warnings are shown every time; a pack kept
    // whole keeps the warnings of the steps after them, to report them again when it is taken.
    const size_t diags_after_expand = diags.all().size();
    bool preprocessed = false;
    if (!diags.has_errors()) {
        // Kept texts need every program preprocessed: the direct mode would skip them.
        const bool known =
            mode != Mode::kAnalyze && !options.keep_programs && driver::LookUpDirect(st);
        if (known && mode == Mode::kPack) {
            if (auto pack = driver::LoadCachedPack(st, out.stats)) {
                // Nothing changed since a compile without errors: its pack (and the warnings
                // of the steps skipped, reported again).
                driver::DedupKnown(st, out.stats);
                out.stats.cache_hits = st.jobs.size();
                out.pack = std::move(*pack);
                clock.Into(ms.preprocess);
                return Finish(st, out, exec, whole);
            }
        }
        driver::PreprocessAndDedup(st, out.stats, mode != Mode::kAnalyze && !options.keep_programs);
        preprocessed = true;
        if (options.keep_programs)
            KeepPrograms(st, out);
    }
    clock.Into(ms.preprocess);
    if (mode == Mode::kAnalyze) {
        if (preprocessed)
            driver::ReportJobDiagnostics(st);
    } else if (!diags.has_errors()) {
        driver::CompileJobs(st, out.stats);
        if (st.modules)
            st.modules->Flush();  // one file of modules per shader file name
        driver::ReportJobDiagnostics(st);
        clock.Into(ms.compile);
        if (!diags.has_errors())
            driver::FinishModules(st);
        if (!diags.has_errors()) {
            checks::Inputs in{st.diags};
            in.st = &st;
            checks::RunChecks(checks::Input::kReflection, mode == Mode::kLint, in);
        }
        clock.Into(ms.finish);
        if (!diags.has_errors())
            out.pack = driver::EmitPack(st, out.stats);
        if (mode == Mode::kLint && !diags.has_errors())
            Lint(st, out.pack);
        if (mode == Mode::kPack && !diags.has_errors())
            driver::StoreCachedPack(st, out.stats, out.pack, diags_after_expand);
        clock.Into(ms.emit);
    }
    return Finish(st, out, exec, whole);
}

// The -W options (the caller's list's WarningPolicy) apply to what the caller is shown, not to
// what the compile caches keep: the compile reports into a list without them, then hands every
// diagnostic over, and a warning the options make an error fails the compile then.
CompileOutput RunUnderPolicy(const std::vector<std::string>& paths,
                             const CompileOptions& options,
                             DiagnosticList& diags,
                             Mode mode) {
    DiagnosticList raw;
    CompileOutput out = Run(paths, options, raw, mode);
    diags.Append(raw);
    if (diags.has_errors()) {
        out.ok = false;
        out.pack.clear();
    }
    return out;
}

}  // namespace

CompileOutput CompileShaders(const std::vector<std::string>& paths,
                             const CompileOptions& options,
                             DiagnosticList& diags) {
    return RunUnderPolicy(paths, options, diags, Mode::kPack);
}

CompileOutput AnalyzeVariants(const std::vector<std::string>& paths,
                              const CompileOptions& options,
                              DiagnosticList& diags) {
    return RunUnderPolicy(paths, options, diags, Mode::kAnalyze);
}

CompileOutput BuildSkeletonPack(const std::vector<std::string>& paths,
                                const CompileOptions& options,
                                DiagnosticList& diags) {
    return RunUnderPolicy(paths, options, diags, Mode::kSkeleton);
}

CompileOutput LintShaders(const std::vector<std::string>& paths,
                          const CompileOptions& options,
                          DiagnosticList& diags) {
    CompileOptions every = options;
    every.all_features = true;
    every.keywords.reset();
    every.materials.clear();
    every.requests.reset();
    return RunUnderPolicy(paths, every, diags, Mode::kLint);
}

pack::Precision DefaultPrecisionFor(int unity_version) {
    return hlsl::DefaultPrecision(unity_version);
}

std::string DefaultTemplatesDir() {
    if (const char* env = std::getenv("KILN_TEMPLATES_DIR"); env && *env)
        return env;
    // <prefix>/bin/<program> -> <prefix>/share/kiln/templates: an installed Kiln, and the build
    // tree, where CMake links build/share/kiln/templates to the source tree's templates/. Found
    // once per process (each stage program's request names it).
    static const std::string beside_program = [] {
        std::error_code ec;
        const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (ec)
            return std::string();
        const std::filesystem::path dir = exe.parent_path().parent_path() / "share/kiln/templates";
        if (!std::filesystem::is_directory(dir, ec))
            return std::string();
        // The real folder (the build tree's is a link): what depfiles and messages name.
        const std::filesystem::path real = std::filesystem::canonical(dir, ec);
        return ec ? dir.string() : real.string();
    }();
    return beside_program;
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
