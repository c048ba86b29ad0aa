// Graphics pipelines from a pack: render state from the pass (with property references resolved
// from the material and the material's own overrides), vertex input and descriptor-set layouts
// from the variant's reflection.
#ifndef KILN_RUNTIME_VK_PIPELINE_H_
#define KILN_RUNTIME_VK_PIPELINE_H_

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kiln/pack/reader.h"
#include "kiln/pack/render_state.h"
#include "vk/context.h"
#include "vk/spirv_check.h"

namespace kiln::vk {

inline constexpr uint32_t kMaxTargets = 8;

struct BlendTarget {
    bool enable = false;
    VkBlendFactor src = VK_BLEND_FACTOR_ONE, dst = VK_BLEND_FACTOR_ZERO;
    VkBlendFactor src_alpha = VK_BLEND_FACTOR_ONE, dst_alpha = VK_BLEND_FACTOR_ZERO;
    VkBlendOp op = VK_BLEND_OP_ADD, op_alpha = VK_BLEND_OP_ADD;
    VkColorComponentFlags mask = 0xF;
    bool advanced = false;  // op is an advanced blend equation (VK_EXT_blend_operation_advanced)

    bool operator==(const BlendTarget&) const = default;
};

struct StencilFace {
    VkCompareOp compare = VK_COMPARE_OP_ALWAYS;
    VkStencilOp pass = VK_STENCIL_OP_KEEP, fail = VK_STENCIL_OP_KEEP, zfail = VK_STENCIL_OP_KEEP;

    bool operator==(const StencilFace&) const = default;
};

// The fixed-function state of one draw, Unity's defaults until a pass or material says otherwise.
struct RenderState {
    VkCullModeFlags cull = VK_CULL_MODE_BACK_BIT;
    // Clockwise front faces: an object whose transform mirrors it (negative determinant), so
    // that culling and SV_IsFrontFace see its faces as the file meant.
    bool front_clockwise = false;
    bool depth_test = true;
    VkCompareOp ztest = VK_COMPARE_OP_LESS_OR_EQUAL;
    bool zwrite = true;
    bool zclip = true;
    float offset_factor = 0, offset_units = 0;
    std::array<BlendTarget, kMaxTargets> targets{};
    bool logic_op_enable = false;  // a Logical* BlendOp on target 0
    VkLogicOp logic_op = VK_LOGIC_OP_COPY;
    bool stencil = false;
    uint32_t stencil_ref = 0, stencil_read = 0xFF, stencil_write = 0xFF;
    StencilFace front, back;

    bool operator==(const RenderState&) const = default;
};

// Unity's enums (kiln/pack/render_state.h) as Vulkan's.
RenderState ToVulkan(const pack::PassState& state);

// pack::ResolvePassState, then ToVulkan.
Status ResolveRenderState(const pack::Pack& pack,
                          uint32_t pass,
                          const pack::PropertyLookup& properties,
                          std::span<const pack::StateOverride> overrides,
                          RenderState& out);

// The layouts a variant's reflection implies (sets 0..n, push constants).
struct VariantLayout {
    std::vector<VkDescriptorSetLayout> sets;
    std::vector<std::vector<VkDescriptorSetLayoutBinding>> bindings;  // per set
    VkPipelineLayout layout = VK_NULL_HANDLE;
    uint32_t push_constant_size = 0;
    VkShaderStageFlags push_constant_stages = 0;
};

struct Pipeline {
    VkPipeline pipeline = VK_NULL_HANDLE;
    VariantLayout layout;
    std::array<VkShaderModule, pack::kStageCount> modules{};
};

struct PipelineTargets {
    VkRenderPass render_pass = VK_NULL_HANDLE;
    uint32_t color_count = 1;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // the render pass's (MSAA)
};

// `checker` looks at the variant's SPIR-V and reflection before the driver does
// (vk/spirv_check.h); null for trusted packs.
Status CreatePipeline(const Context& c,
                      const pack::Pack& pack,
                      uint32_t variant,
                      const RenderState& state,
                      const PipelineTargets& targets,
                      VkPipelineCache cache,
                      ModuleChecker* checker,
                      Pipeline& out);
void DestroyPipeline(const Context& c, Pipeline& pipeline);

}  // namespace kiln::vk

#endif  // KILN_RUNTIME_VK_PIPELINE_H_
