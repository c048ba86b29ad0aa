// kiln watch: kiln compile, then again each time a file the last builds read changes (shaders,
// includes, material and scene files). Changes are seen with inotify on the files' folders, so
// an editor that saves by renaming a new file over the old one is seen too, and a deleted file
// that comes back; changes within 100 ms of each other make one build. A build with errors
// prints them and writes nothing: the last good pack stays.
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <set>
#include <string>

#include "commands.h"
#include "kiln/base/files.h"
#include "compile_run.h"
#include "file_watch.h"

namespace kiln::cli {
namespace {

struct WatchArgs {
    CompileArgs compile;
    int builds = 0;  // stop after this many builds; 0: until interrupted
};

int Watch(const WatchArgs& a, const GlobalOptions& global) {
    const CompileArgs& o = a.compile;
    if (o.preprocess_only || o.output.empty() || o.output == "-") {
        ReportError(global, DiagCode::kBadCommandLine, "",
                    "kiln watch rewrites a pack file: it needs -o FILE (not -o -) and takes no -E");
        return int(kExitUsageError);
    }
    Watcher watcher;
    if (!watcher.ok()) {
        ReportError(global, DiagCode::kCannotReadFile, "",
                    std::string("cannot watch files (inotify): ") + std::strerror(errno));
        return int(kExitInputError);
    }
    bool any_written = false;
    auto changed_at = std::chrono::steady_clock::now();
    for (int build = 1;; ++build) {
        base::ForgetInputFiles();  // this build's inputs are guarded, not the inodes of old ones
        const CompileRun run = RunCompile(o, global);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - changed_at)
                .count();
        for (const std::string& file : run.read)
            watcher.Add(file);  // before the line below: a change after it is seen
        any_written = any_written || run.written;
        const char* since = build == 1 ? "" : " after the change";
        if (run.written) {
            std::printf("kiln watch: build %d: %s written (%zu variant%s), %.0f ms%s\n", build,
                        o.output.c_str(), run.variants, run.variants == 1 ? "" : "s", ms, since);
        } else {
            std::printf("kiln watch: build %d failed: %s\n", build,
                        any_written ? (o.output + " kept (the last good pack)").c_str()
                                    : "no pack written yet");
        }
        std::fflush(stdout);
        if (a.builds > 0 && build >= a.builds)
            return run.exit_code;
        std::set<std::string> changed = watcher.WaitForChange();
        changed_at = std::chrono::steady_clock::now();
        watcher.Settle(changed);
    }
}

}  // namespace

std::function<int()> AddWatchCommand(CLI::App* cmd, const GlobalOptions& global) {
    auto a = std::make_shared<WatchArgs>();
    AddCompileArgs(cmd, &a->compile);
    cmd->add_option("--builds", a->builds,
                    "Stop after N builds, the first included (for scripts and tests); default: "
                    "until interrupted")
        ->check(CLI::PositiveNumber)
        ->option_text("N");
    return [a, &global]() { return Watch(*a, global); };
}

}  // namespace kiln::cli
