// The frame debugger's texel readout (docs/frame-debugger.md): for each target image of a step,
// a script beside its PNG (steps/NNNN-target.js) that hands the page the texels' values, loaded
// when the cursor first moves over the image. A page opened from a file cannot read its own PNGs'
// pixels back (file: images taint a canvas), so the values travel as script: the target's values
// as the runtime decoded them (DebugImage::half, or ::single for one channel) followed by the
// displayed RGBA8 bytes, zlib-compressed and in base64, which the page inflates with the
// browser's DecompressionStream.
#ifndef KILN_TOOLS_FRAME_DEBUG_TEXEL_VALUES_H_
#define KILN_TOOLS_FRAME_DEBUG_TEXEL_VALUES_H_

#include <string>

#include "kiln/result.h"
#include "kiln/runtime/frame_capture.h"

namespace kiln::tools {

// The script for `image`, which calls kilnValues(key, {w, h, c, t, z}): c channels per texel,
// t "f16" or "f32", z the data. "" when the image has no values.
Result<std::string> TexelValuesScript(const std::string& key, const runtime::DebugImage& image);

// What the page runs to show a texel's values (the readout under the zoom control): defines
// kilnValues and readout(img, x, y), a promise of the line to show.
extern const char* const kTexelReadoutScript;

}  // namespace kiln::tools

#endif  // KILN_TOOLS_FRAME_DEBUG_TEXEL_VALUES_H_
