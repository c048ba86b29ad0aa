#include "kiln/material/material.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "kiln/base/text.h"
#include "kiln/pack/names.h"
#include "kiln/pack/render_state.h"
#include "material/issue.h"
#include "material/json.h"

namespace kiln::material {
namespace {

using Kind = JsonValue::Kind;

struct State {
    DiagnosticList* diags;
    const std::string* file;
    bool ok = true;

    void Error(DiagCode code, TextPos pos, std::string message, std::string note = "") {
        AddIssue(*diags, *file, Severity::kError, code, pos, std::move(message), std::move(note));
        ok = false;
    }
};

using base::ToLower;

std::string Join(const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& n : names)
        s += (s.empty() ? "" : ", ") + n;
    return s;
}

bool NumberArray(const JsonValue& v, size_t min, size_t max, std::vector<double>& out) {
    if (v.kind != Kind::kArray || v.items.size() < min || v.items.size() > max)
        return false;
    for (const JsonValue& item : v.items) {
        if (item.kind != Kind::kNumber)
            return false;
        out.push_back(item.number);
    }
    return true;
}

void ParseTexture(State& s, const JsonValue& v, PropertyValue& p) {
    p.kind = PropertyValue::Kind::kTexture;
    if (v.kind == Kind::kString) {
        p.texture = v.string;
        return;
    }
    for (size_t i = 0; i < v.items.size(); ++i) {
        const auto& [key, pos] = v.keys[i];
        const JsonValue& item = v.items[i];
        std::vector<double> pair;
        if (key == "path" && item.kind == Kind::kString) {
            p.texture = item.string;
        } else if ((key == "scale" || key == "offset") && NumberArray(item, 2, 2, pair)) {
            (key == "scale" ? p.scale : p.offset) = {pair[0], pair[1]};
        } else if (key == "path" || key == "scale" || key == "offset") {
            s.Error(DiagCode::kMaterialFieldType, item.pos,
                    "texture field '" + key + "' must be " +
                        (key == "path" ? "a string" : "an array of two numbers"));
        } else {
            s.Error(DiagCode::kMaterialUnknownField, pos, "unknown texture field '" + key + "'",
                    "texture fields are path, scale and offset");
        }
    }
}

void ParseProperties(State& s, const JsonValue& v, Material& m) {
    std::set<std::string> seen;
    for (size_t i = 0; i < v.items.size(); ++i) {
        const auto& [name, pos] = v.keys[i];
        const JsonValue& item = v.items[i];
        if (!seen.insert(name).second) {
            s.Error(DiagCode::kMaterialDuplicate, pos, "property '" + name + "' is set twice");
            continue;
        }
        PropertyValue p;
        p.name = name;
        p.pos = pos;
        if (item.kind == Kind::kNumber) {
            p.numbers = {item.number};
        } else if (item.kind == Kind::kString || item.kind == Kind::kObject) {
            ParseTexture(s, item, p);
        } else if (!NumberArray(item, 1, 4, p.numbers)) {
            s.Error(DiagCode::kMaterialFieldType, item.pos,
                    "property '" + name +
                        "' must be a number, an array of 1 to 4 numbers, or a texture");
            continue;
        }
        m.properties.push_back(std::move(p));
    }
}

void ParseKeywords(State& s, const JsonValue& v, Material& m) {
    std::set<std::string> seen;
    for (const JsonValue& item : v.items) {
        if (item.kind != Kind::kString) {
            s.Error(DiagCode::kMaterialFieldType, item.pos, "a keyword must be a string");
        } else if (!seen.insert(item.string).second) {
            s.Error(DiagCode::kMaterialDuplicate, item.pos,
                    "keyword '" + item.string + "' is listed twice");
        } else {
            m.keywords.push_back({item.string, item.pos});
        }
    }
}

// The value set a .material override of `field` takes (kiln/pack/render_state.h).
std::optional<pack::StateValues> OverrideValues(std::string_view field) {
    if (field == "Cull")
        return pack::StateValues::kCull;
    if (field == "ZWrite")
        return pack::StateValues::kOnOff;
    if (field == "ZTest")
        return pack::StateValues::kCompare;
    if (field == "Blend")
        return pack::StateValues::kBlendFactor;
    return std::nullopt;
}

std::vector<std::string> Names(std::span<const std::string_view> names) {
    return {names.begin(), names.end()};
}

void ParseRenderState(State& s, const JsonValue& v, Material& m) {
    for (size_t i = 0; i < v.items.size(); ++i) {
        const auto& [key, pos] = v.keys[i];
        const JsonValue& item = v.items[i];
        RenderStateOverride o;
        o.pos = pos;
        o.field = key;
        if (key == "ColorMask") {
            const std::optional<uint32_t> mask =
                item.kind == Kind::kString ? pack::ParseColorMask(item.string) : std::nullopt;
            if (!mask) {
                s.Error(DiagCode::kMaterialRenderState, item.pos,
                        "ColorMask must be \"0\" or a combination of R, G, B and A such as "
                        "\"RGB\"");
                continue;
            }
            o.values = {pack::ColorMaskName(*mask)};
            m.render_state.push_back(std::move(o));
            continue;
        }
        const std::optional<pack::StateValues> set = OverrideValues(key);
        if (!set) {
            const std::vector<std::string> fields = Names(pack::OverridableStateFields());
            const std::string near = ClosestName(key, fields);
            s.Error(DiagCode::kMaterialRenderState, pos, "unknown render-state field '" + key + "'",
                    near.empty() ? "overridable: " + Join(fields) : "did you mean '" + near + "'");
            continue;
        }
        std::vector<const JsonValue*> values;
        if (item.kind == Kind::kString) {
            values = {&item};
        } else if (key == "Blend" && item.kind == Kind::kArray &&
                   (item.items.size() == 2 || item.items.size() == 4)) {
            for (const JsonValue& f : item.items)
                values.push_back(&f);
        } else {
            s.Error(DiagCode::kMaterialRenderState, item.pos,
                    key == "Blend" ? "Blend must be \"Off\" or an array of 2 or 4 blend factors"
                                   : key + " must be a string");
            continue;
        }
        if (key == "Blend" && values.size() == 1 && ToLower(item.string) == "off") {
            o.values = {"Off"};
            m.render_state.push_back(std::move(o));
            continue;
        }
        const std::span<const std::string_view> names = pack::StateValueNames(*set);
        for (const JsonValue* f : values) {
            const std::optional<uint32_t> value =
                f->kind == Kind::kString ? pack::ParseStateValue(*set, f->string) : std::nullopt;
            if (!value) {
                const std::string near =
                    f->kind == Kind::kString ? ClosestName(f->string, Names(names)) : "";
                s.Error(DiagCode::kMaterialRenderState, f->pos,
                        "invalid " + key + " value" +
                            (f->kind == Kind::kString ? " '" + f->string + "'" : ""),
                        near.empty() ? "allowed: " + Join(Names(names)) +
                                           (key == "Blend" ? ", or \"Off\"" : "")
                                     : "did you mean '" + near + "'");
            }
            o.values.push_back(value ? std::string(names[*value]) : std::string());
        }
        if (key == "Blend" && values.size() == 1) {
            s.Error(DiagCode::kMaterialRenderState, item.pos,
                    "Blend needs a source and a destination factor, e.g. [\"One\", \"One\"]");
        }
        m.render_state.push_back(std::move(o));
    }
}

}  // namespace

bool ParseMaterial(std::string_view text,
                   const std::string& file,
                   Material& out,
                   DiagnosticList& diags) {
    State s{&diags, &file};
    out.file = file;
    JsonValue root;
    JsonError error;
    if (!ParseJson(text, root, error)) {
        AddIssue(diags, file, Severity::kError, DiagCode::kMaterialJsonSyntax, error.pos,
                 error.message);
        return false;
    }
    if (root.kind != Kind::kObject) {
        s.Error(DiagCode::kMaterialFieldType, root.pos,
                std::string("a material must be a JSON object, not ") + JsonKindName(root.kind));
        return false;
    }
    static const std::map<std::string, Kind> kFields = {
        {"kiln_material", Kind::kNumber}, {"shader", Kind::kString},
        {"description", Kind::kString},   {"properties", Kind::kObject},
        {"keywords", Kind::kArray},       {"render_state", Kind::kObject}};
    std::set<std::string> seen;
    for (size_t i = 0; i < root.items.size(); ++i) {
        const auto& [key, pos] = root.keys[i];
        const JsonValue& item = root.items[i];
        const auto field = kFields.find(key);
        if (field == kFields.end()) {
            std::vector<std::string> names;
            for (const auto& [name, kind] : kFields)
                names.push_back(name);
            const std::string near = ClosestName(key, names);
            s.Error(DiagCode::kMaterialUnknownField, pos, "unknown material field '" + key + "'",
                    near.empty() ? "fields: " + Join(names) : "did you mean '" + near + "'");
            continue;
        }
        if (!seen.insert(key).second) {
            s.Error(DiagCode::kMaterialDuplicate, pos, "field '" + key + "' appears twice");
            continue;
        }
        if (item.kind != field->second) {
            s.Error(DiagCode::kMaterialFieldType, item.pos,
                    "'" + key + "' must be " + JsonKindName(field->second) + ", not " +
                        JsonKindName(item.kind));
            continue;
        }
        if (key == "kiln_material") {
            // only convert what fits an int (a huge double -> int is undefined behaviour)
            out.version = std::abs(item.number) < 1e6 ? static_cast<int>(item.number) : -1;
            if (item.number != kFormatVersion) {
                s.Error(DiagCode::kMaterialUnsupportedVersion, item.pos,
                        "unsupported material format version", "this build reads version 1");
            }
        } else if (key == "shader") {
            out.shader = item.string;
            out.shader_pos = item.pos;
        } else if (key == "properties") {
            ParseProperties(s, item, out);
        } else if (key == "keywords") {
            ParseKeywords(s, item, out);
        } else if (key == "render_state") {
            ParseRenderState(s, item, out);
        }
    }
    if (!seen.count("shader"))
        s.Error(DiagCode::kMaterialMissingField, root.pos, "material has no \"shader\" field");
    return s.ok;
}

}  // namespace kiln::material
