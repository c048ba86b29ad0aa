// The frame debugger's pages (kiln render --frame-debug DIR): a captured frame
// (kiln/runtime/frame_capture.h) written as PNGs, a JSON record and an index.html to step through
// in a browser.
#ifndef KILN_TOOLS_FRAME_DEBUG_H_
#define KILN_TOOLS_FRAME_DEBUG_H_

#include <string>

#include "kiln/result.h"
#include "kiln/runtime/frame_capture.h"

namespace kiln::tools {

// Writes `capture` into `dir` (created if missing): steps/NNNN-<target>.png for every image,
// frame.json with every step's record, and index.html listing the passes and their steps with
// their images. The PNGs are written first and the page last. With a `live_stamp` (kiln render
// --watch, a name for this frame) the page reloads itself, in a browser, once live.js, written
// after it, names another frame.
Status WriteFrameDebug(const std::string& dir,
                       const runtime::FrameCapture& capture,
                       const std::string& live_stamp = "");

}  // namespace kiln::tools

#endif  // KILN_TOOLS_FRAME_DEBUG_H_
