// Render state, the one table the ShaderLab parser, the .material parser and every engine share:
// each command's values as ShaderLab spells them, at the index of Unity's numeric value
// (UnityEngine.Rendering.CullMode, CompareFunction, BlendMode, BlendOp, StencilOp, ColorWriteMask),
// and ResolvePassState, which turns a pass's state records into these enums with a material's
// [property] values and overrides applied. An engine maps the enums to its API (Kiln's Vulkan
// renderer does in runtime/src/vk/render_state.cpp); no string compares.
#ifndef KILN_PACK_RENDER_STATE_H_
#define KILN_PACK_RENDER_STATE_H_

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/pack/format.h"
#include "kiln/result.h"

namespace kiln::pack {

class Pack;

enum class CullMode : uint32_t { kOff, kFront, kBack };
enum class CompareFunction : uint32_t {
    kDisabled,  // depth or stencil test off
    kNever,
    kLess,
    kEqual,
    kLessEqual,
    kGreater,
    kNotEqual,
    kGreaterEqual,
    kAlways,
};
enum class BlendFactor : uint32_t {
    kZero,
    kOne,
    kDstColor,
    kSrcColor,
    kOneMinusDstColor,
    kSrcAlpha,
    kOneMinusSrcColor,
    kDstAlpha,
    kOneMinusDstAlpha,
    kSrcAlphaSaturate,
    kOneMinusSrcAlpha,
};
// 0-4 ordinary blending, 5-20 logical operations (the whole colour attachment), 21-35 advanced
// blend equations (VK_EXT_blend_operation_advanced on Vulkan).
enum class BlendOp : uint32_t {
    kAdd,
    kSubtract,
    kReverseSubtract,
    kMin,
    kMax,
    kLogicalClear,
    kLogicalSet,
    kLogicalCopy,
    kLogicalCopyInverted,
    kLogicalNoop,
    kLogicalInvert,
    kLogicalAnd,
    kLogicalNand,
    kLogicalOr,
    kLogicalNor,
    kLogicalXor,
    kLogicalEquivalence,
    kLogicalAndReverse,
    kLogicalAndInverted,
    kLogicalOrReverse,
    kLogicalOrInverted,
    kMultiply,
    kScreen,
    kOverlay,
    kDarken,
    kLighten,
    kColorDodge,
    kColorBurn,
    kHardLight,
    kSoftLight,
    kDifference,
    kExclusion,
    kHSLHue,
    kHSLSaturation,
    kHSLColor,
    kHSLLuminosity,
};
inline constexpr uint32_t kFirstLogicalBlendOp = uint32_t(BlendOp::kLogicalClear);
inline constexpr uint32_t kFirstAdvancedBlendOp = uint32_t(BlendOp::kMultiply);
enum class StencilOp : uint32_t {
    kKeep,
    kZero,
    kReplace,
    kIncrementSaturate,
    kDecrementSaturate,
    kInvert,
    kIncrementWrap,
    kDecrementWrap,
};
// ColorWriteMask bits.
enum ColorWriteMask : uint32_t {
    kColorWriteA = 1,
    kColorWriteB = 2,
    kColorWriteG = 4,
    kColorWriteR = 8,
    kColorWriteAll = 15,
};

// The value sets of render-state commands.
enum class StateValues : uint32_t { kCull, kCompare, kBlendFactor, kBlendOp, kStencilOp, kOnOff };

// The values of a set as ShaderLab spells them; index = Unity's numeric value (On = 1, Off = 0).
std::span<const std::string_view> StateValueNames(StateValues set);
// The numeric value of `word` (case-insensitive), Unity's aliases included: ZTest Off (Always),
// True and False for On and Off. nullopt when the set has no such value.
std::optional<uint32_t> ParseStateValue(StateValues set, std::string_view word);
// ColorMask as written: "0" or channels R, G, B, A (any order, each at most once) -> mask bits.
std::optional<uint32_t> ParseColorMask(std::string_view word);
// "RGBA" order spelling of mask bits; "0" for none.
std::string ColorMaskName(uint32_t mask);

// The value set a state field takes; nullopt for numeric fields (Offset, Stencil Ref/masks) and
// ColorMask.
std::optional<StateValues> ValueSetOf(StateField field);
// The name of a field in `kiln info` and messages: "Cull", "BlendSrc", "StencilCompFront", ...;
// "unknown" for a value past kStateFieldCount (a field of a newer format minor version).
const char* StateFieldName(StateField field);

// The render-state fields a .material may override (kiln/material/material.h).
std::span<const std::string_view> OverridableStateFields();

struct BlendTargetState {
    bool enable = false;
    BlendFactor src = BlendFactor::kOne, dst = BlendFactor::kZero;
    BlendFactor src_alpha = BlendFactor::kOne, dst_alpha = BlendFactor::kZero;
    BlendOp op = BlendOp::kAdd, op_alpha = BlendOp::kAdd;
    uint32_t color_mask = kColorWriteAll;

    bool operator==(const BlendTargetState&) const = default;
};

struct StencilFaceState {
    CompareFunction compare = CompareFunction::kAlways;
    StencilOp pass = StencilOp::kKeep, fail = StencilOp::kKeep, zfail = StencilOp::kKeep;

    bool operator==(const StencilFaceState&) const = default;
};

inline constexpr uint32_t kMaxRenderTargets = 8;

// The fixed-function state of one draw: Unity's defaults until the pass or material says otherwise.
struct PassState {
    CullMode cull = CullMode::kBack;
    CompareFunction ztest = CompareFunction::kLessEqual;  // kDisabled: no depth test
    bool zwrite = true;
    bool zclip = true;
    bool alpha_to_mask = false;
    bool conservative = false;
    float offset_factor = 0, offset_units = 0;
    std::array<BlendTargetState, kMaxRenderTargets> targets{};
    bool stencil = false;  // any Stencil command present
    uint32_t stencil_ref = 0, stencil_read = 0xFF, stencil_write = 0xFF;
    StencilFaceState front, back;

    bool operator==(const PassState&) const = default;
};

// A numeric material property for `Blend [_SrcBlend] [_DstBlend]` and the like.
using PropertyLookup = std::function<std::optional<float>(std::string_view name)>;

// One material override: a field of OverridableStateFields() and its values as written ("Off";
// ["SrcAlpha", "OneMinusSrcAlpha"]).
struct StateOverride {
    std::string field;
    std::vector<std::string> values;
};

// The pass's state records resolved: literals, numbers and [property] references (Unity's
// numeric values), then `overrides` in order. An error names the first value that is invalid.
Result<PassState> ResolvePassState(const Pack& pack,
                                   uint32_t pass,
                                   const PropertyLookup& properties,
                                   std::span<const StateOverride> overrides);

}  // namespace kiln::pack

#endif  // KILN_PACK_RENDER_STATE_H_
