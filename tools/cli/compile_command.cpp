// kiln compile A.shader [B.shader ...] -o out.kpack [options]: the variant compiler.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "compile_run.h"
#include "kiln/base/files.h"
#include "kiln/compile.h"
#include "kiln/material/sidecar.h"
#include "kiln/show.h"

namespace kiln::cli {
namespace {

std::string DepfileEscape(const std::string& path) {
    std::string out;
    for (char c : path) {
        if (c == ' ' || c == '#' || c == '\\')
            out += '\\';
        if (c == '$')
            out += '$';
        out += c;
    }
    return out;
}

// On `to`: stdout, or stderr when the pack goes to stdout (-o -).
void PrintStats(const CompileStats& s, bool json, FILE* to) {
    const CompileStats::Phases& ms = s.ms;
    if (json) {
        const nlohmann::ordered_json j = {{"permutations", s.permutations},
                                          {"variants", s.variants},
                                          {"profile_stripped", s.profile_stripped},
                                          {"stage_programs", s.stage_programs},
                                          {"unique_programs", s.unique_programs},
                                          {"glslang_compiles", s.glslang_compiles},
                                          {"cache_hits", s.cache_hits},
                                          {"direct_hits", s.direct_hits},
                                          {"shared_preprocesses", s.shared_preprocesses},
                                          {"modules", s.modules},
                                          {"aliased_variants", s.aliased_variants},
                                          {"ms",
                                           {{"load", ms.load},
                                            {"expand", ms.expand},
                                            {"preprocess", ms.preprocess},
                                            {"compile", ms.compile},
                                            {"finish", ms.finish},
                                            {"emit", ms.emit},
                                            {"total", ms.total}}},
                                          {"work_ms",
                                           {{"preprocess", s.work_ms.preprocess},
                                            {"compile", s.work_ms.compile},
                                            {"finish", s.work_ms.finish}}},
                                          {"peak_rss_kib", s.peak_rss_kib},
                                          {"peak_worker_rss_kib", s.peak_worker_rss_kib}};
        std::fprintf(to, "%s\n", j.dump(2).c_str());
        return;
    }
    std::fprintf(
        to,
        "permutations %llu, variants %zu%s, stage programs %zu, unique programs %zu, glslang "
        "compiles %zu, cache hits %zu (direct %zu), shared preprocesses %zu, modules %zu, aliased "
        "variants %zu\n",
        static_cast<unsigned long long>(s.permutations), s.variants,
        s.profile_stripped == 0 ? ""
                                : (" (" + std::to_string(s.profile_stripped) +
                                   " more left out by the stripping profile)")
                                      .c_str(),
        s.stage_programs, s.unique_programs, s.glslang_compiles, s.cache_hits, s.direct_hits,
        s.shared_preprocesses, s.modules, s.aliased_variants);
    std::fprintf(
        to,
        "ms: load %.1f, expand %.1f, preprocess %.1f, compile %.1f, finish %.1f, emit %.1f, total "
        "%.1f\n",
        ms.load, ms.expand, ms.preprocess, ms.compile, ms.finish, ms.emit, ms.total);
    std::fprintf(to, "work ms (all jobs): preprocess %.1f, compile %.1f, finish %.1f\n",
                 s.work_ms.preprocess, s.work_ms.compile, s.work_ms.finish);
    std::fprintf(to, "peak memory: kiln %llu KiB, largest worker %llu KiB\n",
                 static_cast<unsigned long long>(s.peak_rss_kib),
                 static_cast<unsigned long long>(s.peak_worker_rss_kib));
}

}  // namespace

namespace {
// --templates-dir, -j and how glslang runs: kiln compile's options that choose no variant.
void AddToolOptions(CLI::App& cmd, CompilerFlags& f);
}  // namespace

void AddCompilerOptions(CLI::App& cmd, CompilerFlags& f, bool variant_choice) {
    cmd.add_option("-I", f.include_dirs, "Add an include directory (searched in order)");
    cmd.add_option("--project-root", f.project_root,
                   "The Unity project folder that \"Assets/...\" and \"Packages/...\" includes "
                   "start from (default: found above the including file's Assets folder)")
        ->check(CLI::ExistingDirectory);
    cmd.add_option("-D", f.defines, "Define a preprocessor macro NAME or NAME=VALUE");
    cmd.add_option("-U", f.undefines,
                   "Leave a macro of Unity's compile environment undefined (docs/unity-compat.md)");
    cmd.add_option("--include", f.forced_includes,
                   "Include FILE in every program, after Unity's implicit includes");
    cmd.add_option("--unity-version", f.unity_version,
                   "The Unity version to reproduce: UNITY_VERSION (default 2022.3)")
        ->check(CLI::Validator(
            [](std::string& v) {
                return ParseUnityVersion(v) ? std::string()
                                            : "expected a version such as 2022.3 or a "
                                              "UNITY_VERSION number such as 202230";
            },
            ""))
        ->option_text("VERSION");
    cmd.add_option("--precision", f.precision,
                   "What half and fixed are: full (32-bit, as Unity on desktop Vulkan since "
                   "2019), relaxed (min16float, RelaxedPrecision: the driver may use 16 bits; "
                   "as Unity 2018 on Vulkan) or half (binary16 arithmetic; the device needs "
                   "shaderFloat16). Default: what --unity-version's release gives on desktop "
                   "Vulkan (relaxed before 2019.1, else full)")
        ->check(CLI::IsMember({"full", "relaxed", "half"}))
        ->option_text("full|relaxed|half");
    if (!variant_choice) {
        AddToolOptions(cmd, f);
        return;
    }
    cmd.add_option("--materials", f.materials,
                   ".material files or <scene>.kiln.json sidecars: build the shader_feature "
                   "combinations they enable");
    cmd.add_option("--keywords", f.keywords,
                   "shader_feature keywords of one more combination to build, for every shader")
        ->delimiter(',');
    cmd.add_flag("--all-features", f.all_features,
                 "Build every shader_feature combination (default: the all-off one and those "
                 "the materials enable, as Unity does)");
    cmd.add_flag("--strict-variants", f.strict_variants,
                 "Build every multi_compile combination, also those Unity strips when no scene "
                 "uses their feature (lightmaps, fog, instancing), and fail on any of them "
                 "(default: leave those out, as a Unity build with default Graphics Settings)");
    cmd.add_option("--max-variants", f.max_variants,
                   "Largest number of variants a pass may have (default 4096)")
        ->check(CLI::PositiveNumber.description(""))
        ->option_text("N");
    AddToolOptions(cmd, f);
}

namespace {
void AddToolOptions(CLI::App& cmd, CompilerFlags& f) {
    cmd.add_option("--templates-dir", f.templates_dir,
                   "The built-in include library (default: Kiln's templates/)");
    cmd.add_option("-j,--jobs", f.jobs, "Parallel compile jobs (default: all cores)");
    cmd.add_flag("--in-process", f.in_process,
                 "Run glslang and SPIRV-Tools inside kiln instead of in kiln-worker processes "
                 "(for debugging: a crash in them then ends kiln)");
    cmd.add_option("--program-timeout", f.program_timeout,
                   "Seconds one program may take in a worker (default 60)")
        ->check(CLI::Validator(
            [](std::string& v) -> std::string {
                char* end = nullptr;
                const double s = std::strtod(v.c_str(), &end);
                if (end == v.c_str() || *end != '\0' || !(s > 0) || s > 86400)
                    return "must be a number of seconds greater than 0, at most 86400";
                return "";
            },
            ""))
        ->option_text("S");
    cmd.add_option("--program-memory", f.program_memory,
                   "MiB of memory one program may use in a worker (default 2048)")
        ->check(CLI::Range(uint64_t{16}, uint64_t{1} << 24).description(""))
        ->option_text("MIB");
}
}  // namespace

std::optional<int> ParseUnityVersion(const std::string& text) {
    int parts[3] = {0, 0, 0};
    size_t count = 0, i = 0;
    while (i < text.size() && count < 3) {
        size_t j = i;
        while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])))
            ++j;
        if (j == i || j - i > 6)
            return std::nullopt;
        parts[count++] = std::stoi(text.substr(i, j - i));
        if (j == text.size())
            break;
        if (text[j] != '.' || count == 3)
            return std::nullopt;
        i = j + 1;
        if (i == text.size())
            return std::nullopt;
    }
    if (count == 0)
        return std::nullopt;
    if (count == 1)
        return parts[0];  // already a UNITY_VERSION number
    return parts[0] * 100 + std::min(parts[1], 9) * 10 + std::min(parts[2], 9);
}

namespace {

// Why the compile cache folder `dir` cannot be used (created if missing); "" when it can.
std::string CacheUnwritable(const std::string& dir) {
    if (dir.empty())
        return "";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec)
        return ec.message();
    if (access(dir.c_str(), W_OK | X_OK) != 0)
        return std::strerror(errno);
    return "";
}

// Adds the keyword combination of one .material file to `out` (by shader name).
void ReadMaterialKeywords(const std::string& path,
                          CompileOptions& out,
                          std::vector<std::unique_ptr<SourceFile>>& files,
                          DiagnosticList& diags) {
    Result<SourceFile> read = ReadSourceFile(path, material::kMaxFileBytes);
    if (!read) {
        diags.Error(DiagCode::kCannotReadFile, path, kNoPosition, read.error().message);
        return;
    }
    files.push_back(std::make_unique<SourceFile>(std::move(read).value()));
    material::Material m;
    if (!material::ParseMaterial(files.back()->text(), path, m, diags)) {
        return;
    }
    MaterialRequest request;
    for (const material::Keyword& k : m.keywords)
        request.keywords.insert(k.name);
    for (const material::PropertyValue& v : m.properties) {
        if (v.kind == material::PropertyValue::Kind::kNumbers && v.numbers.size() == 1)
            request.values[v.name] = v.numbers[0];
    }
    out.materials[m.shader].push_back(std::move(request));
}

}  // namespace

CompileOptions ToCompileOptions(const CompilerFlags& f,
                                std::vector<std::unique_ptr<SourceFile>>& files,
                                DiagnosticList& diags) {
    CompileOptions o;
    o.include_dirs = f.include_dirs;
    // Searched after the -I folders: an "Assets/..." include names a file under it.
    if (!f.project_root.empty())
        o.include_dirs.push_back(f.project_root);
    for (const std::string& d : f.defines) {
        const size_t eq = d.find('=');
        o.defines.push_back(eq == std::string::npos
                                ? std::make_pair(d, std::string("1"))
                                : std::make_pair(d.substr(0, eq), d.substr(eq + 1)));
    }
    o.undefines = f.undefines;
    for (const std::string& file : f.forced_includes) {
        // As a C compiler's -include: a path that exists relative to the working directory is
        // that file; anything else is looked up like #include "file".
        std::error_code ec;
        o.forced_includes.push_back(
            std::filesystem::exists(file, ec)
                ? std::filesystem::absolute(file).lexically_normal().string()
                : file);
    }
    if (auto v = ParseUnityVersion(f.unity_version))
        o.unity_version = *v;
    o.precision = f.precision.empty() ? DefaultPrecisionFor(o.unity_version)
                                      : pack::PrecisionFromName(f.precision);
    if (!f.keywords.empty())
        o.keywords = std::set<std::string>(f.keywords.begin(), f.keywords.end());
    o.all_features = f.all_features;
    o.strict_variants = f.strict_variants;
    for (const std::string& path : f.materials) {
        if (path.size() >= 10 && path.compare(path.size() - 10, 10, ".kiln.json") == 0) {
            const Result<material::MaterialSidecar> sidecar = material::ReadMaterialSidecar(path);
            if (!sidecar) {
                diags.Error(sidecar.error().code, path, kNoPosition, sidecar.error().message);
                continue;
            }
            for (const auto& [gltf_name, file] : sidecar.value().materials)
                ReadMaterialKeywords(file, o, files, diags);
        } else {
            ReadMaterialKeywords(path, o, files, diags);
        }
    }
    o.max_variants = f.max_variants;
    o.templates_dir = f.templates_dir;
    o.jobs = f.jobs;
    o.isolation = f.in_process ? Isolation::kInProcess : Isolation::kWorkers;
    o.program_timeout_seconds = f.program_timeout;
    o.program_memory_mib = f.program_memory;
    return o;
}

std::vector<const SourceFile*> Views(const CompileOutput& out,
                                     const std::vector<std::unique_ptr<SourceFile>>& more) {
    std::vector<const SourceFile*> views;
    for (const auto& f : out.files)
        views.push_back(f.get());
    for (const auto& f : out.generated)
        views.push_back(f.get());
    for (const auto& f : more)
        views.push_back(f.get());
    return views;
}

namespace {

// Flags that do not go together with scene-driven stripping; "" when they are fine.
std::string CheckStripFlags(const SceneStripFlags& strip, const CompilerFlags& flags) {
    if (!strip.active()) {
        if (strip.explain || strip.explain_json || strip.verify)
            return "--explain, --explain-json and --verify-scene need --scene or --usage";
        return "";
    }
    if (flags.all_features || !flags.keywords.empty() || flags.strict_variants)
        return "--all-features, --keywords and --strict-variants do not apply with --scene or "
               "--usage: the scene's lookups decide every variant";
    if (strip.verify && strip.scenes.empty())
        return "--verify-scene needs --scene (a usage file has no scene to replay)";
    if (flags.materials.size() > 1)
        return "--materials: with --scene, one <scene>.kiln.json sidecar at most";
    for (const std::string& m : flags.materials) {
        if (strip.scenes.empty() || m.size() < 10 || m.compare(m.size() - 10, 10, ".kiln.json"))
            return "--materials '" + m + "': with --scene, --materials takes the scene's " +
                   "<scene>.kiln.json sidecar (material instances come from the scene)";
    }
    return "";
}

// --emit-generated DIR: each surface shader's generated ShaderLab as DIR/<shader>.generated.shader
// (.generated-2.shader for a file's second `#pragma surface`), also when the compile failed:
// that is when it is read.
void EmitGenerated(const std::string& dir,
                   const CompileOutput& out,
                   const std::vector<std::string>& inputs,
                   DiagnosticList& diags) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::map<std::string, int> seen;
    for (const auto& g : out.generated) {
        std::string stem = g->path();
        stem = stem.substr(0, stem.rfind(" (generated"));
        stem = std::filesystem::path(stem).stem().string();
        const int n = ++seen[stem];
        const std::string path =
            (std::filesystem::path(dir) /
             (stem + ".generated" + (n > 1 ? "-" + std::to_string(n) : "") + ".shader"))
                .string();
        if (Status written = base::WriteFileAtomically(path, g->text(), {inputs}); !written.ok())
            diags.Error(DiagCode::kCannotWriteFile, path, kNoPosition, written.error().message);
    }
}

// kiln compile -E: every distinct stage program's text as glslang would compile it, each under a
// comment naming the shader, pass, keywords, stage and entry point. Nothing is compiled.
int PreprocessOnly(const CompileArgs& o, const GlobalOptions& global) {
    if (o.strip.active() || o.md || !o.mf.empty() || !o.stats.empty()) {
        ReportError(global, DiagCode::kBadCommandLine, "",
                    "-E prints the preprocessed programs only; it takes no --scene, --usage, "
                    "-MD, -MF or --stats");
        return int(kExitUsageError);
    }
    std::vector<std::unique_ptr<SourceFile>> material_files;
    DiagnosticList diags = global.NewDiagnostics();
    CompileOptions options = ToCompileOptions(o.flags, material_files, diags);
    options.cache_dir.clear();
    options.keep_programs = true;
    CompileOutput out;
    if (!diags.has_errors())
        out = AnalyzeVariants(o.files, options, diags);
    std::string text;
    for (const ProgramText& p : out.programs)
        text += ProgramView(p) + "\n";
    if (!diags.has_errors()) {
        const std::string target = o.output.empty() ? std::string(base::kStandardStream) : o.output;
        std::vector<std::string> inputs = o.flags.materials;
        inputs.insert(inputs.end(), o.files.begin(), o.files.end());
        for (const auto& f : out.files)
            inputs.push_back(f->path());
        if (Status written = base::WriteFileAtomically(target, text, {inputs}); !written.ok())
            diags.Error(DiagCode::kCannotWriteFile, target, kNoPosition, written.error().message);
    }
    PrintDiagnostics(diags, Views(out, material_files), global);
    return ExitCodeFor(diags);
}

}  // namespace

void AddCompileArgs(CLI::App* cmd, CompileArgs* o) {
    cmd->add_option("files", o->files, "ShaderLab files")->required();
    cmd->add_option("-o,--output", o->output,
                    "The pack to write (- writes it to standard output); with -E, where the "
                    "text goes (default: standard output)");
    cmd->add_flag("-E", o->preprocess_only,
                  "Preprocess only (glslc -E): print the HLSL glslang would compile for every "
                  "distinct stage program, reduced to its entry point, with #line back to the "
                  ".shader; no pack is written");
    AddCompilerOptions(*cmd, o->flags);
    // -O0/-O/-Os, -MD and -MF are rewritten to these before parsing (main.cpp); the help shows
    // the compiler spellings only, as README does.
    cmd->add_option("--opt", o->opt, "")
        ->check(CLI::Validator(
            [](std::string& v) {
                return v == "0" || v == "1" || v == "s" ? std::string()
                                                        : "-O" + v + ": expected -O0, -O or -Os";
            },
            ""))
        ->group("");
    cmd->add_option("--perf-passes", o->perf_passes,
                    "The pass list of -O: kiln (default; SPIRV-Tools' list less what legalization "
                    "did already) or spirv-tools (RegisterPerformancePasses)")
        ->check(CLI::IsMember({"kiln", "spirv-tools"}));
    cmd->add_flag("-g", o->debug, "Keep debug information in the SPIR-V");
    cmd->add_option("--cache-dir", o->cache_dir, "Compile cache (default: the user cache folder)");
    cmd->add_flag("--no-cache", o->no_cache, "Do not read or write the compile cache");
    cmd->add_flag("--md", o->md, "")->group("");
    cmd->add_option("--mf", o->mf, "")->group("");
    cmd->add_flag("--stats{text}", o->stats,
                  "Print variant and compile counts, cache hits, phase times and peak memory on "
                  "stdout; --stats=json as one JSON object")
        ->check(CLI::IsMember({"text", "json"}));
    cmd->add_flag("--no-keyword-aliases", o->no_aliases,
                  "Store every variant, also those of keywords whose SPIR-V duplicates another "
                  "keyword's (pack format 1.0 readers need this)");
    cmd->add_option("--emit-generated", o->emit_generated,
                    "Write the passes generated for each surface shader (#pragma surface) to "
                    "DIR/<shader>.generated.shader, as Unity's \"Show generated code\"")
        ->option_text("DIR");
    AddSceneStripOptions(*cmd, o->strip);
    cmd->footer(
        "Compiler-style options:\n"
        "  -O0 | -O | -Os              Optimization: none, performance (the default; also -O1,\n"
        "                              -O2, -O3) or size\n"
        "  -MD                         Write a depfile of every file read\n"
        "  -MF FILE                    The depfile's path (default: OUTPUT.d)");
}

CompileRun RunCompile(const CompileArgs& o, const GlobalOptions& global) {
    DiagnosticList diags = global.NewDiagnostics();
    // Every file the compile reads: the command line's, then the scene's, then what it included.
    std::vector<std::string> inputs = o.flags.materials;
    inputs.insert(inputs.end(), o.files.begin(), o.files.end());
    if (o.preprocess_only)
        return {PreprocessOnly(o, global), inputs};
    const bool to_stdout = o.output == base::kStandardStream;
    std::string bad_output;
    if (o.output.empty())
        bad_output = "kiln compile needs -o FILE (the pack to write; -o - for standard output)";
    else if (to_stdout && (o.md || !o.mf.empty()))
        bad_output = "-MD and -MF need a pack file to name in the depfile, not -o -";
    else if (to_stdout && (o.strip.explain || o.strip.explain_json))
        bad_output = "--explain prints on standard output, where -o - writes the pack";
    if (!bad_output.empty()) {
        ReportError(global, DiagCode::kBadCommandLine, "", bad_output);
        return {int(kExitUsageError), inputs};
    }
    if (std::string bad = CheckStripFlags(o.strip, o.flags); !bad.empty()) {
        ReportError(global, DiagCode::kBadCommandLine, "", bad);
        return {int(kExitUsageError), inputs};
    }
    std::vector<std::unique_ptr<SourceFile>> material_files;
    // With --scene, --materials are the scene's sidecars (the dry run reads them).
    CompilerFlags flags = o.flags;
    if (o.strip.active())
        flags.materials.clear();
    CompileOptions options = ToCompileOptions(flags, material_files, diags);
    if (diags.has_errors()) {
        PrintDiagnostics(diags, Views(CompileOutput{}, material_files), global);
        return {ExitCodeFor(diags), inputs};
    }
    options.opt_level = o.opt == "0"                     ? OptimizationLevel::kNone
                        : o.opt == "s"                   ? OptimizationLevel::kSize
                        : o.perf_passes == "spirv-tools" ? OptimizationLevel::kPerformanceSpirvTools
                                                         : OptimizationLevel::kPerformance;
    options.debug_info = o.debug;
    options.keyword_aliases = !o.no_aliases;
    options.cache_dir = o.no_cache ? "" : (o.cache_dir.empty() ? DefaultCacheDir() : o.cache_dir);
    if (std::string why = CacheUnwritable(options.cache_dir); !why.empty()) {
        // Never silence: the build works, only slower, and says so once.
        diags.Warning(DiagCode::kCannotWriteFile, options.cache_dir, kNoPosition,
                      "the compile cache cannot be written (" + why + "); compiling without it");
        options.cache_dir.clear();
    }
    const bool tty = isatty(STDERR_FILENO) && global.diag_format == DiagFormat::kText;
    if (tty) {
        options.progress = [](const char* phase, size_t done, size_t total) {
            std::fprintf(stderr, "\r\033[Kkiln: %s %zu/%zu", phase, done, total);
            if (done == total)
                std::fputs("\r\033[K", stderr);
        };
    }
    // gcc's rule: an output that is an input, a directory or a device is refused before any
    // work (and again when written, against every file the compile read).
    for (const std::string& read : SceneStripInputs(o.strip, o.flags.materials)) {
        base::NoteInputFile(read);  // refused when written, too
        inputs.push_back(read);
    }
    const std::string dep_path = o.mf.empty() ? o.output + ".d" : o.mf;
    std::vector<std::string> outputs = {o.output};
    if (o.md || !o.mf.empty())
        outputs.push_back(dep_path);
    if (Status distinct = base::CheckDistinctOutputs({{"-o", o.output}, {"-MF", outputs.back()}});
        outputs.size() > 1 && !distinct.ok()) {
        diags.Error(DiagCode::kCannotWriteFile, o.output, kNoPosition, distinct.error().message);
        PrintDiagnostics(diags, {}, global);
        return {ExitCodeFor(diags), inputs};
    }
    for (const std::string& output : outputs) {
        if (Result<std::string> ok = base::CheckOutputPath(output, inputs); !ok) {
            diags.Error(DiagCode::kCannotWriteFile, output, kNoPosition, ok.error().message);
            PrintDiagnostics(diags, {}, global);
            return {ExitCodeFor(diags), inputs};
        }
    }
    if (o.strip.active() && !PlanRequests(o.strip, o.files, o.flags.materials, options, diags)) {
        PrintDiagnostics(diags, {}, global);
        return {ExitCodeFor(diags), inputs};
    }
    const auto started = std::chrono::steady_clock::now();
    CompileOutput out = CompileShaders(o.files, options, diags);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    for (const auto& f : out.files)
        inputs.push_back(f->path());
    if (!o.emit_generated.empty())
        EmitGenerated(o.emit_generated, out, inputs, diags);
    if (out.ok && o.strip.active() && !VerifyScenes(o.strip, out.pack, o.flags.materials, diags))
        out.ok = false;  // no pack that misses what the scene needs
    if (out.ok && (o.strip.explain || o.strip.explain_json)) {
        DiagnosticList ignored;  // the compile read these shaders already
        PrintExplain(o.strip, out, seconds,
                     BuildSkeletonPack(o.files, options, ignored).pack.size());
    }
    bool pack_written = false;
    if (out.ok) {
        Status written = base::WriteFileAtomically(
            o.output, std::span<const uint8_t>(out.pack.data(), out.pack.size()), {inputs});
        if (!written.ok()) {
            diags.Error(DiagCode::kCannotWriteFile, o.output, kNoPosition, written.error().message);
        }
        pack_written = written.ok();
    }
    if (out.ok && !diags.has_errors() && (o.md || !o.mf.empty())) {
        std::string text = DepfileEscape(o.output) + ":";
        for (const auto& f : out.files) {
            text += " \\\n  " +
                    DepfileEscape(std::filesystem::absolute(f->path()).lexically_normal().string());
        }
        text += "\n";
        Status written = base::WriteFileAtomically(dep_path, text, {inputs});
        if (!written.ok()) {
            diags.Error(DiagCode::kCannotWriteFile, dep_path, kNoPosition, written.error().message);
        }
    }
    if (!o.stats.empty())
        PrintStats(out.stats, o.stats == "json", to_stdout ? stderr : stdout);
    PrintDiagnostics(diags, Views(out, material_files), global);
    return {ExitCodeFor(diags), inputs, pack_written, out.stats.variants};
}

std::function<int()> AddCompileCommand(CLI::App* cmd, const GlobalOptions& global) {
    auto o = std::make_shared<CompileArgs>();
    AddCompileArgs(cmd, o.get());
    return [o, &global]() { return RunCompile(*o, global).exit_code; };
}

}  // namespace kiln::cli
