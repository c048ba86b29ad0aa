// A render path as one object (docs/architecture.md, "Render paths"): it plans a frame of a scene
// on the CPU (PathPlan: every variant lookup it will make, in drawing order, with who asked),
// then builds that plan into a Frame (render/frame.h). Everything that needs to know what a path
// draws walks the same plan: RenderFrame draws it, PlanScene (kiln/runtime/plan.h: the dry run,
// kiln compile --scene stripping and --verify-scene) looks its Requests up without a device, and
// the usage file lists its Materials. So a path cannot draw a variant its stripped pack lacks.
//
// Paths are registered by name (RenderPath in kiln/runtime/renderer.h): forward and deferred
// are built in (render/forward.cpp, render/deferred.cpp); a program linking the runtime's
// internals may register more before rendering (tests/runtime/toy_path_test.cpp does).
#ifndef KILN_RUNTIME_RENDER_RENDER_PATH_H_
#define KILN_RUNTIME_RENDER_RENDER_PATH_H_

#include <chrono>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "render/draw_builder.h"
#include "render/forward_plan.h"
#include "render/frame.h"
#include "render/frame_values.h"

namespace kiln::runtime {

// What a path plans a frame from. `materials` caches material instances across frames (the
// requests point into it); warnings (a shader the path cannot draw) go to `warnings` once each.
struct PlanInputs {
    const std::vector<const pack::Pack*>& packs;
    const Scene& scene;
    const FrameSettings& settings;
    const CameraSetup& camera;
    const ColorPipeline& color;
    MaterialCache& materials;
    DiagnosticList& warnings;
};

// What a path builds a frame with: the renderer, the scene's uploaded resources, and the builder
// that turns requests into draws. `bounds`: the scene's world bounds (set when shadows are on).
struct BuildInputs {
    Renderer::State& state;
    SceneResources& resources;
    DrawBuilder& builder;
    const Scene& scene;
    const FrameSettings& settings;
    const CameraSetup& camera;
    FrameStats& stats;
};

// One frame of a path, planned. Requests point into the plan (it is not copied).
class PathPlan {
  public:
    virtual ~PathPlan() = default;

    // Every request the frame draws, in drawing order, GrabPass copies included (they look no
    // variant up). The shadow passes' casters and collector are among them.
    virtual void Requests(std::vector<const DrawRequest*>& out) const = 0;
    // The material instances the requests use: the draw list's and the path's own (a light
    // pass's, the shadow collector's).
    virtual void Materials(std::vector<const MaterialInstance*>& out) const = 0;
    // Primitives drawn.
    virtual uint32_t Objects() const = 0;
    // Builds the frame's targets and passes (frame.width and height are set; the output target
    // is the path's to choose). The caller takes the builder's uniforms and records the frame.
    virtual Status Build(BuildInputs& in, Frame& frame) const = 0;
};

class PathRenderer {
  public:
    virtual ~PathRenderer() = default;

    // The name --path takes, and a sentence for a command's help.
    virtual std::string_view Name() const = 0;
    virtual std::string_view Summary() const = 0;
    // Changes what the path cannot draw as asked (the deferred path's single sample), with a
    // warning each.
    virtual void Adjust(FrameSettings& settings,
                        const Scene& scene,
                        DiagnosticList& warnings) const {
        (void)settings, (void)scene, (void)warnings;
    }
    // Plans a frame: errors are those a render stops at before drawing (a material that does not
    // validate, a pass shader missing from every pack).
    virtual Result<std::unique_ptr<PathPlan>> Plan(const PlanInputs& in) const = 0;
    // The path's own counts of a drawn frame in words (FrameStats::path_counts).
    virtual std::string Counts(const FrameStats& stats) const {
        (void)stats;
        return "";
    }
};

// The path registered under `name`, or null.
const PathRenderer* FindPathRenderer(std::string_view name);
// Registers a path; false (and nothing registered) when its name is taken or empty. Not
// thread-safe with rendering: register before any frame.
bool RegisterPathRenderer(std::unique_ptr<PathRenderer> path);
// The error (K0007) for a name no path is registered under, naming the closest one.
Error UnknownPath(std::string_view name);

// The built-in paths (render/forward.cpp, render/deferred.cpp).
std::unique_ptr<PathRenderer> MakeForwardPath();
std::unique_ptr<PathRenderer> MakeDeferredPath();

// A plan its caller built and keeps, drawn as the path draws its own (kiln test plans its own
// frames: render/tool_access.h).
struct DeferredPlan;
std::unique_ptr<PathPlan> ViewForwardPlan(const ForwardPlan& plan);
std::unique_ptr<PathPlan> ViewDeferredPlan(const DeferredPlan& plan);

// Builds and records `plan`'s frame (what RenderFrame does after planning), with
// settings.msaa samples per pixel resolved before the read-back; `observer`: the frame recorded
// step by step (render/frame.h), each draw's Draw::Info filled. The meshes and textures come
// from `resources`.
Status DrawPlan(Renderer::State& state,
                SceneResources& resources,
                const Scene& scene,
                const FrameSettings& settings,
                const CameraSetup& camera,
                const PathPlan& plan,
                LinearImage& out,
                FrameStats& stats,
                const StepObserver* observer = nullptr,
                std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now());

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_RENDER_PATH_H_
