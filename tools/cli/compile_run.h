// What `kiln compile` and `kiln watch` share: the compile command's arguments and one run of it
// (compile_command.cpp), which watch repeats on every change (watch_command.cpp).
#ifndef KILN_TOOLS_CLI_COMPILE_RUN_H_
#define KILN_TOOLS_CLI_COMPILE_RUN_H_

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "commands.h"

namespace kiln::cli {

struct CompileArgs {
    std::vector<std::string> files;
    std::string output;
    CompilerFlags flags;
    std::string opt = "1";
    std::string perf_passes = "kiln";
    bool debug = false;
    std::string cache_dir;
    bool no_cache = false;
    bool md = false;
    std::string mf;
    std::string stats;  // "", "text" or "json"
    bool no_aliases = false;
    bool preprocess_only = false;  // -E
    std::string emit_generated;    // --emit-generated DIR
    SceneStripFlags strip;
};

// Adds kiln compile's arguments and options to `cmd`, parsed into `o`.
void AddCompileArgs(CLI::App* cmd, CompileArgs* o);

struct CompileRun {
    int exit_code = 0;
    std::vector<std::string> read;  // every file the run read (or tried to), given ones first
    bool written = false;           // the pack was written
    size_t variants = 0;
};

// One kiln compile: diagnostics printed, the pack (and depfile) written when it succeeds; on any
// error nothing is written, so a pack from an earlier run stays.
CompileRun RunCompile(const CompileArgs& o, const GlobalOptions& global);

}  // namespace kiln::cli

#endif  // KILN_TOOLS_CLI_COMPILE_RUN_H_
