// ResolveRenderState: the pass's state as Unity's enums (kiln/pack/render_state.h, the table every
// side shares) mapped to Vulkan. Each table is indexed by Unity's numeric value.
#include "vk/pipeline.h"

namespace kiln::vk {
namespace {

using pack::kFirstAdvancedBlendOp;
using pack::kFirstLogicalBlendOp;

constexpr VkBlendFactor kBlendFactors[] = {
    VK_BLEND_FACTOR_ZERO,
    VK_BLEND_FACTOR_ONE,
    VK_BLEND_FACTOR_DST_COLOR,
    VK_BLEND_FACTOR_SRC_COLOR,
    VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR,
    VK_BLEND_FACTOR_SRC_ALPHA,
    VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR,
    VK_BLEND_FACTOR_DST_ALPHA,
    VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA,
    VK_BLEND_FACTOR_SRC_ALPHA_SATURATE,
    VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
};
constexpr VkCompareOp kCompare[] = {
    VK_COMPARE_OP_ALWAYS,  // Disabled: the test is off
    VK_COMPARE_OP_NEVER,
    VK_COMPARE_OP_LESS,
    VK_COMPARE_OP_EQUAL,
    VK_COMPARE_OP_LESS_OR_EQUAL,
    VK_COMPARE_OP_GREATER,
    VK_COMPARE_OP_NOT_EQUAL,
    VK_COMPARE_OP_GREATER_OR_EQUAL,
    VK_COMPARE_OP_ALWAYS,
};
constexpr VkCullModeFlags kCull[] = {VK_CULL_MODE_NONE, VK_CULL_MODE_FRONT_BIT,
                                     VK_CULL_MODE_BACK_BIT};
constexpr VkBlendOp kBlendOps[] = {
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_SUBTRACT,
    VK_BLEND_OP_REVERSE_SUBTRACT,
    VK_BLEND_OP_MIN,
    VK_BLEND_OP_MAX,
    // Logical operations are not blend equations in Vulkan: see kLogicOps.
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    VK_BLEND_OP_ADD,
    // Advanced blend equations (VK_EXT_blend_operation_advanced).
    VK_BLEND_OP_MULTIPLY_EXT,
    VK_BLEND_OP_SCREEN_EXT,
    VK_BLEND_OP_OVERLAY_EXT,
    VK_BLEND_OP_DARKEN_EXT,
    VK_BLEND_OP_LIGHTEN_EXT,
    VK_BLEND_OP_COLORDODGE_EXT,
    VK_BLEND_OP_COLORBURN_EXT,
    VK_BLEND_OP_HARDLIGHT_EXT,
    VK_BLEND_OP_SOFTLIGHT_EXT,
    VK_BLEND_OP_DIFFERENCE_EXT,
    VK_BLEND_OP_EXCLUSION_EXT,
    VK_BLEND_OP_HSL_HUE_EXT,
    VK_BLEND_OP_HSL_SATURATION_EXT,
    VK_BLEND_OP_HSL_COLOR_EXT,
    VK_BLEND_OP_HSL_LUMINOSITY_EXT,
};
// Unity's LogicalClear .. LogicalOrInverted, in order.
constexpr VkLogicOp kLogicOps[] = {
    VK_LOGIC_OP_CLEAR,         VK_LOGIC_OP_SET,          VK_LOGIC_OP_COPY,
    VK_LOGIC_OP_COPY_INVERTED, VK_LOGIC_OP_NO_OP,        VK_LOGIC_OP_INVERT,
    VK_LOGIC_OP_AND,           VK_LOGIC_OP_NAND,         VK_LOGIC_OP_OR,
    VK_LOGIC_OP_NOR,           VK_LOGIC_OP_XOR,          VK_LOGIC_OP_EQUIVALENT,
    VK_LOGIC_OP_AND_REVERSE,   VK_LOGIC_OP_AND_INVERTED, VK_LOGIC_OP_OR_REVERSE,
    VK_LOGIC_OP_OR_INVERTED,
};
constexpr VkStencilOp kStencilOps[] = {
    VK_STENCIL_OP_KEEP,
    VK_STENCIL_OP_ZERO,
    VK_STENCIL_OP_REPLACE,
    VK_STENCIL_OP_INCREMENT_AND_CLAMP,
    VK_STENCIL_OP_DECREMENT_AND_CLAMP,
    VK_STENCIL_OP_INVERT,
    VK_STENCIL_OP_INCREMENT_AND_WRAP,
    VK_STENCIL_OP_DECREMENT_AND_WRAP,
};
static_assert(std::size(kBlendOps) == uint32_t(pack::BlendOp::kHSLLuminosity) + 1);
static_assert(std::size(kLogicOps) == kFirstAdvancedBlendOp - kFirstLogicalBlendOp);

template <class T, size_t N, class E>
T Map(const T (&table)[N], E value) {
    return table[uint32_t(value) < N ? uint32_t(value) : 0];
}

VkColorComponentFlags Mask(uint32_t m) {
    return (m & pack::kColorWriteR ? VK_COLOR_COMPONENT_R_BIT : 0) |
           (m & pack::kColorWriteG ? VK_COLOR_COMPONENT_G_BIT : 0) |
           (m & pack::kColorWriteB ? VK_COLOR_COMPONENT_B_BIT : 0) |
           (m & pack::kColorWriteA ? VK_COLOR_COMPONENT_A_BIT : 0);
}

}  // namespace

RenderState ToVulkan(const pack::PassState& p) {
    RenderState s;
    s.cull = Map(kCull, p.cull);
    s.depth_test = p.ztest != pack::CompareFunction::kDisabled;
    s.ztest = Map(kCompare, p.ztest);
    s.zwrite = p.zwrite;
    s.zclip = p.zclip;
    s.offset_factor = p.offset_factor;
    s.offset_units = p.offset_units;
    for (size_t i = 0; i < kMaxTargets; ++i) {
        const pack::BlendTargetState& t = p.targets[i];
        BlendTarget& out = s.targets[i];
        out.enable = t.enable;
        out.src = Map(kBlendFactors, t.src);
        out.dst = Map(kBlendFactors, t.dst);
        out.src_alpha = Map(kBlendFactors, t.src_alpha);
        out.dst_alpha = Map(kBlendFactors, t.dst_alpha);
        out.op = Map(kBlendOps, t.op);
        out.op_alpha = Map(kBlendOps, t.op_alpha);
        out.mask = Mask(t.color_mask);
        const uint32_t op = uint32_t(t.op);
        if (i == 0 && op >= kFirstLogicalBlendOp && op < kFirstAdvancedBlendOp) {
            s.logic_op_enable = true;  // Vulkan applies one logic op to every attachment
            s.logic_op = kLogicOps[op - kFirstLogicalBlendOp];
        }
        out.advanced = op >= kFirstAdvancedBlendOp;
    }
    s.stencil = p.stencil;
    s.stencil_ref = p.stencil_ref;
    s.stencil_read = p.stencil_read;
    s.stencil_write = p.stencil_write;
    const auto face = [](const pack::StencilFaceState& f) {
        return StencilFace{Map(kCompare, f.compare), Map(kStencilOps, f.pass),
                           Map(kStencilOps, f.fail), Map(kStencilOps, f.zfail)};
    };
    s.front = face(p.front);
    s.back = face(p.back);
    return s;
}

Status ResolveRenderState(const pack::Pack& pack,
                          uint32_t pass,
                          const pack::PropertyLookup& properties,
                          std::span<const pack::StateOverride> overrides,
                          RenderState& out) {
    Result<pack::PassState> state = pack::ResolvePassState(pack, pass, properties, overrides);
    if (!state) {
        return Error{DiagCode::kRenderFailed, state.error().message};
    }
    out = ToVulkan(state.value());
    return {};
}

}  // namespace kiln::vk
