#include "material/json.h"

#include <cmath>
#include <cstdlib>

namespace kiln::material {
namespace {

struct State {
    std::string_view text;
    size_t at = 0;
    uint32_t line = 1;
    size_t line_start = 0;
    JsonError* error = nullptr;

    TextPos Pos() const {
        return TextPos{static_cast<uint32_t>(at), line, static_cast<uint32_t>(at - line_start + 1)};
    }
    bool Fail(const std::string& message) {
        error->pos = Pos();
        error->message = message;
        return false;
    }
    bool End() const { return at >= text.size(); }
    char Peek() const { return End() ? '\0' : text[at]; }
    void SkipSpace() {
        while (!End()) {
            const char c = text[at];
            if (c == '\n') {
                ++line;
                line_start = at + 1;
            } else if (c != ' ' && c != '\t' && c != '\r') {
                return;
            }
            ++at;
        }
    }
    std::string Describe() const {
        if (End())
            return "end of file";
        const char c = text[at];
        if (c >= 0x20 && c < 0x7f)
            return std::string("'") + c + "'";
        return "a control or non-ASCII byte";
    }
};

bool ParseValue(State& s, JsonValue& out, size_t depth);

bool ParseString(State& s, std::string& out) {
    ++s.at;  // opening quote
    while (true) {
        if (s.End())
            return s.Fail("unterminated string");
        const unsigned char c = static_cast<unsigned char>(s.text[s.at]);
        if (c == '"') {
            ++s.at;
            return true;
        }
        if (c < 0x20)
            return s.Fail("control character in string; escape it");
        if (c != '\\') {
            out += static_cast<char>(c);
            ++s.at;
            continue;
        }
        if (++s.at >= s.text.size())
            return s.Fail("unterminated string");
        const char e = s.text[s.at];
        static const std::string_view kSimple = "\"\\/bfnrt", kValue = "\"\\/\b\f\n\r\t";
        if (const size_t k = kSimple.find(e); k != std::string_view::npos) {
            out += kValue[k];
            ++s.at;
            continue;
        }
        if (e != 'u')
            return s.Fail(std::string("unknown escape '\\") + e + "' in string");
        if (s.at + 4 >= s.text.size())
            return s.Fail("truncated \\u escape");
        uint32_t cp = 0;
        for (size_t i = 1; i <= 4; ++i) {
            const char h = s.text[s.at + i];
            const int v = (h >= '0' && h <= '9')   ? h - '0'
                          : (h >= 'a' && h <= 'f') ? h - 'a' + 10
                          : (h >= 'A' && h <= 'F') ? h - 'A' + 10
                                                   : -1;
            if (v < 0)
                return s.Fail("expected 4 hex digits after \\u");
            cp = cp * 16 + static_cast<uint32_t>(v);
        }
        s.at += 5;
        if (cp >= 0xD800 && cp <= 0xDFFF)
            cp = 0xFFFD;  // lone or paired surrogates: names in materials are ASCII anyway
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }
}

bool ParseNumber(State& s, JsonValue& out) {
    const size_t begin = s.at;
    auto digits = [&] {
        const size_t from = s.at;
        while (!s.End() && s.Peek() >= '0' && s.Peek() <= '9')
            ++s.at;
        return s.at > from;
    };
    if (s.Peek() == '-')
        ++s.at;
    if (s.Peek() == '0') {
        ++s.at;
    } else if (!digits()) {
        return s.Fail("expected a digit");
    }
    if (s.Peek() == '.') {
        ++s.at;
        if (!digits())
            return s.Fail("expected a digit after '.'");
    }
    if (s.Peek() == 'e' || s.Peek() == 'E') {
        ++s.at;
        if (s.Peek() == '+' || s.Peek() == '-')
            ++s.at;
        if (!digits())
            return s.Fail("expected a digit in the exponent");
    }
    const std::string literal(s.text.substr(begin, s.at - begin));
    out.kind = JsonValue::Kind::kNumber;
    out.number = std::strtod(literal.c_str(), nullptr);
    if (!std::isfinite(out.number)) {
        s.at = begin;
        return s.Fail("number out of range");
    }
    return true;
}

bool ParseContainer(State& s, JsonValue& out, size_t depth) {
    const bool object = s.Peek() == '{';
    const char close = object ? '}' : ']';
    out.kind = object ? JsonValue::Kind::kObject : JsonValue::Kind::kArray;
    if (depth >= kMaxJsonDepth)
        return s.Fail("nesting deeper than 64 levels");
    ++s.at;
    s.SkipSpace();
    if (s.Peek() == close) {
        ++s.at;
        return true;
    }
    while (true) {
        if (object) {
            if (s.Peek() != '"')
                return s.Fail("expected a string key, found " + s.Describe());
            const TextPos key_pos = s.Pos();
            std::string key;
            if (!ParseString(s, key))
                return false;
            s.SkipSpace();
            if (s.Peek() != ':')
                return s.Fail("expected ':' after the key, found " + s.Describe());
            ++s.at;
            out.keys.emplace_back(std::move(key), key_pos);
        }
        out.items.emplace_back();
        if (!ParseValue(s, out.items.back(), depth + 1))
            return false;
        s.SkipSpace();
        if (s.Peek() == ',') {
            ++s.at;
            s.SkipSpace();
            if (s.Peek() == close)
                return s.Fail("trailing comma before " + s.Describe());
            continue;
        }
        if (s.Peek() == close) {
            ++s.at;
            return true;
        }
        return s.Fail(std::string("expected ',' or '") + close + "', found " + s.Describe());
    }
}

bool ParseLiteral(State& s, JsonValue& out, std::string_view word) {
    if (s.text.substr(s.at, word.size()) != word)
        return s.Fail("expected a value, found " + s.Describe());
    s.at += word.size();
    out.kind = word == "null" ? JsonValue::Kind::kNull : JsonValue::Kind::kBool;
    out.boolean = word == "true";
    return true;
}

bool ParseValue(State& s, JsonValue& out, size_t depth) {
    s.SkipSpace();
    out.pos = s.Pos();
    switch (s.Peek()) {
        case '{':
        case '[':
            return ParseContainer(s, out, depth);
        case '"':
            out.kind = JsonValue::Kind::kString;
            return ParseString(s, out.string);
        case 't':
            return ParseLiteral(s, out, "true");
        case 'f':
            return ParseLiteral(s, out, "false");
        case 'n':
            return ParseLiteral(s, out, "null");
        default:
            if (s.Peek() == '-' || (s.Peek() >= '0' && s.Peek() <= '9'))
                return ParseNumber(s, out);
            return s.Fail("expected a value, found " + s.Describe());
    }
}

}  // namespace

const char* JsonKindName(JsonValue::Kind kind) {
    switch (kind) {
        case JsonValue::Kind::kNull:
            return "null";
        case JsonValue::Kind::kBool:
            return "a boolean";
        case JsonValue::Kind::kNumber:
            return "a number";
        case JsonValue::Kind::kString:
            return "a string";
        case JsonValue::Kind::kArray:
            return "an array";
        case JsonValue::Kind::kObject:
            return "an object";
    }
    return "a value";
}

bool ParseJson(std::string_view text, JsonValue& out, JsonError& error) {
    State s;
    s.text = text;
    s.error = &error;
    if (!ParseValue(s, out, 0))
        return false;
    s.SkipSpace();
    if (!s.End())
        return s.Fail("unexpected " + s.Describe() + " after the JSON value");
    return true;
}

}  // namespace kiln::material
