// Unity's GrabPass in a frame of passes. The forward draws of a frame pass are split where an
// object's GrabPass stands (render/forward_plan.h: a request with `grab`): the pass being drawn
// ends, the colour drawn so far is copied into the grab texture (a copy pass, FramePass::
// copy_from, which the frame debugger shows as a step), and the draws after it go into a new pass
// that loads the targets and samples the texture by name. `GrabPass { }` copies into _GrabTexture
// before every object that has one; `GrabPass { "_Name" }` copies once per frame, for the first
// object, into _Name; later objects sample that copy, as in Unity.
#ifndef KILN_RUNTIME_RENDER_GRAB_PASS_H_
#define KILN_RUNTIME_RENDER_GRAB_PASS_H_

#include <span>

#include "render/draw_builder.h"
#include "render/forward_plan.h"
#include "render/frame.h"

namespace kiln::runtime {

// Appends `first` (its targets, clear and sampled targets; no draws) to the frame with the draws of
// `requests`, then, after each GrabPass, a copy pass from `source` (the pass's single-sample
// colour: the attachment, or its resolve target with MSAA) and a pass like `first` that loads its
// targets. Grab targets are added to the frame (bilinear, the colour's format).
Status BuildForwardPasses(DrawBuilder& builder,
                          Frame& frame,
                          const FramePass& first,
                          uint32_t source,
                          std::span<const DrawRequest> requests,
                          FrameStats& stats);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_GRAB_PASS_H_
