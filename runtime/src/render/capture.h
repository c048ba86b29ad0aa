// The frame debugger's observer (render/frame.h, RecordFrame): turns each step's read-back targets
// into viewable images and records the step (kiln/runtime/frame_capture.h).
#ifndef KILN_RUNTIME_RENDER_CAPTURE_H_
#define KILN_RUNTIME_RENDER_CAPTURE_H_

#include <glm/mat4x4.hpp>

#include "kiln/runtime/frame_capture.h"
#include "render/frame.h"

namespace kiln::runtime {

// `projection` linearises depth targets; `color` shows light targets as the final image is shown.
StepObserver CaptureObserver(const glm::mat4& projection,
                             const ColorPipeline& color,
                             FrameCapture& out);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_CAPTURE_H_
