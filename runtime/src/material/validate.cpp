// ValidateMaterial: a parsed material against its shader's Properties and keywords in a pack.
#include "kiln/material/material.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "kiln/base/files.h"
#include "material/issue.h"
#include "material/keywords.h"

namespace kiln::material {
namespace {

using pack::PropertyType;

struct State {
    const pack::Pack& pack;
    DiagnosticList& diags;
    const std::string& file;
    bool ok = true;

    void Add(Severity severity,
             DiagCode code,
             TextPos pos,
             std::string message,
             std::string note = "") {
        AddIssue(diags, file, severity, code, pos, std::move(message), std::move(note));
        ok = ok && severity != Severity::kError;
    }
};

std::string Number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

void CheckProperty(State& s,
                   const PropertyValue& v,
                   const pack::PropertyRec& rec,
                   const std::string& material_dir) {
    const auto type = static_cast<PropertyType>(rec.type);
    const std::string what = "property '" + v.name + "' is a " + pack::PropertyTypeName(type);
    const bool texture = v.kind == PropertyValue::Kind::kTexture;
    const size_t n = v.numbers.size();
    if (pack::IsTextureProperty(type)) {
        if (!texture) {
            s.Add(Severity::kError, DiagCode::kMaterialPropertyValueType, v.pos,
                  what + " texture, not a number",
                  "write a path string or {\"path\": ..., \"scale\": [x, y], \"offset\": [x, y]}");
        } else if (!v.texture.empty() && !material_dir.empty()) {
            const std::filesystem::path file = std::filesystem::path(material_dir) / v.texture;
            std::error_code ec;
            if (!std::filesystem::exists(file, ec)) {
                s.Add(Severity::kWarning, DiagCode::kMaterialTextureNotFound, v.pos,
                      "texture '" + v.texture + "' of property '" + v.name +
                          "' not found beside the material");
            } else if (std::string kind = base::NotRegularFileKind(file.string()); !kind.empty()) {
                // The renderer reads regular files only (a FIFO would block it): it binds the
                // default texture, as for a missing file.
                s.Add(Severity::kWarning, DiagCode::kMaterialTextureNotFound, v.pos,
                      "texture '" + v.texture + "' of property '" + v.name + "' is " + kind +
                          ", not a regular file");
            }
        }
        return;
    }
    if (texture) {
        s.Add(Severity::kError, DiagCode::kMaterialPropertyValueType, v.pos,
              what + ", not a texture");
        return;
    }
    switch (type) {
        case PropertyType::kColor:
            if (n < 3)
                s.Add(Severity::kError, DiagCode::kMaterialPropertyValueType, v.pos,
                      what + ": give 3 or 4 numbers (r, g, b[, a])");
            return;
        case PropertyType::kVector:
            if (n < 2)
                s.Add(Severity::kError, DiagCode::kMaterialPropertyValueType, v.pos,
                      what + ": give 2 to 4 numbers");
            return;
        case PropertyType::kInt:
        case PropertyType::kInteger:
            if (n != 1 || std::trunc(v.numbers[0]) != v.numbers[0])
                s.Add(Severity::kError, DiagCode::kMaterialPropertyValueType, v.pos,
                      what + ": give one whole number");
            return;
        case PropertyType::kFloat:
        case PropertyType::kRange:
            if (n != 1) {
                s.Add(Severity::kError, DiagCode::kMaterialPropertyValueType, v.pos,
                      what + ": give one number");
            } else if (type == PropertyType::kRange &&
                       // Range(10, 0.1) is the interval between the two, as in Unity
                       (v.numbers[0] < std::min(rec.range_min, rec.range_max) ||
                        v.numbers[0] > std::max(rec.range_min, rec.range_max))) {
                s.Add(
                    Severity::kError, DiagCode::kMaterialOutOfRange, v.pos,
                    "value " + Number(v.numbers[0]) + " of property '" + v.name +
                        "' is outside its range",
                    "declared Range(" + Number(rec.range_min) + ", " + Number(rec.range_max) + ")");
            }
            return;
        default:
            return;
    }
}

struct KeywordUse {
    uint32_t set;  // global KeywordSetRec index
    bool multi_compile;
};

void CheckKeywords(State& s, const Material& m, const pack::ShaderRec& shader) {
    std::map<std::string, std::vector<KeywordUse>> declared;
    for (uint32_t p = 0; p < shader.pass_count; ++p) {
        const pack::PassRec pass = s.pack.Pass(shader.first_pass + p).value();
        for (uint32_t k = 0; k < pass.keyword_set_count; ++k) {
            const uint32_t set_index = pass.first_keyword_set + k;
            const pack::KeywordSetRec set = s.pack.KeywordSet(set_index).value();
            for (uint32_t w = 0; w < set.keyword_count; ++w) {
                const std::string name(s.pack.Keyword(set.first_keyword + w).value());
                if (!name.empty()) {
                    declared[name].push_back(
                        {set_index, set.kind == uint32_t(pack::KeywordSetKind::kMultiCompile)});
                }
            }
        }
    }
    std::vector<std::string> names;
    for (const auto& [name, uses] : declared)
        names.push_back(name);
    std::map<uint32_t, const Keyword*> set_owner;
    for (const Keyword& k : m.keywords) {
        const auto it = declared.find(k.name);
        if (it == declared.end()) {
            const std::string near = ClosestName(k.name, names);
            s.Add(Severity::kError, DiagCode::kMaterialUnknownKeyword, k.pos,
                  "keyword '" + k.name + "' is not declared by shader '" + m.shader + "'",
                  near.empty() ? "" : "did you mean '" + near + "'");
            continue;
        }
        bool all_multi_compile = true;
        for (const KeywordUse& use : it->second) {
            all_multi_compile = all_multi_compile && use.multi_compile;
            const auto [owner, inserted] = set_owner.emplace(use.set, &k);
            if (!inserted && owner->second->name != k.name) {
                s.Add(Severity::kError, DiagCode::kMaterialConflictingKeywords, k.pos,
                      "keywords '" + owner->second->name + "' and '" + k.name +
                          "' are alternatives of one keyword set",
                      "enable at most one keyword of each set");
            }
        }
        if (all_multi_compile) {
            s.Add(Severity::kWarning, DiagCode::kMaterialEngineKeyword, k.pos,
                  "keyword '" + k.name +
                      "' is a multi_compile keyword the renderer chooses per draw; the material "
                      "setting is ignored");
        }
    }
}

// A listed keyword that a keyword-switch property's value turns off (or, for a KeywordEnum, that
// is not the entry its value selects) is still enabled: the material contradicts itself.
void CheckSwitches(State& s, const Material& m, uint32_t shader) {
    for (const PropertySwitch& sw : PropertySwitches(m, s.pack, shader)) {
        for (const Keyword& k : m.keywords) {
            const auto& driven = sw.driven.keywords;
            if (k.name == sw.enabled ||
                std::find(driven.begin(), driven.end(), k.name) == driven.end())
                continue;
            s.Add(Severity::kWarning, DiagCode::kMaterialKeywordContradictsProperty, k.pos,
                  "keyword '" + k.name + "' is listed, but property '" + sw.property +
                      "' = " + Number(sw.value) +
                      (sw.enabled.empty() ? " turns it off" : " selects '" + sw.enabled + "'") +
                      (sw.set_by_material ? "" : " (its default)"),
                  "the property drives the keyword as in Unity: set the property, not the keyword");
        }
    }
}

}  // namespace

bool ValidateMaterial(const Material& m,
                      const pack::Pack& pack,
                      const std::string& material_dir,
                      DiagnosticList& diags) {
    State s{pack, diags, m.file};
    const auto shader_index = pack.FindShader(m.shader);
    if (!shader_index) {
        std::vector<std::string> names;
        for (uint32_t i = 0; i < pack.Count(pack::SectionTag::kShaders); ++i)
            names.emplace_back(pack.String(pack.Shader(i).value().name));
        const std::string near = ClosestName(m.shader, names);
        s.Add(Severity::kError, DiagCode::kMaterialUnknownShader, m.shader_pos,
              "no shader '" + m.shader + "' in the pack",
              near.empty() ? "" : "did you mean '" + near + "'");
        return false;
    }
    const pack::ShaderRec shader = pack.Shader(*shader_index).value();
    std::map<std::string, pack::PropertyRec> props;
    std::vector<std::string> names;
    for (uint32_t i = 0; i < shader.property_count; ++i) {
        const auto rec =
            pack.Get<pack::PropertyRec>(pack::SectionTag::kProperties, shader.first_property + i)
                .value();
        names.emplace_back(pack.String(rec.name));
        props.emplace(names.back(), rec);
    }
    for (const PropertyValue& v : m.properties) {
        const auto it = props.find(v.name);
        if (it == props.end()) {
            const std::string near = ClosestName(v.name, names);
            s.Add(Severity::kError, DiagCode::kMaterialUnknownProperty, v.pos,
                  "shader '" + m.shader + "' has no property '" + v.name + "'",
                  near.empty() ? "" : "did you mean '" + near + "'");
            continue;
        }
        CheckProperty(s, v, it->second, material_dir);
    }
    CheckKeywords(s, m, shader);
    CheckSwitches(s, m, *shader_index);
    return s.ok;
}

}  // namespace kiln::material
