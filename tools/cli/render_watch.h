// kiln render --watch: after the first frame, each change of a pack or of a file the scene was
// made from is drawn: a pack is replaced in the running renderer (Renderer::ReplacePack), the
// scene loaded again, the frame rendered and written.
#ifndef KILN_TOOLS_CLI_RENDER_WATCH_H_
#define KILN_TOOLS_CLI_RENDER_WATCH_H_

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kiln/result.h"
#include "kiln/runtime/renderer.h"

namespace kiln::cli {

struct WatchedScene {
    std::vector<std::string> packs;                   // the renderer's, from index 0
    std::function<std::vector<std::string>()> files;  // what the scene is made from, now
    std::function<std::optional<int>()> load_scene;   // loads it again; an exit code on error
    std::function<int()> draw;                        // renders and writes a frame; exit code
    std::function<void()> next_frame;                 // before each frame after the first
    std::function<void(const Error&, const std::string&)> report;  // an error about a file
};

// Runs until interrupted; each frame's line on `summary`.
int WatchScene(runtime::Renderer& renderer, const WatchedScene& w, FILE* summary);

}  // namespace kiln::cli

#endif  // KILN_TOOLS_CLI_RENDER_WATCH_H_
