// DrawBuilder: a planned request (render/forward_plan.h) becomes a Draw of a frame pass
// (render/frame.h): the variant the selector picks, its pipeline for the pass's targets, its
// texture descriptors and its uniform bytes, decided on the CPU. Both paths build their draws
// with it: the forward path's base and additive passes, and the deferred path's G-buffer, light
// and forward passes. A request without an instance draws the full-screen triangle (the deferred
// light pass).
#ifndef KILN_RUNTIME_RENDER_DRAW_BUILDER_H_
#define KILN_RUNTIME_RENDER_DRAW_BUILDER_H_

#include <map>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "render/forward_plan.h"
#include "render/frame.h"
#include "render/frame_values.h"
#include "render/renderer_state.h"

namespace kiln::runtime {

class DrawBuilder {
  public:
    // `record_info`: fill each Draw::Info (the frame debugger's record of the draw).
    DrawBuilder(Renderer::State& s,
                SceneResources& resources,
                const Scene& scene,
                Values frame,
                FrameStats& stats,
                bool record_info = false);

    // The pass the next draws go into: its targets (what pipelines are created against) and
    // the frame targets it samples by texture name (the light pass's G-buffer).
    void BeginPass(const Frame& frame,
                   const FramePass& pass,
                   std::map<std::string, uint32_t, std::less<>> target_textures = {});

    // One draw of a request's pass for its primitive, appended to `draws`.
    Status Build(const DrawRequest& request, std::vector<Draw>& draws);
    // The forward path's requests in order, counted as base and additive passes in the stats.
    Status BuildForward(std::span<const DrawRequest> requests, std::vector<Draw>& draws);

    // Every draw's uniform blocks, at the offsets their writes name.
    std::vector<uint8_t> TakeUniforms() { return std::move(uniforms_); }

  private:
    // What draws of one material's pass with one variant share in a pass: the pipeline, the
    // texture descriptors and the <tex>_TexelSize values they imply.
    struct Binding {
        const vk::Pipeline* pipeline = nullptr;
        std::vector<Draw::Write> textures;
        Values texel_sizes;
        // Per uniform block of the variant, in ModulesOf order: the block as the frame's, the
        // textures' sizes and the material's values fill it (the same for every draw of the
        // binding), and its members by name, which the draw's own values overwrite.
        struct BlockPlan {
            std::vector<uint8_t> base;
            std::vector<std::pair<std::string, pack::MemberRec>> members;  // sorted by name
        };
        std::vector<BlockPlan> plans;
        bool vertex_light = false;  // the variant has VERTEXLIGHT_ON
        std::string keywords;       // the variant's, joined
        std::string state;          // the render state as ShaderLab spells it (when recording info)
        std::vector<Draw::Info::Texture> texture_info;  // when recording info
    };

    void Warn(DiagCode code, std::string message);
    Status Pipeline(const MaterialInstance& m,
                    uint32_t pass,
                    uint32_t variant,
                    bool additive,
                    bool mirrored,
                    bool depth_only,
                    const std::vector<std::string>& chosen,
                    Binding& out);
    // `shadow_map`: the frame target bound as _ShadowMapTexture (-1: none).
    Status Textures(const MaterialInstance& m,
                    const pack::VariantRec& v,
                    int shadow_map,
                    Binding& out);
    Status TargetTexture(uint32_t target, pack::ResourceKind kind, Draw::Write& out);
    void Uniforms(const pack::Pack& pack,
                  const pack::VariantRec& v,
                  const ValueLookup& lookup,
                  Draw& d);
    // Uniforms from the binding's plans: each block's bytes copied, then the members of the
    // draw's own tables written over them (`per_draw`, lowest precedence first); `fixed` looks
    // up the rest when a plan is made.
    void PlannedUniforms(const pack::Pack& pack,
                         const pack::VariantRec& v,
                         Binding& binding,
                         const ValueLookup& fixed,
                         std::span<const Values* const> per_draw,
                         Draw& d);

    Renderer::State& s_;
    SceneResources& resources_;
    const Scene& scene_;
    Values frame_values_;
    FrameStats& stats_;
    bool record_info_ = false;
    const Frame* frame_ = nullptr;
    vk::TargetFormats targets_;
    std::map<std::string, uint32_t, std::less<>> target_textures_;
    std::vector<uint8_t> uniforms_;
    VkDeviceSize alignment_ = 256;
    // (material, pass, variant, additive, mirrored, shadow map)
    std::map<std::tuple<const MaterialInstance*, uint32_t, uint32_t, bool, bool, int>, Binding>
        bindings_;
    // (pixel light, vertex lights) -> LightValues, and instance -> ObjectValues: once per frame
    std::map<std::pair<const Light*, std::vector<const Light*>>, Values> light_values_;
    std::map<const Instance*, Values> object_values_;
};

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_DRAW_BUILDER_H_
