#include "render_watch.h"

#include <chrono>
#include <set>

#include "commands.h"
#include "file_watch.h"
#include "kiln/base/files.h"

namespace kiln::cli {

int WatchScene(runtime::Renderer& renderer, const WatchedScene& w, FILE* summary) {
    Watcher watcher;
    if (!watcher.ok()) {
        w.report(Error{DiagCode::kCannotReadFile, "cannot watch files (inotify)"}, "");
        return int(kExitInputError);
    }
    std::fflush(summary);  // the first frame's line, before the wait
    for (const std::string& p : w.packs)
        watcher.Add(p);
    for (const std::string& f : w.files())
        watcher.Add(f);
    for (int frame = 2;; ++frame) {
        std::set<std::string> changed = watcher.WaitForChange();
        const auto started = std::chrono::steady_clock::now();
        watcher.Settle(changed);
        w.next_frame();
        base::ForgetInputFiles();  // this frame's inputs are guarded, not replaced files' inodes
        for (size_t i = 0; i < w.packs.size(); ++i) {
            if (!changed.erase(Watcher::Normal(w.packs[i])))
                continue;
            const Result<runtime::Renderer::PackReload> r = renderer.ReplacePack(i, w.packs[i]);
            if (!r) {
                w.report(r.error(), w.packs[i]);  // the previous pack is still drawn
                continue;
            }
            std::fprintf(summary, "%s: replaced, %u pipelines kept, %u to make again\n",
                         w.packs[i].c_str(), r.value().pipelines_kept, r.value().pipelines_dropped);
            std::fflush(summary);
        }
        if (!changed.empty()) {  // a file of the scene
            if (w.load_scene())
                continue;  // its errors are printed; the next change is waited for
            for (const std::string& f : w.files())
                watcher.Add(f);
        }
        w.draw();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
                .count();
        std::fprintf(summary, "kiln render --watch: frame %d drawn %.0f ms after the change\n",
                     frame, ms);
        std::fflush(summary);
    }
}

}  // namespace kiln::cli
