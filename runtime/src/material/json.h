// A small JSON reader that keeps the source position of every value and key, so material files
// get file:line:col diagnostics. Strict RFC 8259 (no comments, no trailing commas), depth and
// size bounded; never throws.
#ifndef KILN_RUNTIME_MATERIAL_JSON_H_
#define KILN_RUNTIME_MATERIAL_JSON_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kiln/material/material.h"

namespace kiln::material {

struct JsonValue {
    enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };
    Kind kind = Kind::kNull;
    TextPos pos;
    bool boolean = false;
    double number = 0;
    std::string string;
    std::vector<JsonValue> items;
    std::vector<std::pair<std::string, TextPos>> keys;  // parallel to items for objects
};

const char* JsonKindName(JsonValue::Kind kind);

inline constexpr size_t kMaxJsonDepth = 64;

struct JsonError {
    TextPos pos;
    std::string message;
};

// Parses `text` into `out`; on failure returns false and sets `error` (position + message).
bool ParseJson(std::string_view text, JsonValue& out, JsonError& error);

}  // namespace kiln::material

#endif  // KILN_RUNTIME_MATERIAL_JSON_H_
