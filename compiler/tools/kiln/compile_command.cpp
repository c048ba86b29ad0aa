// kiln compile A.shader [B.shader ...] -o out.kpack [options]: the variant compiler.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "commands.h"
#include "kiln/compile.h"

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

}  // namespace

void AddCompilerOptions(CLI::App& cmd, CompilerFlags& f) {
    cmd.add_option("-I", f.include_dirs, "Add an include directory (searched in order)");
    cmd.add_option("-D", f.defines, "Define a preprocessor macro NAME or NAME=VALUE");
    cmd.add_option("--keywords", f.keywords,
                   "shader_feature keywords to build (default: all shader_feature variants)")
        ->delimiter(',');
    cmd.add_option("--max-variants", f.max_variants, "Largest number of variants a pass may have")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--templates-dir", f.templates_dir,
                   "The built-in include library (default: Kiln's templates/)");
    cmd.add_option("-j,--jobs", f.jobs, "Parallel compile jobs (default: all cores)");
}

CompileOptions ToCompileOptions(const CompilerFlags& f) {
    CompileOptions o;
    o.include_dirs = f.include_dirs;
    for (const std::string& d : f.defines) {
        const size_t eq = d.find('=');
        o.defines.push_back(eq == std::string::npos
                                ? std::make_pair(d, std::string("1"))
                                : std::make_pair(d.substr(0, eq), d.substr(eq + 1)));
    }
    if (!f.keywords.empty())
        o.keywords = std::set<std::string>(f.keywords.begin(), f.keywords.end());
    o.max_variants = f.max_variants;
    o.templates_dir = f.templates_dir;
    o.jobs = f.jobs;
    return o;
}

std::vector<const SourceFile*> Views(const CompileOutput& out) {
    std::vector<const SourceFile*> views;
    for (const auto& f : out.files)
        views.push_back(f.get());
    return views;
}

std::function<int()> AddCompileCommand(CLI::App& app, const GlobalOptions& global) {
    struct Options {
        std::vector<std::string> files;
        std::string output;
        CompilerFlags flags;
        std::string opt = "1";
        bool debug = false;
        std::string cache_dir;
        bool no_cache = false;
        bool md = false;
        std::string mf;
        bool stats = false;
    };
    auto o = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("compile", "Compile .shader files into a variant pack");
    cmd->add_option("files", o->files, "ShaderLab files")->required();
    cmd->add_option("-o,--output", o->output, "The pack to write")->required();
    AddCompilerOptions(*cmd, o->flags);
    cmd->add_option("--opt", o->opt, "Optimization: 0 (-O0), 1 (-O, default) or s (-Os)")
        ->check(CLI::IsMember({"0", "1", "s"}));
    cmd->add_flag("-g", o->debug, "Keep debug information in the SPIR-V");
    cmd->add_option("--cache-dir", o->cache_dir, "Compile cache (default: the user cache folder)");
    cmd->add_flag("--no-cache", o->no_cache, "Do not read or write the compile cache");
    cmd->add_flag("--md", o->md, "Write a depfile of every file read (-MD)");
    cmd->add_option("--mf", o->mf, "Depfile path (-MF; default: OUTPUT.d)");
    cmd->add_flag("--stats", o->stats, "Print variant and compile counts on stdout");

    return [o, &global]() {
        CompileOptions options = ToCompileOptions(o->flags);
        options.opt_level = o->opt == "0"   ? OptimizationLevel::kNone
                            : o->opt == "s" ? OptimizationLevel::kSize
                                            : OptimizationLevel::kPerformance;
        options.debug_info = o->debug;
        options.cache_dir =
            o->no_cache ? "" : (o->cache_dir.empty() ? DefaultCacheDir() : o->cache_dir);
        const bool tty = isatty(STDERR_FILENO) && global.diag_format == DiagFormat::kText;
        if (tty) {
            options.progress = [](const char* phase, size_t done, size_t total) {
                std::fprintf(stderr, "\r\033[Kkiln: %s %zu/%zu", phase, done, total);
                if (done == total)
                    std::fputs("\r\033[K", stderr);
            };
        }
        DiagnosticList diags;
        CompileOutput out = CompileShaders(o->files, options, diags);
        if (out.ok) {
            Result<bool> written = WriteFileAtomic(o->output, out.pack);
            if (!written) {
                diags.Error(DiagCode::kCannotWriteFile, o->output, {}, written.error().message);
            }
        }
        if (out.ok && !diags.has_errors() && (o->md || !o->mf.empty())) {
            const std::string dep_path = o->mf.empty() ? o->output + ".d" : o->mf;
            std::string text = DepfileEscape(o->output) + ":";
            for (const auto& f : out.files) {
                text +=
                    " \\\n  " +
                    DepfileEscape(std::filesystem::absolute(f->path()).lexically_normal().string());
            }
            text += "\n";
            Result<bool> written =
                WriteFileAtomic(dep_path, std::vector<uint8_t>(text.begin(), text.end()));
            if (!written) {
                diags.Error(DiagCode::kCannotWriteFile, dep_path, {}, written.error().message);
            }
        }
        if (o->stats) {
            const CompileStats& s = out.stats;
            std::printf(
                "permutations %llu, variants %zu, stage programs %zu, unique programs %zu, "
                "glslang compiles %zu, cache hits %zu, modules %zu\n",
                static_cast<unsigned long long>(s.permutations), s.variants, s.stage_programs,
                s.unique_programs, s.glslang_compiles, s.cache_hits, s.modules);
        }
        PrintDiagnostics(diags, Views(out), global);
        return ExitCodeFor(diags);
    };
}

}  // namespace kiln::cli
