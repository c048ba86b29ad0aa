// Legacy fixed-function commands: Lighting, SeparateSpecular, ColorMaterial, Color, Material { },
// AlphaTest, SetTexture [_Tex] { combine ... }, BindChannels { }, Fog { }. Unity generates vertex
// and fragment programs from them (Unity manual, "ShaderLab: legacy fixed-function"); Kiln's
// generator is hlsl/fixed_function.h.
#include "parser.h"

#include "kiln/base/text.h"

namespace kiln::shaderlab {
namespace {

bool Is(const Token& t, std::string_view word) {
    return t.kind == TokenKind::kIdentifier && EqualsIgnoreCase(t.text, word);
}

using base::ToLower;

const std::vector<std::string_view> kComparisons = {"Greater", "GEqual",   "Less",   "LEqual",
                                                    "Equal",   "NotEqual", "Always", "Never"};

}  // namespace

bool Parser::TryFixedFunctionCommand(FixedFunction& fixed, bool in_pass, bool& ok) {
    if (!At(TokenKind::kIdentifier)) {
        return false;
    }
    const Token& t = Peek();
    if (AtWord("Lighting")) {
        ok = ParseOnOff(fixed.lighting, "Lighting");
    } else if (AtWord("SeparateSpecular")) {
        ok = ParseOnOff(fixed.separate_specular, "SeparateSpecular");
    } else if (AtWord("ColorMaterial")) {
        Next();
        const Token& v = Peek();
        ok = Is(v, "AmbientAndDiffuse") || Is(v, "Emission");
        if (ok) {
            fixed.color_material = Is(v, "Emission") ? "Emission" : "AmbientAndDiffuse";
            Next();
        } else {
            Error(DiagCode::kInvalidValue, v.range,
                  "invalid value " + Describe(v) +
                      " for 'ColorMaterial'; expected AmbientAndDiffuse or Emission");
        }
    } else if (AtWord("Color")) {
        Next();
        fixed.color = ParseFixedValue("for 'Color'", true);
        ok = fixed.color.has_value();
    } else if (AtWord("Material")) {
        ok = ParseMaterialBlock(fixed);
    } else if (AtWord("AlphaTest")) {
        ok = ParseAlphaTest(fixed);
    } else if (AtWord("SetTexture")) {
        if (!in_pass) {
            Error(DiagCode::kMisplacedCommand, t.range,
                  "'SetTexture' is not allowed here; it belongs in a Pass");
            ok = false;
            return true;
        }
        ok = ParseSetTexture(fixed);
    } else if (AtWord("BindChannels")) {
        ok = ParseBindChannels(fixed);
    } else if (AtWord("Fog")) {
        // Kiln's generated programs have no fixed-function fog: `Fog { Mode Off }` is what they
        // do anyway; anything else is reported.
        Next();
        const size_t start = pos_;
        SkipBalanced();
        bool off = false;
        for (size_t i = start; i + 1 < pos_; ++i) {
            off = off || (Is(tokens_[i], "Mode") && Is(tokens_[i + 1], "Off"));
        }
        if (!off) {
            Warning(DiagCode::kLegacyCommandIgnored, t.range,
                    "fixed-function 'Fog' settings are ignored: Kiln's fixed-function passes "
                    "are drawn without fog");
        }
        ok = true;
        return true;
    } else {
        return false;
    }
    fixed.any = true;
    return true;
}

bool Parser::ParseOnOff(std::optional<bool>& slot, std::string_view command) {
    Next();
    const Token& v = Peek();
    if (Is(v, "On") || Is(v, "True")) {
        slot = true;
    } else if (Is(v, "Off") || Is(v, "False")) {
        slot = false;
    } else {
        Error(DiagCode::kInvalidValue, v.range,
              "invalid value " + Describe(v) + " for '" + std::string(command) +
                  "'; expected On or Off");
        return false;
    }
    Next();
    return true;
}

std::optional<FixedValue> Parser::ParseFixedValue(std::string_view context, bool colour) {
    const Token& first = Peek();
    FixedValue v;
    if (At(TokenKind::kLBracket)) {
        Next();
        const Token* name = Expect(TokenKind::kIdentifier, "a property name", "after '['");
        if (name == nullptr || !Expect(TokenKind::kRBracket, "']'", "after the property name")) {
            return std::nullopt;
        }
        v.property = std::string(name->text);
    } else if (colour && At(TokenKind::kLParen)) {
        Next();
        do {
            const std::optional<double> n =
                ParseSignedNumber(std::string("in a colour ") + std::string(context));
            if (!n) {
                return std::nullopt;
            }
            v.numbers.push_back(*n);
        } while (Accept(TokenKind::kComma));
        if (!Expect(TokenKind::kRParen, "')'", "after the colour")) {
            return std::nullopt;
        }
        if (v.numbers.size() < 3 || v.numbers.size() > 4) {
            Error(DiagCode::kInvalidValue, RangeFrom(first),
                  "expected 3 or 4 colour components " + std::string(context) + ", found " +
                      std::to_string(v.numbers.size()));
            return std::nullopt;
        }
        v.numbers.resize(4, 1.0);
    } else {
        const std::optional<double> n = ParseSignedNumber(
            colour ? std::string("or a colour such as (1, 1, 1, 1) ") + std::string(context)
                   : std::string(context));
        if (!n) {
            return std::nullopt;
        }
        v.numbers = colour ? std::vector<double>{*n, *n, *n, *n} : std::vector<double>{*n};
    }
    v.range = RangeFrom(first);
    return v;
}

bool Parser::ParseMaterialBlock(FixedFunction& fixed) {
    Next();
    return ParseBlock("'Material'", [&] {
        const Token& t = Peek();
        std::optional<FixedValue>* slot = nullptr;
        bool colour = true;
        if (Is(t, "Diffuse")) {
            slot = &fixed.diffuse;
        } else if (Is(t, "Ambient")) {
            slot = &fixed.ambient;
        } else if (Is(t, "Specular")) {
            slot = &fixed.specular;
        } else if (Is(t, "Emission")) {
            slot = &fixed.emission;
        } else if (Is(t, "Shininess")) {
            slot = &fixed.shininess;
            colour = false;
        } else {
            Error(DiagCode::kUnknownCommand, t.range,
                  "unknown command " + Describe(t) +
                      " in a Material block; expected Diffuse, Ambient, Specular, Emission or "
                      "Shininess");
            return false;
        }
        Next();
        *slot = ParseFixedValue("for '" + std::string(t.text) + "'", colour);
        return slot->has_value();
    });
}

bool Parser::ParseAlphaTest(FixedFunction& fixed) {
    Next();
    const Token& cmp = Peek();
    if (Is(cmp, "Off")) {
        Next();
        fixed.alpha_test = "Off";
        return true;
    }
    for (std::string_view word : kComparisons) {
        if (Is(cmp, word)) {
            Next();
            fixed.alpha_test = std::string(word);
            if (At(TokenKind::kNumber) || At(TokenKind::kLBracket) || At(TokenKind::kMinus)) {
                fixed.alpha_ref = ParseFixedValue("for 'AlphaTest'", false);
                return fixed.alpha_ref.has_value();
            }
            fixed.alpha_ref = FixedValue{{0.0}, "", cmp.range};
            return true;
        }
    }
    Error(DiagCode::kInvalidValue, cmp.range,
          "invalid value " + Describe(cmp) +
              " for 'AlphaTest'; expected Off, Greater, GEqual, Less, LEqual, Equal, NotEqual, "
              "Always or Never");
    return false;
}

bool Parser::ParseSetTexture(FixedFunction& fixed) {
    const Token& kw = Next();
    TextureStage stage;
    if (!Expect(TokenKind::kLBracket, "'['", "after 'SetTexture'")) {
        return false;
    }
    const Token* name = Expect(TokenKind::kIdentifier, "a texture property name", "after '['");
    if (name == nullptr || !Expect(TokenKind::kRBracket, "']'", "after the texture name")) {
        return false;
    }
    stage.texture = std::string(name->text);
    // Unity's default when a stage has no combine: texture * previous.
    stage.color.op = CombineOp::kMultiply;
    stage.color.sources = {{"texture", false, false}, {"previous", false, false}};
    const bool ok = ParseBlock("'SetTexture'", [&] {
        const Token& t = Peek();
        if (Is(t, "combine")) {
            Next();
            return ParseCombine(stage, t.range.begin.line);
        }
        if (Is(t, "constantColor")) {
            Next();
            stage.constant_color = ParseFixedValue("for 'constantColor'", true);
            return stage.constant_color.has_value();
        }
        if (Is(t, "matrix")) {
            Warning(DiagCode::kLegacyCommandIgnored, t.range,
                    "texture 'matrix' of a SetTexture stage is ignored; the texture's tiling "
                    "and offset (_ST) apply");
            return false;  // skip the rest of the line
        }
        Error(DiagCode::kUnknownCommand, t.range,
              "unknown command " + Describe(t) +
                  " in a SetTexture block; expected combine, constantColor or matrix");
        return false;
    });
    stage.range = RangeFrom(kw);
    fixed.stages.push_back(std::move(stage));
    return ok;
}

bool Parser::ParseCombine(TextureStage& stage, uint32_t line) {
    std::optional<Combiner> color = ParseCombiner(line);
    if (!color) {
        return false;
    }
    stage.color = *color;
    stage.alpha.reset();
    if (Peek().range.begin.line == line && Accept(TokenKind::kComma)) {
        stage.alpha = ParseCombiner(line);
        return stage.alpha.has_value();
    }
    return true;
}

std::optional<CombineSource> Parser::ParseCombineSource(uint32_t line) {
    CombineSource src;
    const Token& t = Peek();
    if (Is(t, "one") && Peek(1).kind == TokenKind::kMinus) {
        Next();
        Next();
        src.one_minus = true;
    }
    const Token& n = Peek();
    if (n.range.begin.line == line &&
        (Is(n, "previous") || Is(n, "primary") || Is(n, "texture") || Is(n, "constant"))) {
        src.name = ToLower(n.text);
        Next();
    } else {
        Error(DiagCode::kInvalidValue, n.range,
              "expected a combine source (previous, primary, texture or constant), found " +
                  Describe(n));
        return std::nullopt;
    }
    if (Peek().range.begin.line == line && AtWord("alpha")) {
        Next();
        src.alpha = true;
    }
    return src;
}

std::optional<Combiner> Parser::ParseCombiner(uint32_t line) {
    Combiner c;
    auto source = [&]() -> bool {
        std::optional<CombineSource> s = ParseCombineSource(line);
        if (s) {
            c.sources.push_back(*s);
        }
        return s.has_value();
    };
    auto on_line = [&] { return Peek().range.begin.line == line; };
    auto at_star = [&] {
        return on_line() && Peek().kind == TokenKind::kUnknown && Peek().text == "*";
    };
    if (!source()) {
        return std::nullopt;
    }
    if (at_star()) {
        Next();
        if (!source()) {
            return std::nullopt;
        }
        c.op = CombineOp::kMultiply;
        if (on_line() && (At(TokenKind::kPlus) || At(TokenKind::kMinus))) {
            const bool minus = At(TokenKind::kMinus);
            Next();
            const bool signed_add = !minus && on_line() && Accept(TokenKind::kMinus);
            if (!source()) {
                return std::nullopt;
            }
            c.op = minus ? CombineOp::kMultiplySubtract
                         : (signed_add ? CombineOp::kMultiplyAddSigned : CombineOp::kMultiplyAdd);
        }
    } else if (on_line() && (At(TokenKind::kPlus) || At(TokenKind::kMinus))) {
        const bool minus = At(TokenKind::kMinus);
        Next();
        const bool signed_add = !minus && on_line() && Accept(TokenKind::kMinus);
        if (!source()) {
            return std::nullopt;
        }
        c.op =
            minus ? CombineOp::kSubtract : (signed_add ? CombineOp::kAddSigned : CombineOp::kAdd);
    } else if (on_line() && AtWord("lerp")) {
        Next();
        if (!Expect(TokenKind::kLParen, "'('", "after 'lerp'") || !source() ||
            !Expect(TokenKind::kRParen, "')'", "after the lerp source") || !source()) {
            return std::nullopt;
        }
        c.op = CombineOp::kLerp;
    }
    if (on_line() && (AtWord("Double") || AtWord("Quad"))) {
        c.scale = AtWord("Double") ? 2 : 4;
        Next();
    }
    return c;
}

bool Parser::ParseBindChannels(FixedFunction& fixed) {
    Next();
    return ParseBlock("'BindChannels'", [&] {
        if (!AtWord("Bind")) {
            Error(
                DiagCode::kUnknownCommand, Peek().range,
                "unknown command " + Describe(Peek()) + " in a BindChannels block; expected Bind");
            return false;
        }
        Next();
        const Token* from =
            Expect(TokenKind::kString, "a vertex data name such as \"Vertex\"", "after 'Bind'");
        if (from == nullptr || !Expect(TokenKind::kComma, "','", "after the vertex data name")) {
            return false;
        }
        const Token* to =
            Expect(TokenKind::kIdentifier, "a target such as vertex or texcoord", "after ','");
        if (to == nullptr) {
            return false;
        }
        fixed.bindings.emplace_back(ToLower(from->text), ToLower(to->text));
        return true;
    });
}

}  // namespace kiln::shaderlab
