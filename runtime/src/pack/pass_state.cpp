// ResolvePassState (kiln/pack/render_state.h): a pass's StateRecs and a material's overrides as
// Unity's enums. Literals are the canonical words the compiler wrote; numbers and [property]
// values are Unity's numeric values.
#include "kiln/pack/render_state.h"

#include <cmath>
#include <cstdlib>
#include <utility>

#include "kiln/pack/engine_names.h"
#include "kiln/pack/reader.h"

namespace kiln::pack {
namespace {

struct Value {
    bool is_number = false;
    float number = 0;
    std::string text;
};

struct Resolver {
    std::optional<std::string> error;

    void Fail(std::string message) {
        if (!error) {
            error = std::move(message);
        }
    }

    // A value of `set`, by its word or by Unity's numeric value.
    uint32_t Pick(StateValues set, const Value& v, std::string_view what, uint32_t fallback) {
        const size_t count = StateValueNames(set).size();
        if (v.is_number) {
            const float n = v.number;
            if (std::isfinite(n) && n >= 0 && n < float(count) && n == std::floor(n)) {
                return uint32_t(n);
            }
            Fail(std::string(what) + " value " + std::to_string(n) + " is not a valid " +
                 std::string(what) + " (0.." + std::to_string(count - 1) + ")");
            return fallback;
        }
        if (std::optional<uint32_t> value = ParseStateValue(set, v.text)) {
            return *value;
        }
        Fail("unsupported " + std::string(what) + " '" + v.text + "'");
        return fallback;
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

    uint32_t Mask(const Value& v) {
        if (v.is_number) {
            return uint32_t(v.number) & kColorWriteAll;
        }
        if (std::optional<uint32_t> mask = ParseColorMask(v.text)) {
            return *mask;
        }
        Fail("unsupported ColorMask '" + v.text + "'");
        return kColorWriteAll;
    }

    // Applies one field to every target or to one.
    template <class F>
    void ForTargets(PassState& s, int32_t target, F&& f) {
        if (target >= 0 && uint32_t(target) < kMaxRenderTargets) {
            f(s.targets[size_t(target)]);
            return;
        }
        for (auto& t : s.targets) {
            f(t);
        }
    }

    void ApplyBlend(PassState& s, StateField field, int32_t target, const Value& v) {
        if (field == StateField::kBlendOff) {
            ForTargets(s, target, [](BlendTargetState& t) { t.enable = false; });
            return;
        }
        if (field == StateField::kBlendOp || field == StateField::kBlendOpAlpha) {
            const auto op =
                BlendOp(Pick(StateValues::kBlendOp, v, "BlendOp", uint32_t(BlendOp::kAdd)));
            ForTargets(s, target, [&](BlendTargetState& t) {
                t.op_alpha = op;
                t.op = field == StateField::kBlendOp ? op : t.op;
            });
            return;
        }
        const auto f =
            BlendFactor(Pick(StateValues::kBlendFactor, v, "Blend", uint32_t(BlendFactor::kOne)));
        ForTargets(s, target, [&](BlendTargetState& t) {
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
    }

    void ApplyStencil(PassState& s, StateField field, const Value& v) {
        s.stencil = true;
        const char* what = StateFieldName(field);
        switch (field) {
            case StateField::kStencilRef:
                s.stencil_ref = uint32_t(Number(v, what));
                return;
            case StateField::kStencilReadMask:
                s.stencil_read = uint32_t(Number(v, what));
                return;
            case StateField::kStencilWriteMask:
                s.stencil_write = uint32_t(Number(v, what));
                return;
            case StateField::kStencilCompFront:
            case StateField::kStencilCompBack:
                (field == StateField::kStencilCompFront ? s.front : s.back).compare =
                    CompareFunction(
                        Pick(StateValues::kCompare, v, what, uint32_t(CompareFunction::kAlways)));
                return;
            default:
                break;
        }
        const bool front = field <= StateField::kStencilZFailFront;
        StencilFaceState& face = front ? s.front : s.back;
        const auto op = StencilOp(
            Pick(StateValues::kStencilOp, v, "stencil operation", uint32_t(StencilOp::kKeep)));
        const auto base = front ? StateField::kStencilPassFront : StateField::kStencilPassBack;
        const int which = int(field) - int(base);  // 0 pass, 1 fail, 2 zfail
        (which == 0 ? face.pass : which == 1 ? face.fail : face.zfail) = op;
    }

    void Apply(PassState& s, StateField field, int32_t target, const Value& v) {
        const auto on = [&](const char* what) {
            return Pick(StateValues::kOnOff,
                        v.is_number ? Value{true, v.number != 0 ? 1.0f : 0.0f, {}} : v, what,
                        0) != 0;
        };
        switch (field) {
            case StateField::kCull:
                s.cull = CullMode(Pick(StateValues::kCull, v, "Cull", uint32_t(CullMode::kBack)));
                return;
            case StateField::kZTest:
                s.ztest = CompareFunction(
                    Pick(StateValues::kCompare, v, "ZTest", uint32_t(CompareFunction::kLessEqual)));
                return;
            case StateField::kZWrite:
                s.zwrite = on("ZWrite");
                return;
            case StateField::kZClip:
                s.zclip = on("ZClip");
                return;
            case StateField::kAlphaToMask:
                s.alpha_to_mask = on("AlphaToMask");
                return;
            case StateField::kConservative:
                s.conservative = on("Conservative");
                return;
            case StateField::kOffsetFactor:
                s.offset_factor = Number(v, "Offset");
                return;
            case StateField::kOffsetUnits:
                s.offset_units = Number(v, "Offset");
                return;
            case StateField::kColorMask: {
                const uint32_t m = Mask(v);
                ForTargets(s, target, [&](BlendTargetState& t) { t.color_mask = m; });
                return;
            }
            default:
                break;
        }
        if (field >= StateField::kBlendOff && field <= StateField::kBlendOpAlpha) {
            ApplyBlend(s, field, target, v);
        } else {
            ApplyStencil(s, field, v);
        }
    }

    void Override(PassState& s, const StateOverride& o) {
        const auto text = [&](size_t i) {
            return Value{false, 0, i < o.values.size() ? o.values[i] : std::string()};
        };
        // The one-value fields of OverridableStateFields().
        constexpr std::pair<std::string_view, StateField> kSingle[] = {
            {"Cull", StateField::kCull},
            {"ZWrite", StateField::kZWrite},
            {"ZTest", StateField::kZTest},
            {"ColorMask", StateField::kColorMask}};
        for (const auto& [name, field] : kSingle) {
            if (o.field == name) {
                Apply(s, field, -1, text(0));
                return;
            }
        }
        if (o.field == "Blend") {
            if (o.values.size() == 1 && o.values[0] == "Off") {
                Apply(s, StateField::kBlendOff, -1, text(0));
                return;
            }
            Apply(s, StateField::kBlendSrc, -1, text(0));
            Apply(s, StateField::kBlendDst, -1, text(1));
            if (o.values.size() == 4) {
                Apply(s, StateField::kBlendSrcAlpha, -1, text(2));
                Apply(s, StateField::kBlendDstAlpha, -1, text(3));
            }
        } else {
            Fail("unsupported render-state override '" + o.field + "'");
        }
    }
};

}  // namespace

Result<PassState> ResolvePassState(const Pack& pack,
                                   uint32_t pass,
                                   const PropertyLookup& properties,
                                   std::span<const StateOverride> overrides) {
    if (pass >= pack.Count(SectionTag::kPasses)) {
        return Error{DiagCode::kIndexOutOfRange,
                     "pass index " + std::to_string(pass) + " is out of range (the pack has " +
                         std::to_string(pack.Count(SectionTag::kPasses)) + " passes)"};
    }
    Resolver r;
    PassState s;
    const PassRec p = pack.Pass(pass).value();
    for (uint32_t i = 0; i < p.state_count; ++i) {
        const auto rec = pack.Get<StateRec>(SectionTag::kStates, p.first_state + i).value();
        if (rec.field >= kStateFieldCount) {
            continue;  // a field from a newer minor version
        }
        Value v;
        if (StateKind(rec.kind) == StateKind::kNumber) {
            v = Value{true, rec.number, {}};
        } else if (StateKind(rec.kind) == StateKind::kPropertyRef) {
            const std::string name(pack.String(rec.text));
            std::optional<float> value = properties ? properties(name) : std::nullopt;
            if (!value && name == kStateGuiZTestMode)
                value = kStateGuiZTestModeValue;  // set by Unity's UI system, not a material
            if (!value) {
                r.Fail("render state refers to property '" + name +
                       "', which the material does not set and the shader does not declare");
                continue;
            }
            v = Value{true, *value, {}};
        } else {
            v.text = std::string(pack.String(rec.text));
        }
        r.Apply(s, StateField(rec.field), rec.target, v);
    }
    for (const StateOverride& o : overrides) {
        r.Override(s, o);
    }
    if (r.error) {
        return Error{DiagCode::kMaterialRenderState, *r.error};
    }
    return s;
}

}  // namespace kiln::pack
