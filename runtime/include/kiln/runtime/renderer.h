// The renderer an engine (or `kiln render`) drives: it owns a headless Vulkan device, the
// mapped variant packs, their pipelines and default textures, and renders a Scene with one of the
// lecture's two paths: forward (per object a ForwardBase pass with the main directional light,
// ambient, vertex and SH lights, and one additively blended ForwardAdd pass per further pixel
// light) or deferred (the objects' Deferred passes write a G-buffer, then one light pass per light
// shades it in screen space; objects without a Deferred pass and transparent ones are drawn
// forward afterwards). docs/runtime.md.
#ifndef KILN_RUNTIME_RENDERER_H_
#define KILN_RUNTIME_RENDERER_H_

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/reader.h"
#include "kiln/pack/variant_selector.h"
#include "kiln/result.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/scene.h"

namespace kiln::runtime {

struct RendererOptions {
    bool validation = false;    // VK_LAYER_KHRONOS_validation; messages are collected
    std::string device_filter;  // only devices whose name contains this
    pack::MissingVariantPolicy missing_variant = pack::MissingVariantPolicy::kError;
    std::string pipeline_cache;   // a file to seed and save the VkPipelineCache; empty: none
    bool float32_target = false;  // R32G32B32A32_SFLOAT instead of R16G16B16A16_SFLOAT
    // Every distinct module of a pack goes through spirv-val and checks against the device's
    // limits and the variant's layout before the driver sees it (a pack's checksum is no proof
    // of where it came from). True skips that, for packs one built oneself (kiln render
    // --trust-packs).
    bool trust_packs = false;
};

// How the forward path lights an object with the lights other than its main directional light
// (docs/runtime.md, "Light modes"): kAuto is Unity's ranking (the brightest pixel_lights per
// pixel, up to four point lights per vertex, the rest in spherical harmonics); the others put
// every such light in one mode (kVertex: four point lights per vertex, the rest in SH).
enum class LightMode { kAuto, kPixel, kVertex, kSH };

// A render path by name (docs/runtime.md, "Render paths"). Two are built in: forward (the lecture's
// base and additive passes) and deferred (a G-buffer lit per light in screen space); a program
// that links the runtime's internals may register more (render/render_path.h). A name no path is
// registered under is an error when a frame is rendered or planned.
struct RenderPath {
    std::string name;
    static const RenderPath kForward, kDeferred;
    friend bool operator==(const RenderPath&, const RenderPath&) = default;
};
inline const RenderPath RenderPath::kForward{"forward"};
inline const RenderPath RenderPath::kDeferred{"deferred"};

// The registered paths in registration order (the built-in ones first), each with a summary for
// a command's help.
struct RenderPathInfo {
    std::string name, summary;
};
std::vector<RenderPathInfo> RenderPaths();

// The deferred path's G-buffer normals (RT2): the target's format, and the encoding (xyz * 0.5 +
// 0.5, or octahedral in two channels with the _GBUFFER_NORMALS_OCT keyword). Unity's is RGB10A2
// with xyz.
struct GBufferSettings {
    enum class Normals { kRGB10A2, kRGBA8, kRGBA16F };
    Normals normals = Normals::kRGB10A2;
    bool octahedral = false;
};

// Real-time shadows of the pixel lights from the objects' ShadowCaster passes (forward path):
// hard (each comparison filtered over 2x2 texels) or soft (SHADOWS_SOFT: a wider filter).
enum class Shadows { kOff, kHard, kSoft };

struct FrameSettings {
    uint32_t width = 960, height = 540;
    // A scene camera index; kCameraDefault: the first, or one framing the scene when it has
    // none; kCameraAuto: one framing the scene. Other negative values are an error.
    static constexpr int kCameraDefault = -1, kCameraAuto = -2;
    int camera = kCameraDefault;
    uint32_t pixel_lights = 4;  // at most this many additive (ForwardAdd) passes per object
    LightMode light_mode = LightMode::kAuto;
    RenderPath path = RenderPath::kForward;
    GBufferSettings gbuffer;
    float time = 0;              // seconds, for _Time
    glm::vec3 background{0.0f};  // linear clear colour
    bool default_light = true;   // light a scene without lights by one directional light
    // Samples per pixel (MSAA: 1, 2, 4 or 8) on the forward path, resolved before the display
    // transform; the deferred path draws 1 with a warning, as Unity's deferred path does.
    uint32_t msaa = 1;
    // Off by default, as a scene file says nothing about shadows.
    Shadows shadows = Shadows::kOff;
    uint32_t shadow_resolution = 2048;  // texels a side of each map (a cube's faces: half)
};

struct FrameStats {
    uint32_t objects = 0;        // primitives drawn
    uint32_t base_passes = 0;    // ForwardBase (or untagged) draws
    uint32_t add_passes = 0;     // ForwardAdd draws
    uint32_t vertex_lit = 0;     // base draws with VERTEXLIGHT_ON
    uint32_t sh_lit = 0;         // base draws with lights in their spherical harmonics
    uint32_t gbuffer_draws = 0;  // deferred path: Deferred passes into the G-buffer
    uint32_t light_passes = 0;   // deferred path: light passes over the G-buffer
    uint32_t shadow_draws = 0;   // ShadowCaster draws into maps and the camera depth, collectors
    uint32_t grab_copies = 0;    // GrabPass copies of the colour target into a texture
    // The path's own counts in words, as its summary line shows them ("3 G-buffer draws, 2 light
    // passes"); empty when it has none.
    std::string path_counts;
    uint32_t pipelines_created = 0;
    // Device uploads this frame: vertex and index buffers, and material instances resolved. A
    // scene with an id (Scene::id) uploads them on its first frame only.
    uint32_t buffers_uploaded = 0;
    uint32_t materials_resolved = 0;
    std::string camera;  // which camera was used
    // GPU time from timestamp queries, in milliseconds: the whole frame and each pass (in frame
    // order: "forward", or "gbuffer", "lighting", "forward"). Negative and empty where the
    // queue has no timestamps, and for a captured frame (whose draws are timed one at a time,
    // kiln/runtime/frame_capture.h).
    double gpu_ms = -1;
    struct PassTime {
        std::string pass;
        double gpu_ms = 0;
    };
    std::vector<PassTime> pass_times;
    // CPU time of the frame in milliseconds, from the call to the submission: planning, building
    // the draws and recording them; not the wait for the GPU nor the read-back (readback_ms).
    double cpu_ms = 0;
    double readback_ms = 0;  // the wait for the GPU and the output's copy to host floats
    // Vulkan objects the frame created: targets, views, framebuffers, buffers, descriptor and
    // query pools, command buffers and fences (pipelines and scene uploads are counted above).
    // The renderer keeps them for the next frames of the same size and path (docs/runtime.md,
    // "Frame resources"): 0 in steady state.
    uint32_t allocations = 0;
    // What the frame did not render as asked (K0012-K0015, K0024), each once; the file is the
    // scene, or the pack or cache a warning is about.
    DiagnosticList warnings;
};

struct FrameCapture;

class Renderer {
  public:
    Renderer();
    ~Renderer();  // waits for the device, saves the pipeline cache, destroys everything
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    static Result<Renderer> Create(const RendererOptions& options);

    // Maps and validates a pack; shaders are looked up in the order packs were added. The pack's
    // handle for ReplacePack and RemovePack is its index: pack_count() - 1 after the call.
    Status AddPack(const std::string& path);

    // What ReplacePack did with the replaced pack's pipelines.
    struct PackReload {
        uint32_t pipelines_kept = 0;     // of variants whose code and interface did not change
        uint32_t pipelines_dropped = 0;  // the others: rebuilt when next drawn
    };
    // Live edit: the pack at `index` is replaced by the one at `path` (mapped, and its variant
    // data checked, before anything changes: on any error the old pack stays). Pipelines of
    // variants whose SPIR-V and reflection are unchanged (by content, whatever their index) are
    // kept; the others are destroyed and made again when drawn. The scene's uploaded resources
    // and the frame resources are made again on the next frame, and the pack's usage record
    // starts afresh. Call it between frames: frames wait for the device before they return, so
    // no frame is in flight (the renderer is not thread-safe).
    Result<PackReload> ReplacePack(size_t index, const std::string& path);
    // The pack at `index` unloaded: its shaders are found in no pack any more (a material naming
    // one is then a clear error), its pipelines destroyed. Other packs keep their index.
    Status RemovePack(size_t index);

    // Renders one frame into a linear (scene-referred) image. Colour properties are decoded
    // from sRGB through `color`. With `capture` the frame is drawn one step at a time and every
    // step recorded (kiln/runtime/frame_capture.h); the image is the same.
    Status Render(const Scene& scene,
                  const FrameSettings& settings,
                  const ColorPipeline& color,
                  LinearImage& out,
                  FrameStats& stats,
                  FrameCapture* capture = nullptr);

    std::string DeviceName() const;
    // shaderFloat16 is enabled: packs compiled with --precision half can be drawn.
    bool HasFloat16() const;
    std::vector<std::string> ValidationMessages() const;
    Status WriteUsage(const std::string& path) const;

    size_t pack_count() const;  // packs added, removed ones included (they hold nothing)
    const pack::Pack& pack(size_t index) const;

    struct State;  // opaque: defined inside the library

    // For the runtime's own internals (render/tool_access.h, the one internal header Kiln's own
    // tools include, implements their access with it). An engine has no use for it: State is
    // opaque.
    State& internal_state();
    const State& internal_state() const;

  private:
    std::unique_ptr<State> state_;
};

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDERER_H_
