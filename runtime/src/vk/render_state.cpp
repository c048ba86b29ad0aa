// ResolveRenderState: a pass's StateRecs (literals, numbers and [property] references) and the
// material's overrides turned into Vulkan enums. Property references take Unity's enum values
// (UnityEngine.Rendering.BlendMode, CompareFunction, CullMode, BlendOp, StencilOp).
#include "vk/pipeline.h"

#include <cmath>
#include <string_view>

namespace kiln::vk {
namespace {

using pack::StateField;
using pack::StateKind;

struct Value {
    bool is_number = false;
    float number = 0;
    std::string text;
};

template <class T>
struct Named {
    std::string_view name;
    T value;
};

// Unity's BlendMode order: index = the numeric value a property holds.
constexpr Named<VkBlendFactor> kBlendFactors[] = {
    {"Zero", VK_BLEND_FACTOR_ZERO},
    {"One", VK_BLEND_FACTOR_ONE},
    {"DstColor", VK_BLEND_FACTOR_DST_COLOR},
    {"SrcColor", VK_BLEND_FACTOR_SRC_COLOR},
    {"OneMinusDstColor", VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR},
    {"SrcAlpha", VK_BLEND_FACTOR_SRC_ALPHA},
    {"OneMinusSrcColor", VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR},
    {"DstAlpha", VK_BLEND_FACTOR_DST_ALPHA},
    {"OneMinusDstAlpha", VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA},
    {"SrcAlphaSaturate", VK_BLEND_FACTOR_SRC_ALPHA_SATURATE},
    {"OneMinusSrcAlpha", VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA},
};
// CompareFunction: 0 Disabled, 1 Never ... 8 Always.
constexpr Named<VkCompareOp> kCompare[] = {
    {"Disabled", VK_COMPARE_OP_ALWAYS},
    {"Never", VK_COMPARE_OP_NEVER},
    {"Less", VK_COMPARE_OP_LESS},
    {"Equal", VK_COMPARE_OP_EQUAL},
    {"LEqual", VK_COMPARE_OP_LESS_OR_EQUAL},
    {"Greater", VK_COMPARE_OP_GREATER},
    {"NotEqual", VK_COMPARE_OP_NOT_EQUAL},
    {"GEqual", VK_COMPARE_OP_GREATER_OR_EQUAL},
    {"Always", VK_COMPARE_OP_ALWAYS},
};
constexpr Named<VkCullModeFlags> kCull[] = {{"Off", VK_CULL_MODE_NONE},
                                            {"Front", VK_CULL_MODE_FRONT_BIT},
                                            {"Back", VK_CULL_MODE_BACK_BIT}};
constexpr Named<VkBlendOp> kBlendOps[] = {{"Add", VK_BLEND_OP_ADD},
                                          {"Sub", VK_BLEND_OP_SUBTRACT},
                                          {"RevSub", VK_BLEND_OP_REVERSE_SUBTRACT},
                                          {"Min", VK_BLEND_OP_MIN},
                                          {"Max", VK_BLEND_OP_MAX}};
constexpr Named<VkStencilOp> kStencilOps[] = {
    {"Keep", VK_STENCIL_OP_KEEP},
    {"Zero", VK_STENCIL_OP_ZERO},
    {"Replace", VK_STENCIL_OP_REPLACE},
    {"IncrSat", VK_STENCIL_OP_INCREMENT_AND_CLAMP},
    {"DecrSat", VK_STENCIL_OP_DECREMENT_AND_CLAMP},
    {"Invert", VK_STENCIL_OP_INVERT},
    {"IncrWrap", VK_STENCIL_OP_INCREMENT_AND_WRAP},
    {"DecrWrap", VK_STENCIL_OP_DECREMENT_AND_WRAP},
};

struct Resolver {
    const PropertyLookup& properties;
    std::optional<runtime::Error> error;

    void Fail(std::string message) {
        if (!error) {
            error = runtime::Error{std::move(message)};
        }
    }

    // A table entry by name, or by index when the value is a number.
    template <class T, size_t N>
    T Pick(const Named<T> (&table)[N], const Value& v, std::string_view what, T fallback) {
        if (v.is_number) {
            const float n = v.number;
            if (std::isfinite(n) && n >= 0 && n < float(N) && n == std::floor(n)) {
                return table[size_t(n)].value;
            }
            Fail(std::string(what) + " value " + std::to_string(n) + " is not a valid " +
                 std::string(what) + " (0.." + std::to_string(N - 1) + ")");
            return fallback;
        }
        for (const auto& entry : table) {
            if (entry.name == v.text) {
                return entry.value;
            }
        }
        Fail("unsupported " + std::string(what) + " '" + v.text + "'");
        return fallback;
    }

    bool OnOff(const Value& v, std::string_view what) {
        if (v.is_number) {
            return v.number != 0;
        }
        if (v.text == "On" || v.text == "True") {
            return true;
        }
        if (v.text != "Off" && v.text != "False") {
            Fail("unsupported " + std::string(what) + " '" + v.text + "'");
        }
        return false;
    }

    float Number(const Value& v, std::string_view what) {
        if (v.is_number) {
            return v.number;
        }
        char* end = nullptr;
        const float f = std::strtof(v.text.c_str(), &end);
        if (end == v.text.c_str() || *end != '\0') {
            Fail("expected a number for " + std::string(what) + ", got '" + v.text + "'");
        }
        return f;
    }

    VkColorComponentFlags Mask(const Value& v) {
        if (v.is_number) {  // UnityEngine.Rendering.ColorWriteMask: A=1, B=2, G=4, R=8
            const uint32_t m = uint32_t(v.number);
            return (m & 8 ? VK_COLOR_COMPONENT_R_BIT : 0) | (m & 4 ? VK_COLOR_COMPONENT_G_BIT : 0) |
                   (m & 2 ? VK_COLOR_COMPONENT_B_BIT : 0) | (m & 1 ? VK_COLOR_COMPONENT_A_BIT : 0);
        }
        if (v.text == "0") {
            return 0;
        }
        VkColorComponentFlags mask = 0;
        for (char ch : v.text) {
            switch (ch) {
                case 'R':
                    mask |= VK_COLOR_COMPONENT_R_BIT;
                    break;
                case 'G':
                    mask |= VK_COLOR_COMPONENT_G_BIT;
                    break;
                case 'B':
                    mask |= VK_COLOR_COMPONENT_B_BIT;
                    break;
                case 'A':
                    mask |= VK_COLOR_COMPONENT_A_BIT;
                    break;
                default:
                    Fail("unsupported ColorMask '" + v.text + "'");
            }
        }
        return mask;
    }

    // Applies one field to every target or to one.
    template <class F>
    void ForTargets(RenderState& s, int32_t target, F&& f) {
        if (target >= 0 && uint32_t(target) < kMaxTargets) {
            f(s.targets[size_t(target)]);
            return;
        }
        for (auto& t : s.targets) {
            f(t);
        }
    }

    void Apply(RenderState& s, StateField field, int32_t target, const Value& v) {
        switch (field) {
            case StateField::kCull:
                s.cull = Pick(kCull, v, "Cull", VkCullModeFlags(VK_CULL_MODE_BACK_BIT));
                break;
            case StateField::kZTest:
                s.ztest = Pick(kCompare, v, "ZTest", VK_COMPARE_OP_LESS_OR_EQUAL);
                s.depth_test = !(v.is_number ? v.number == 0 : v.text == "Disabled");
                break;
            case StateField::kZWrite:
                s.zwrite = OnOff(v, "ZWrite");
                break;
            case StateField::kZClip:
                s.zclip = OnOff(v, "ZClip");
                break;
            case StateField::kAlphaToMask:
            case StateField::kConservative:
                break;  // single-sampled, no conservative rasterization: no effect
            case StateField::kOffsetFactor:
                s.offset_factor = Number(v, "Offset");
                break;
            case StateField::kOffsetUnits:
                s.offset_units = Number(v, "Offset");
                break;
            case StateField::kBlendOff:
                ForTargets(s, target, [](BlendTarget& t) { t.enable = false; });
                break;
            case StateField::kBlendSrc:
            case StateField::kBlendDst:
            case StateField::kBlendSrcAlpha:
            case StateField::kBlendDstAlpha: {
                const VkBlendFactor f = Pick(kBlendFactors, v, "Blend", VK_BLEND_FACTOR_ONE);
                ForTargets(s, target, [&](BlendTarget& t) {
                    t.enable = true;
                    if (field == StateField::kBlendSrc) {
                        t.src = t.src_alpha = f;  // alpha follows colour unless given
                    } else if (field == StateField::kBlendDst) {
                        t.dst = t.dst_alpha = f;
                    } else if (field == StateField::kBlendSrcAlpha) {
                        t.src_alpha = f;
                    } else {
                        t.dst_alpha = f;
                    }
                });
                break;
            }
            case StateField::kBlendOp:
            case StateField::kBlendOpAlpha: {
                const VkBlendOp op = Pick(kBlendOps, v, "BlendOp", VK_BLEND_OP_ADD);
                ForTargets(s, target, [&](BlendTarget& t) {
                    if (field == StateField::kBlendOp) {
                        t.op = t.op_alpha = op;
                    } else {
                        t.op_alpha = op;
                    }
                });
                break;
            }
            case StateField::kColorMask: {
                const VkColorComponentFlags m = Mask(v);
                ForTargets(s, target, [&](BlendTarget& t) { t.mask = m; });
                break;
            }
            case StateField::kStencilRef:
                s.stencil = true;
                s.stencil_ref = uint32_t(Number(v, "Stencil Ref"));
                break;
            case StateField::kStencilReadMask:
                s.stencil = true;
                s.stencil_read = uint32_t(Number(v, "Stencil ReadMask"));
                break;
            case StateField::kStencilWriteMask:
                s.stencil = true;
                s.stencil_write = uint32_t(Number(v, "Stencil WriteMask"));
                break;
            case StateField::kStencilCompFront:
            case StateField::kStencilCompBack: {
                s.stencil = true;
                auto& face = field == StateField::kStencilCompFront ? s.front : s.back;
                face.compare = Pick(kCompare, v, "Stencil Comp", VK_COMPARE_OP_ALWAYS);
                break;
            }
            default: {
                s.stencil = true;
                const bool front = field <= StateField::kStencilZFailFront;
                auto& face = front ? s.front : s.back;
                const VkStencilOp op =
                    Pick(kStencilOps, v, "stencil operation", VK_STENCIL_OP_KEEP);
                const auto base =
                    front ? StateField::kStencilPassFront : StateField::kStencilPassBack;
                const int which = int(field) - int(base);  // 0 pass, 1 fail, 2 zfail
                (which == 0 ? face.pass : which == 1 ? face.fail : face.zfail) = op;
                break;
            }
        }
    }
};

}  // namespace

std::optional<runtime::Error> ResolveRenderState(const pack::Pack& pack,
                                                 uint32_t pass,
                                                 const PropertyLookup& properties,
                                                 const std::vector<StateOverride>& overrides,
                                                 RenderState& out) {
    Resolver r{properties, std::nullopt};
    RenderState s;
    const pack::PassRec p = pack.Pass(pass);
    for (uint32_t i = 0; i < p.state_count; ++i) {
        const auto rec = pack.Get<pack::StateRec>(pack::SectionTag::kStates, p.first_state + i);
        if (rec.field >= pack::kStateFieldCount) {
            continue;  // a field from a newer minor version
        }
        Value v;
        switch (StateKind(rec.kind)) {
            case StateKind::kNumber:
                v.is_number = true;
                v.number = rec.number;
                break;
            case StateKind::kPropertyRef: {
                const std::string name(pack.String(rec.text));
                const std::optional<float> value = properties ? properties(name) : std::nullopt;
                if (!value) {
                    r.Fail("render state refers to property '" + name +
                           "', which the material does not set and the shader does not declare");
                    continue;
                }
                v.is_number = true;
                v.number = *value;
                break;
            }
            default:
                v.text = std::string(pack.String(rec.text));
                break;
        }
        r.Apply(s, StateField(rec.field), rec.target, v);
    }
    for (const StateOverride& o : overrides) {
        auto text = [&](size_t i) {
            Value v;
            v.text = i < o.values.size() ? o.values[i] : std::string();
            return v;
        };
        if (o.field == "Cull") {
            r.Apply(s, StateField::kCull, -1, text(0));
        } else if (o.field == "ZWrite") {
            r.Apply(s, StateField::kZWrite, -1, text(0));
        } else if (o.field == "ZTest") {
            r.Apply(s, StateField::kZTest, -1, text(0));
        } else if (o.field == "ColorMask") {
            r.Apply(s, StateField::kColorMask, -1, text(0));
        } else if (o.field == "Blend") {
            if (o.values.size() == 1 && o.values[0] == "Off") {
                r.Apply(s, StateField::kBlendOff, -1, text(0));
                continue;
            }
            r.Apply(s, StateField::kBlendSrc, -1, text(0));
            r.Apply(s, StateField::kBlendDst, -1, text(1));
            if (o.values.size() == 4) {
                r.Apply(s, StateField::kBlendSrcAlpha, -1, text(2));
                r.Apply(s, StateField::kBlendDstAlpha, -1, text(3));
            }
        } else {
            r.Fail("unsupported render-state override '" + o.field + "'");
        }
    }
    if (r.error) {
        return r.error;
    }
    out = s;
    return std::nullopt;
}

}  // namespace kiln::vk
