// Render-state commands: Cull, ZTest, ZWrite, ZClip, AlphaToMask, Conservative, Offset, Blend,
// BlendOp, ColorMask and Stencil { }. Every value may be a property reference such as [_Cull].
#include "parser.h"

#include <algorithm>

#include "kiln/pack/names.h"
#include "kiln/pack/render_state.h"

namespace kiln::shaderlab {
namespace {

using Words = std::vector<std::string_view>;

constexpr int kMaxRenderTargets = int(pack::kMaxRenderTargets);

std::string JoinWords(std::span<const std::string_view> words) {
    std::string out;
    for (size_t i = 0; i < words.size(); ++i) {
        out += (i == 0 ? "" : ", ") + std::string(words[i]);
    }
    return out;
}

}  // namespace

bool Parser::TryStateCommand(RenderState& state, bool& ok) {
    if (!At(TokenKind::kIdentifier)) {
        return false;
    }
    if (AtWord("Cull")) {
        ok = ParseSimpleState(state.cull, "Cull", pack::StateValues::kCull);
    } else if (AtWord("ZTest")) {
        ok = ParseSimpleState(state.ztest, "ZTest", pack::StateValues::kCompare);
    } else if (AtWord("ZWrite")) {
        ok = ParseSimpleState(state.zwrite, "ZWrite", pack::StateValues::kOnOff);
    } else if (AtWord("ZClip")) {
        ok = ParseSimpleState(state.zclip, "ZClip", pack::StateValues::kOnOff);
    } else if (AtWord("AlphaToMask")) {
        ok = ParseSimpleState(state.alpha_to_mask, "AlphaToMask", pack::StateValues::kOnOff);
    } else if (AtWord("Conservative")) {
        ok = ParseSimpleState(state.conservative, "Conservative", pack::StateValues::kOnOff);
    } else if (AtWord("Offset")) {
        ok = ParseOffset(state);
    } else if (AtWord("Blend")) {
        ok = ParseBlend(state);
    } else if (AtWord("BlendOp")) {
        ok = ParseBlendOp(state);
    } else if (AtWord("ColorMask")) {
        ok = ParseColorMask(state);
    } else if (AtWord("Stencil")) {
        ok = ParseStencil(state);
    } else {
        return false;
    }
    return true;
}

std::optional<StateValue> Parser::ParsePropertyRef() {
    const Token& open = Next();  // '['
    const Token* name = Expect(TokenKind::kIdentifier, "a property name", "after '['");
    if (name == nullptr || !Expect(TokenKind::kRBracket, "']'", "after the property name")) {
        return std::nullopt;
    }
    return StateValue{StateValue::Kind::kPropertyRef, std::string(name->text), 0, RangeFrom(open)};
}

std::optional<StateValue> Parser::ParseEnumValue(std::string_view command, pack::StateValues set) {
    if (At(TokenKind::kLBracket)) {
        return ParsePropertyRef();
    }
    const Token& t = Peek();
    const std::span<const std::string_view> names = pack::StateValueNames(set);
    if (t.kind == TokenKind::kIdentifier) {
        if (const std::optional<uint32_t> value = pack::ParseStateValue(set, t.text)) {
            Next();
            return StateValue{StateValue::Kind::kLiteral, std::string(names[*value]), 0, t.range};
        }
    }
    Error(DiagCode::kInvalidValue, t.range,
          "invalid value " + Describe(t) + " for '" + std::string(command) + "'; expected " +
              JoinWords(names) + " or a [property] reference" +
              pack::DidYouMean(t.text, std::vector<std::string>(names.begin(), names.end())));
    return std::nullopt;
}

std::optional<StateValue> Parser::ParseNumberValue(std::string_view command,
                                                   double min,
                                                   double max,
                                                   bool integer) {
    if (At(TokenKind::kLBracket)) {
        return ParsePropertyRef();
    }
    const Token& first = Peek();
    const bool negative = Accept(TokenKind::kMinus);
    const Token& t = Peek();
    std::optional<double> v = t.kind == TokenKind::kNumber ? ParseDouble(t.text) : std::nullopt;
    if (v && negative) {
        *v = -*v;
    }
    if (!v || *v < min || *v > max ||
        (integer && *v != static_cast<double>(static_cast<int64_t>(*v)))) {
        const std::string expected =
            integer ? "an integer from " + std::to_string(static_cast<int64_t>(min)) + " to " +
                          std::to_string(static_cast<int64_t>(max))
                    : std::string("a number");
        Error(DiagCode::kInvalidValue, t.kind == TokenKind::kNumber ? RangeFrom(first) : t.range,
              "invalid value " + Describe(t) + " for '" + std::string(command) + "'; expected " +
                  expected + " or a [property] reference");
        return std::nullopt;
    }
    Next();
    return StateValue{StateValue::Kind::kNumber,
                      std::string(negative ? "-" : "") + std::string(t.text), *v, RangeFrom(first)};
}

bool Parser::ParseSimpleState(std::optional<SimpleState>& slot,
                              std::string_view command,
                              pack::StateValues set) {
    const Token& kw = Next();
    const std::optional<StateValue> v = ParseEnumValue(command, set);
    if (!v) {
        return false;
    }
    SimpleState st{RangeFrom(kw), *v};
    if (slot) {
        WarnDuplicate(DiagCode::kDuplicateCommand, st.range,
                      "'" + std::string(command) + "' command", slot->range);
    }
    slot = st;
    return true;
}

bool Parser::ParseOffset(RenderState& state) {
    const Token& kw = Next();
    const std::optional<StateValue> factor = ParseNumberValue("Offset", -1e9, 1e9, false);
    if (!factor || !Expect(TokenKind::kComma, "','", "between the Offset factor and units")) {
        return false;
    }
    const std::optional<StateValue> units = ParseNumberValue("Offset", -1e9, 1e9, false);
    if (!units) {
        return false;
    }
    state.offset = OffsetState{RangeFrom(kw), *factor, *units};
    return true;
}

std::optional<int> Parser::ParseRenderTarget(std::string_view command) {
    if (!At(TokenKind::kNumber)) {
        return -1;
    }
    const Token& t = Next();
    const std::optional<double> v = ParseDouble(t.text);
    if (!v || *v < 0 || *v >= kMaxRenderTargets ||
        *v != static_cast<double>(static_cast<int>(*v))) {
        Error(DiagCode::kBadRenderTarget, t.range,
              "render target index " + std::string(t.text) + " of '" + std::string(command) +
                  "' is out of range; expected 0 to " + std::to_string(kMaxRenderTargets - 1));
        return std::nullopt;
    }
    return static_cast<int>(*v);
}

bool Parser::ParseBlend(RenderState& state) {
    const Token& kw = Next();
    BlendState b;
    const std::optional<int> target = ParseRenderTarget("Blend");
    if (!target) {
        return false;
    }
    b.target = *target;
    if (AtWord("Off")) {
        Next();
        b.off = true;
    } else {
        std::optional<StateValue> src = ParseEnumValue("Blend", pack::StateValues::kBlendFactor);
        std::optional<StateValue> dst =
            src ? ParseEnumValue("Blend", pack::StateValues::kBlendFactor) : std::nullopt;
        if (!dst) {
            return false;
        }
        b.src = *src;
        b.dst = *dst;
        if (Accept(TokenKind::kComma)) {
            b.src_alpha = ParseEnumValue("Blend", pack::StateValues::kBlendFactor);
            b.dst_alpha = b.src_alpha ? ParseEnumValue("Blend", pack::StateValues::kBlendFactor)
                                      : std::nullopt;
            if (!b.dst_alpha) {
                return false;
            }
        }
    }
    b.range = RangeFrom(kw);
    for (const BlendState& other : state.blend) {
        if (other.target == b.target) {
            WarnDuplicate(DiagCode::kDuplicateCommand, b.range,
                          "'Blend' command for the same render target", other.range);
        }
    }
    state.blend.push_back(std::move(b));
    return true;
}

bool Parser::ParseBlendOp(RenderState& state) {
    const Token& kw = Next();
    BlendOpState b;
    const std::optional<int> target = ParseRenderTarget("BlendOp");
    if (!target) {
        return false;
    }
    b.target = *target;
    const std::optional<StateValue> op = ParseEnumValue("BlendOp", pack::StateValues::kBlendOp);
    if (!op) {
        return false;
    }
    b.op = *op;
    if (Accept(TokenKind::kComma)) {
        b.op_alpha = ParseEnumValue("BlendOp", pack::StateValues::kBlendOp);
        if (!b.op_alpha) {
            return false;
        }
    }
    b.range = RangeFrom(kw);
    for (const BlendOpState& other : state.blend_op) {
        if (other.target == b.target) {
            WarnDuplicate(DiagCode::kDuplicateCommand, b.range,
                          "'BlendOp' command for the same render target", other.range);
        }
    }
    state.blend_op.push_back(std::move(b));
    return true;
}

bool Parser::ParseColorMask(RenderState& state) {
    const Token& kw = Next();
    ColorMaskState cm;
    const Token& t = Peek();
    if (At(TokenKind::kLBracket)) {
        std::optional<StateValue> ref = ParsePropertyRef();
        if (!ref) {
            return false;
        }
        cm.mask = *ref;
    } else {
        // 0, or a set of the letters R, G, B, A in any order, each at most once.
        std::optional<uint32_t> mask;
        if ((t.kind == TokenKind::kNumber && t.text == "0") || t.kind == TokenKind::kIdentifier) {
            mask = pack::ParseColorMask(t.text);
        }
        const bool valid = mask.has_value();
        const std::string canonical = valid ? pack::ColorMaskName(*mask) : "";
        if (!valid) {
            Error(DiagCode::kInvalidValue, t.range,
                  "invalid value " + Describe(t) +
                      " for 'ColorMask'; expected 0, a combination of R, G, B and A, or a "
                      "[property] reference");
            return false;
        }
        Next();
        cm.mask = StateValue{StateValue::Kind::kLiteral, canonical, 0, t.range};
    }
    const std::optional<int> target = ParseRenderTarget("ColorMask");
    if (!target) {
        return false;
    }
    cm.target = *target;
    cm.range = RangeFrom(kw);
    for (const ColorMaskState& other : state.color_mask) {
        if (other.target == cm.target) {
            WarnDuplicate(DiagCode::kDuplicateCommand, cm.range,
                          "'ColorMask' command for the same render target", other.range);
        }
    }
    state.color_mask.push_back(std::move(cm));
    return true;
}

bool Parser::ParseStencil(RenderState& state) {
    const Token& kw = Next();
    StencilState st;
    const bool ok = ParseBlock("'Stencil'", [&] {
        static const Words kMasks = {"Ref", "ReadMask", "WriteMask"};
        static const Words kComps = {"Comp", "CompFront", "CompBack"};
        static const Words kOps = {"Pass",       "Fail",     "ZFail",    "PassFront", "FailFront",
                                   "ZFailFront", "PassBack", "FailBack", "ZFailBack"};
        const Token& k = Peek();
        if (k.kind != TokenKind::kIdentifier) {
            ErrorUnexpected(k, "in a Stencil block");
            return false;
        }
        auto match = [&](const Words& words) -> std::string_view {
            for (std::string_view w : words) {
                if (EqualsIgnoreCase(k.text, w)) {
                    return w;
                }
            }
            return {};
        };
        std::optional<StateValue> value;
        std::string_view key;
        if (!(key = match(kMasks)).empty()) {
            Next();
            value = ParseNumberValue(key, 0, 255, true);
        } else if (!(key = match(kComps)).empty()) {
            Next();
            value = ParseEnumValue(key, pack::StateValues::kCompare);
        } else if (!(key = match(kOps)).empty()) {
            Next();
            value = ParseEnumValue(key, pack::StateValues::kStencilOp);
        } else {
            Error(DiagCode::kUnknownCommand, k.range,
                  "unknown stencil command '" + std::string(k.text) +
                      "'; expected Ref, ReadMask, WriteMask, Comp, Pass, Fail or ZFail (optionally "
                      "with a Front or Back suffix)");
            return false;
        }
        if (!value) {
            return false;
        }
        StencilEntry entry{std::string(key), *value, RangeFrom(k)};
        for (const StencilEntry& other : st.entries) {
            if (other.key == entry.key) {
                WarnDuplicate(DiagCode::kDuplicateCommand, entry.range,
                              "stencil '" + entry.key + "' command", other.range);
            }
        }
        st.entries.push_back(std::move(entry));
        return true;
    });
    st.range = RangeFrom(kw);
    if (state.stencil) {
        WarnDuplicate(DiagCode::kDuplicateCommand, st.range, "'Stencil' block",
                      state.stencil->range);
    }
    state.stencil = std::move(st);
    return ok;
}

}  // namespace kiln::shaderlab
