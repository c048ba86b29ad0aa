#include "kiln/pack/render_state.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "kiln/base/text.h"
#include "kiln/pack/reader.h"

namespace kiln::pack {
namespace {

constexpr std::string_view kCullNames[] = {"Off", "Front", "Back"};
constexpr std::string_view kCompareNames[] = {"Disabled", "Never",    "Less",   "Equal", "LEqual",
                                              "Greater",  "NotEqual", "GEqual", "Always"};
constexpr std::string_view kBlendFactorNames[] = {"Zero",
                                                  "One",
                                                  "DstColor",
                                                  "SrcColor",
                                                  "OneMinusDstColor",
                                                  "SrcAlpha",
                                                  "OneMinusSrcColor",
                                                  "DstAlpha",
                                                  "OneMinusDstAlpha",
                                                  "SrcAlphaSaturate",
                                                  "OneMinusSrcAlpha"};
constexpr std::string_view kBlendOpNames[] = {"Add",
                                              "Sub",
                                              "RevSub",
                                              "Min",
                                              "Max",
                                              "LogicalClear",
                                              "LogicalSet",
                                              "LogicalCopy",
                                              "LogicalCopyInverted",
                                              "LogicalNoop",
                                              "LogicalInvert",
                                              "LogicalAnd",
                                              "LogicalNand",
                                              "LogicalOr",
                                              "LogicalNor",
                                              "LogicalXor",
                                              "LogicalEquiv",
                                              "LogicalAndReverse",
                                              "LogicalAndInverted",
                                              "LogicalOrReverse",
                                              "LogicalOrInverted",
                                              "Multiply",
                                              "Screen",
                                              "Overlay",
                                              "Darken",
                                              "Lighten",
                                              "ColorDodge",
                                              "ColorBurn",
                                              "HardLight",
                                              "SoftLight",
                                              "Difference",
                                              "Exclusion",
                                              "HSLHue",
                                              "HSLSaturation",
                                              "HSLColor",
                                              "HSLLuminosity"};
constexpr std::string_view kStencilOpNames[] = {"Keep",    "Zero",   "Replace",  "IncrSat",
                                                "DecrSat", "Invert", "IncrWrap", "DecrWrap"};
constexpr std::string_view kOnOffNames[] = {"Off", "On"};
constexpr std::string_view kOverridable[] = {"Blend", "ColorMask", "Cull", "ZTest", "ZWrite"};

static_assert(std::size(kCompareNames) == uint32_t(CompareFunction::kAlways) + 1);
static_assert(std::size(kBlendFactorNames) == uint32_t(BlendFactor::kOneMinusSrcAlpha) + 1);
static_assert(std::size(kBlendOpNames) == uint32_t(BlendOp::kHSLLuminosity) + 1);
static_assert(std::size(kStencilOpNames) == uint32_t(StencilOp::kDecrementWrap) + 1);

// Spellings Unity also accepts, with the value they mean.
struct Alias {
    StateValues set;
    std::string_view word;
    uint32_t value;
};
constexpr Alias kAliases[] = {
    {StateValues::kCompare, "Off", uint32_t(CompareFunction::kAlways)},  // ZTest Off
    {StateValues::kOnOff, "True", 1},                                    // ZClip True
    {StateValues::kOnOff, "False", 0},
};

using base::EqualsIgnoreCase;

}  // namespace

std::span<const std::string_view> StateValueNames(StateValues set) {
    switch (set) {
        case StateValues::kCull:
            return kCullNames;
        case StateValues::kCompare:
            return kCompareNames;
        case StateValues::kBlendFactor:
            return kBlendFactorNames;
        case StateValues::kBlendOp:
            return kBlendOpNames;
        case StateValues::kStencilOp:
            return kStencilOpNames;
        case StateValues::kOnOff:
            return kOnOffNames;
    }
    return {};
}

std::optional<uint32_t> ParseStateValue(StateValues set, std::string_view word) {
    const std::span<const std::string_view> names = StateValueNames(set);
    for (size_t i = 0; i < names.size(); ++i) {
        if (EqualsIgnoreCase(word, names[i])) {
            return uint32_t(i);
        }
    }
    for (const Alias& a : kAliases) {
        if (a.set == set && EqualsIgnoreCase(word, a.word)) {
            return a.value;
        }
    }
    return std::nullopt;
}

std::optional<uint32_t> ParseColorMask(std::string_view word) {
    if (word == "0") {
        return 0u;
    }
    uint32_t mask = 0;
    for (const char c : word) {
        uint32_t bit = 0;
        switch (std::toupper(static_cast<unsigned char>(c))) {
            case 'R':
                bit = kColorWriteR;
                break;
            case 'G':
                bit = kColorWriteG;
                break;
            case 'B':
                bit = kColorWriteB;
                break;
            case 'A':
                bit = kColorWriteA;
                break;
            default:
                return std::nullopt;
        }
        if (mask & bit) {
            return std::nullopt;  // a channel twice
        }
        mask |= bit;
    }
    return word.empty() ? std::nullopt : std::optional<uint32_t>(mask);
}

std::string ColorMaskName(uint32_t mask) {
    std::string out;
    out += mask & kColorWriteR ? "R" : "";
    out += mask & kColorWriteG ? "G" : "";
    out += mask & kColorWriteB ? "B" : "";
    out += mask & kColorWriteA ? "A" : "";
    return out.empty() ? "0" : out;
}

std::optional<StateValues> ValueSetOf(StateField field) {
    switch (field) {
        case StateField::kCull:
            return StateValues::kCull;
        case StateField::kZTest:
        case StateField::kStencilCompFront:
        case StateField::kStencilCompBack:
            return StateValues::kCompare;
        case StateField::kZWrite:
        case StateField::kZClip:
        case StateField::kAlphaToMask:
        case StateField::kConservative:
            return StateValues::kOnOff;
        case StateField::kBlendSrc:
        case StateField::kBlendDst:
        case StateField::kBlendSrcAlpha:
        case StateField::kBlendDstAlpha:
            return StateValues::kBlendFactor;
        case StateField::kBlendOp:
        case StateField::kBlendOpAlpha:
            return StateValues::kBlendOp;
        case StateField::kStencilPassFront:
        case StateField::kStencilFailFront:
        case StateField::kStencilZFailFront:
        case StateField::kStencilPassBack:
        case StateField::kStencilFailBack:
        case StateField::kStencilZFailBack:
            return StateValues::kStencilOp;
        default:
            return std::nullopt;
    }
}

const char* StateFieldName(StateField field) {
    constexpr const char* kNames[kStateFieldCount] = {"Cull",
                                                      "ZTest",
                                                      "ZWrite",
                                                      "ZClip",
                                                      "AlphaToMask",
                                                      "Conservative",
                                                      "OffsetFactor",
                                                      "OffsetUnits",
                                                      "BlendOff",
                                                      "BlendSrc",
                                                      "BlendDst",
                                                      "BlendSrcAlpha",
                                                      "BlendDstAlpha",
                                                      "BlendOp",
                                                      "BlendOpAlpha",
                                                      "ColorMask",
                                                      "StencilRef",
                                                      "StencilReadMask",
                                                      "StencilWriteMask",
                                                      "StencilCompFront",
                                                      "StencilPassFront",
                                                      "StencilFailFront",
                                                      "StencilZFailFront",
                                                      "StencilCompBack",
                                                      "StencilPassBack",
                                                      "StencilFailBack",
                                                      "StencilZFailBack"};
    return uint32_t(field) < kStateFieldCount ? kNames[uint32_t(field)] : "unknown";
}

std::span<const std::string_view> OverridableStateFields() {
    return kOverridable;
}

}  // namespace kiln::pack
