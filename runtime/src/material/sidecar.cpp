#include "kiln/material/sidecar.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <string>

#include "kiln/base/files.h"
#include "kiln/material/material.h"
#include "material/json.h"

namespace kiln::material {
namespace {

using Kind = JsonValue::Kind;

Error At(const std::string& path, TextPos pos, const std::string& message) {
    return Error{DiagCode::kBadScene, path + ":" + std::to_string(pos.line) + ":" +
                                          std::to_string(pos.column) + ": " + message};
}

// Three numbers, linear RGB.
bool ReadColour(const JsonValue& value, std::array<float, 3>& out) {
    if (value.kind != Kind::kArray || value.items.size() != 3) {
        return false;
    }
    for (size_t c = 0; c < 3; ++c) {
        if (value.items[c].kind != Kind::kNumber) {
            return false;
        }
        out[c] = float(value.items[c].number);
    }
    return true;
}

}  // namespace

Result<MaterialSidecar> ReadMaterialSidecar(const std::string& path) {
    Result<std::string> text = base::ReadRegularFile(path, kMaxFileBytes);
    if (!text) {
        return text.error();
    }
    JsonValue doc;
    JsonError error;
    if (!ParseJson(text.value(), doc, error)) {
        return At(path, error.pos, error.message);
    }
    if (doc.kind != Kind::kObject) {
        return At(path, doc.pos, "a material sidecar must be a JSON object");
    }
    MaterialSidecar out;
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    for (size_t i = 0; i < doc.items.size(); ++i) {
        const auto& [key, key_pos] = doc.keys[i];
        const JsonValue& value = doc.items[i];
        if (key == "kiln_materials") {
            if (value.kind != Kind::kNumber || value.number != 1) {
                return At(path, value.pos, "kiln_materials must be 1");
            }
        } else if (key == "materials") {
            if (value.kind != Kind::kObject) {
                return At(path, value.pos,
                          "'materials' must map glTF material names to .material files");
            }
            for (size_t m = 0; m < value.items.size(); ++m) {
                const std::string& name = value.keys[m].first;
                if (value.items[m].kind != Kind::kString) {
                    return At(path, value.items[m].pos,
                              "material '" + name + "' must name a .material file");
                }
                out.materials[name] = (dir / value.items[m].string).lexically_normal().string();
            }
        } else if (key == "ambient") {
            if (value.kind == Kind::kObject) {
                out.trilight = true;
                const std::pair<const char*, std::array<float, 3>*> slots[] = {
                    {"sky", &out.ambient}, {"equator", &out.equator}, {"ground", &out.ground}};
                for (const auto& [name, slot] : slots) {
                    const auto it =
                        std::find_if(value.keys.begin(), value.keys.end(),
                                     [&, n = name](const auto& k) { return k.first == n; });
                    if (it == value.keys.end()) {
                        return At(path, value.pos,
                                  std::string("a gradient 'ambient' needs '") + name +
                                      "' (sky, equator and ground, each three numbers)");
                    }
                    const JsonValue& colour = value.items[size_t(it - value.keys.begin())];
                    if (!ReadColour(colour, *slot)) {
                        return At(path, colour.pos,
                                  std::string("'") + name + "' must be three numbers (linear RGB)");
                    }
                }
                if (value.keys.size() != 3) {
                    return At(path, value.pos,
                              "a gradient 'ambient' has exactly sky, equator and ground");
                }
            } else if (!ReadColour(value, out.ambient)) {
                return At(path, value.pos,
                          "'ambient' must be three numbers (linear RGB) or {\"sky\", "
                          "\"equator\", \"ground\"} of three numbers each");
            }
            out.has_ambient = true;
        } else if (key == "lights") {
            if (value.kind != Kind::kObject) {
                return At(path, value.pos,
                          "'lights' must map light names to auto, important or not-important");
            }
            for (size_t l = 0; l < value.items.size(); ++l) {
                const JsonValue& mode = value.items[l];
                const std::string& name = value.keys[l].first;
                if (mode.kind != Kind::kString ||
                    (mode.string != "auto" && mode.string != "important" &&
                     mode.string != "not-important")) {
                    return At(path, mode.pos,
                              "light '" + name + "' must be auto, important or not-important");
                }
                out.light_modes[name] = {mode.string, std::to_string(mode.pos.line) + ":" +
                                                          std::to_string(mode.pos.column)};
            }
        } else if (key != "description") {
            return At(path, key_pos,
                      "unknown field '" + key +
                          "' (expected kiln_materials, materials, ambient, lights, description)");
        }
    }
    return out;
}

}  // namespace kiln::material
