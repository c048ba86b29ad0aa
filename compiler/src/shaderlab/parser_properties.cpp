// Properties { [Attr] _Name ("Display", Type) = Default ... }
#include "parser.h"

namespace kiln::shaderlab {
namespace {

struct TypeSpec {
    const char* name;
    PropertyType type;
};

constexpr TypeSpec kTypes[] = {
    {"Color", PropertyType::kColor},         {"Vector", PropertyType::kVector},
    {"Float", PropertyType::kFloat},         {"Int", PropertyType::kInt},
    {"Integer", PropertyType::kInteger},     {"Range", PropertyType::kRange},
    {"2D", PropertyType::kTexture2D},        {"3D", PropertyType::kTexture3D},
    {"Cube", PropertyType::kCube},           {"2DArray", PropertyType::kTexture2DArray},
    {"CubeArray", PropertyType::kCubeArray}, {"Any", PropertyType::kTextureAny},
    {"Rect", PropertyType::kTexture2D},  // legacy spelling of 2D that Unity still accepts
};

constexpr const char* kTypeList =
    "Color, Vector, Float, Int, Integer, Range(min, max), 2D, 3D, Cube, 2DArray, CubeArray or Any";

// Attributes Kiln knows, with their argument counts (-1: no upper bound) and canonical spelling.
// Unknown attributes are kept as written: they may be custom material property drawers.
struct AttributeSpec {
    const char* name;
    int min_args;
    int max_args;
    bool numeric;  // the argument must be a number
};

constexpr AttributeSpec kAttributes[] = {
    {"HDR", 0, 0, false},
    {"Gamma", 0, 0, false},
    {"NoScaleOffset", 0, 0, false},
    {"Normal", 0, 0, false},
    {"Linear", 0, 0, false},  // Kiln: a texture of data, sampled without sRGB decoding
    {"MainTexture", 0, 0, false},
    {"MainColor", 0, 0, false},
    {"HideInInspector", 0, 0, false},
    {"PerRendererData", 0, 0, false},
    {"Toggle", 0, 1, false},
    {"ToggleOff", 0, 1, false},
    {"KeywordEnum", 1, 9, false},
    {"Enum", 1, -1, false},
    {"PowerSlider", 1, 1, true},
    {"IntRange", 0, 0, false},
    {"Header", 1, -1, false},
    {"Space", 0, 1, true},
};

std::string Trim(std::string_view s) {
    size_t b = 0;
    size_t e = s.size();
    while (b < e && (s[b] == ' ' || s[b] == '\t')) {
        ++b;
    }
    while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t')) {
        --e;
    }
    return std::string(s.substr(b, e - b));
}

std::vector<std::string> SplitArgs(std::string_view raw) {
    std::vector<std::string> args;
    if (Trim(raw).empty()) {
        return args;
    }
    size_t start = 0;
    while (true) {
        const size_t comma = raw.find(',', start);
        args.push_back(Trim(raw.substr(start, comma - start)));
        if (comma == std::string_view::npos) {
            break;
        }
        start = comma + 1;
    }
    return args;
}

std::string CountText(int n, const char* noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace

bool Parser::ParseProperties(Shader& shader) {
    const Token& kw = Next();
    if (shader.properties_range) {
        Diagnostic& d = Error(DiagCode::kDuplicateCommand, kw.range,
                              "duplicate 'Properties' block; a Shader has at most one");
        d.notes.push_back({source_.path(), *shader.properties_range, "first declared here"});
    }
    const bool ok = ParseBlock("'Properties'", [&] {
        const bool prop_ok = ParseProperty(shader.properties);
        shader.properties_incomplete = shader.properties_incomplete || !prop_ok;
        return prop_ok;
    });
    if (!shader.properties_range) {
        shader.properties_range = RangeFrom(kw);
    }
    return ok;
}

bool Parser::ParseProperty(std::vector<Property>& out) {
    const Token& first = Peek();
    Property prop;
    while (At(TokenKind::kLBracket)) {
        if (!ParseAttribute(prop.attributes)) {
            return false;
        }
    }
    const Token* name = Expect(TokenKind::kIdentifier, "a property name", "in a Properties block");
    if (name == nullptr) {
        return false;
    }
    prop.name = std::string(name->text);
    prop.name_range = name->range;
    if (!Expect(TokenKind::kLParen, "'('", "after the property name '" + prop.name + "'")) {
        return false;
    }
    const Token* display = Expect(TokenKind::kString, "a display name string", "after '('");
    if (display == nullptr) {
        return false;
    }
    prop.display_name = std::string(display->text);
    if (!Expect(TokenKind::kComma, "','", "after the display name") || !ParsePropertyType(prop) ||
        !Expect(TokenKind::kRParen, "')'", "after the property type") ||
        !Expect(TokenKind::kEquals, "'='", "before the default value of '" + prop.name + "'") ||
        !ParsePropertyDefault(prop)) {
        return false;
    }
    prop.range = RangeFrom(first);
    out.push_back(std::move(prop));
    return true;
}

bool Parser::ParseAttribute(std::vector<Attribute>& out) {
    const Token& open = Next();  // '['
    Attribute attr;
    const Token* name = Expect(TokenKind::kIdentifier, "an attribute name", "after '['");
    if (name == nullptr) {
        return false;
    }
    attr.name = std::string(name->text);
    // Dotted names (Unity's virtual texturing: [TextureStack.Stack]).
    while (Peek().kind == TokenKind::kUnknown && Peek().text == "." &&
           Peek(1).kind == TokenKind::kIdentifier &&
           Peek(1).range.begin.offset == Peek().range.end.offset) {
        Next();
        attr.name += "." + std::string(Next().text);
    }
    if (At(TokenKind::kLParen)) {
        const Token& lparen = Next();
        attr.has_parens = true;
        // Arguments are free text (e.g. [Header(Specular settings)]): take the raw source up to
        // ')'.
        while (!At(TokenKind::kRParen)) {
            const Token& t = Peek();
            if (t.kind == TokenKind::kEof || t.kind == TokenKind::kRBracket ||
                t.kind == TokenKind::kLBrace || t.kind == TokenKind::kRBrace ||
                t.range.begin.line != lparen.range.begin.line) {
                Diagnostic& d = Error(DiagCode::kBadAttribute, t.range,
                                      "expected ')' to close the arguments of attribute '" +
                                          attr.name + "', found " + Describe(t));
                d.notes.push_back({source_.path(), lparen.range, "'(' opened here"});
                return false;
            }
            Next();
        }
        const Token& rparen = Next();
        const std::string_view text = source_.text();
        attr.raw_args = std::string(text.substr(
            lparen.range.end.offset, rparen.range.begin.offset - lparen.range.end.offset));
        attr.args = SplitArgs(attr.raw_args);
    }
    if (!Expect(TokenKind::kRBracket, "']'", "to close attribute '" + attr.name + "'")) {
        return false;
    }
    attr.range = RangeFrom(open);
    for (const AttributeSpec& spec : kAttributes) {
        if (!EqualsIgnoreCase(attr.name, spec.name)) {
            continue;
        }
        attr.name = spec.name;
        const int n = static_cast<int>(attr.args.size());
        std::string problem;
        if (n < spec.min_args || (spec.max_args >= 0 && n > spec.max_args)) {
            problem = spec.min_args == spec.max_args
                          ? "takes " + CountText(spec.min_args, "argument")
                          : "takes " + std::to_string(spec.min_args) + " to " +
                                (spec.max_args < 0 ? std::string("any number of")
                                                   : std::to_string(spec.max_args)) +
                                " arguments";
            problem += ", found " + std::to_string(n);
        } else if (spec.numeric && n == 1 && !ParseDouble(attr.args[0])) {
            problem = "takes a number, found '" + attr.args[0] + "'";
        } else if (attr.name == std::string("Enum") && n > 1) {
            if (n % 2 != 0) {
                problem = "takes an enum type name or name, value pairs, found " +
                          CountText(n, "argument");
            }
            for (int i = 1; problem.empty() && i < n; i += 2) {
                if (!ParseDouble(attr.args[i])) {
                    problem = "value '" + attr.args[i] + "' of '" + attr.args[i - 1] +
                              "' is not a number";
                }
            }
        }
        if (!problem.empty()) {
            Error(DiagCode::kBadAttribute, attr.range, "attribute '" + attr.name + "' " + problem);
            return false;
        }
        break;
    }
    out.push_back(std::move(attr));
    return true;
}

bool Parser::ParsePropertyType(Property& prop) {
    const Token& t = Peek();
    prop.type_range = t.range;
    if (t.kind == TokenKind::kIdentifier) {
        for (const TypeSpec& spec : kTypes) {
            if (EqualsIgnoreCase(t.text, spec.name)) {
                prop.type = spec.type;
                Next();
                if (spec.type != PropertyType::kRange) {
                    return true;
                }
                if (!Expect(TokenKind::kLParen, "'('", "after 'Range'")) {
                    return false;
                }
                const std::optional<double> lo = ParseSignedNumber("as the Range minimum");
                if (!lo || !Expect(TokenKind::kComma, "','", "after the Range minimum")) {
                    return false;
                }
                const std::optional<double> hi = ParseSignedNumber("as the Range maximum");
                if (!hi || !Expect(TokenKind::kRParen, "')'", "after the Range maximum")) {
                    return false;
                }
                prop.range_min = *lo;
                prop.range_max = *hi;
                prop.type_range = RangeFrom(t);
                return true;
            }
        }
    }
    Error(DiagCode::kUnknownPropertyType, t.range,
          "expected a property type (" + std::string(kTypeList) + "), found " + Describe(t));
    return false;
}

std::optional<double> Parser::ParseSignedNumber(std::string_view context) {
    const Token& first = Peek();
    double sign = 1;
    if (Accept(TokenKind::kMinus)) {
        sign = -1;
    } else {
        Accept(TokenKind::kPlus);
    }
    const Token& t = Peek();
    std::optional<double> v;
    if (t.kind == TokenKind::kNumber) {
        v = ParseDouble(t.text);
    }
    if (!v) {
        Error(DiagCode::kExpectedNumber, t.kind == TokenKind::kNumber ? t.range : first.range,
              (t.kind == TokenKind::kNumber
                   ? "number " + std::string(t.text) + " is out of range "
                   : "expected a number " + std::string(context) + ", found " + Describe(t)));
        return std::nullopt;
    }
    Next();
    return sign * *v;
}

bool Parser::ParsePropertyDefault(Property& prop) {
    const Token& first = Peek();
    const std::string what =
        std::string(PropertyTypeName(prop.type)) + " property '" + prop.name + "'";
    switch (prop.type) {
        case PropertyType::kColor:
        case PropertyType::kVector: {
            if (!At(TokenKind::kLParen)) {
                Error(DiagCode::kBadPropertyDefault, first.range,
                      "expected a default such as (1, 1, 1, 1) for " + what + ", found " +
                          Describe(first));
                return false;
            }
            Next();
            std::vector<double> values;
            do {
                const std::optional<double> v = ParseSignedNumber("in the default vector");
                if (!v) {
                    return false;
                }
                values.push_back(*v);
            } while (Accept(TokenKind::kComma));
            if (!Expect(TokenKind::kRParen, "')'", "after the default vector")) {
                return false;
            }
            const size_t min = prop.type == PropertyType::kColor ? 3 : 2;
            if (values.size() < min || values.size() > 4) {
                Error(DiagCode::kBadPropertyDefault, RangeFrom(first),
                      "expected " + std::to_string(min) + " to 4 components in the default of " +
                          what + ", found " + std::to_string(values.size()));
                return false;
            }
            // Missing components: alpha 1 for colours, 0 for vectors.
            while (values.size() < 4) {
                values.push_back(prop.type == PropertyType::kColor && values.size() == 3 ? 1.0
                                                                                         : 0.0);
            }
            prop.default_value = std::move(values);
            break;
        }
        case PropertyType::kFloat:
        case PropertyType::kInt:
        case PropertyType::kInteger:
        case PropertyType::kRange: {
            const Token& t = Peek(At(TokenKind::kMinus) || At(TokenKind::kPlus) ? 1 : 0);
            if (t.kind != TokenKind::kNumber) {
                Error(DiagCode::kBadPropertyDefault, t.range,
                      "expected a number as the default of " + what + ", found " + Describe(t));
                return false;
            }
            const std::optional<double> v = ParseSignedNumber("as the default");
            if (!v) {
                return false;
            }
            prop.default_value = {*v};
            break;
        }
        default: {  // textures
            if (!At(TokenKind::kString)) {
                Error(DiagCode::kBadPropertyDefault, first.range,
                      "expected a texture default such as \"white\" {} for " + what + ", found " +
                          Describe(first));
                return false;
            }
            prop.default_texture = std::string(Next().text);
            if (At(TokenKind::kLBrace)) {
                SkipBalanced();  // legacy texture options ({ TexGen ... }) carry no meaning here
            }
            break;
        }
    }
    prop.default_range = RangeFrom(first);
    return true;
}

}  // namespace kiln::shaderlab
