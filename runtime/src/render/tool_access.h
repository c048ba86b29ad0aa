// What Kiln's own tools may use of the runtime's internals, in one header (kiln_tools: the
// `kiln test` harness and `kiln stability`, which draw one pass of one material on every object
// of their own scenes): material instances they can change, the camera, and a forward frame of
// their own requests. Nothing else of runtime/src is theirs to include (tests/source/
// layering_test.py checks), and an engine has no use for any of it: never installed.
#ifndef KILN_RUNTIME_RENDER_TOOL_ACCESS_H_
#define KILN_RUNTIME_RENDER_TOOL_ACCESS_H_

#include <string>
#include <vector>

#include "kiln/runtime/color.h"
#include "kiln/runtime/image.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "render/forward_plan.h"      // ForwardPlan, DrawRequest
#include "render/frame_values.h"      // CameraSetup, ChooseCamera
#include "render/material_binding.h"  // MaterialInstance, InstanceFromDefaults / MaterialFile

namespace kiln::runtime::tool_access {

// The renderer's packs in the order shaders are looked up in, and the file each was mapped from.
std::vector<const pack::Pack*> Packs(const Renderer& renderer);
const std::string& PackPath(const Renderer& renderer, size_t index);

// Draws `plan`'s requests as the forward path draws its frame (its materials' resources uploaded
// with the scene's), into `out`.
Status DrawForwardPlan(Renderer& renderer,
                       const ColorPipeline& color,
                       const Scene& scene,
                       const FrameSettings& settings,
                       const CameraSetup& camera,
                       const ForwardPlan& plan,
                       LinearImage& out);

}  // namespace kiln::runtime::tool_access

#endif  // KILN_RUNTIME_RENDER_TOOL_ACCESS_H_
