// EnabledKeywords: a material's keywords, with those its keyword-switch properties enable.
#include "kiln/material/material.h"

#include <algorithm>

#include "kiln/pack/property_keywords.h"
#include "material/keywords.h"

namespace kiln::material {

std::vector<PropertySwitch> PropertySwitches(const Material& m,
                                             const pack::Pack& pack,
                                             uint32_t shader) {
    std::vector<PropertySwitch> out;
    const pack::ShaderRec s = pack.Shader(shader).value();
    for (uint32_t i = s.first_property; i < s.first_property + s.property_count; ++i) {
        const auto p = pack.Get<pack::PropertyRec>(pack::SectionTag::kProperties, i).value();
        for (uint32_t a = p.first_attribute; a < p.first_attribute + p.attribute_count; ++a) {
            const auto attr =
                pack.Get<pack::AttributeRec>(pack::SectionTag::kAttributes, a).value();
            PropertySwitch sw;
            sw.property = std::string(pack.String(p.name));
            sw.driven =
                pack::KeywordsDrivenBy(sw.property, pack.String(attr.name), pack.String(attr.args));
            if (sw.driven.kind == pack::PropertyKeywords::Kind::kNone)
                continue;
            sw.value = p.default_value[0];
            for (const PropertyValue& v : m.properties) {
                if (v.name == sw.property && v.kind == PropertyValue::Kind::kNumbers &&
                    !v.numbers.empty()) {
                    sw.value = v.numbers[0];
                    sw.set_by_material = true;
                    sw.pos = v.pos;
                }
            }
            sw.enabled = pack::KeywordEnabledBy(sw.driven, sw.value);
            out.push_back(std::move(sw));
        }
    }
    return out;
}

std::vector<std::string> EnabledKeywords(const Material& m,
                                         const pack::Pack& pack,
                                         uint32_t shader) {
    std::vector<std::string> out;
    for (const Keyword& k : m.keywords)
        out.push_back(k.name);
    for (const PropertySwitch& sw : PropertySwitches(m, pack, shader)) {
        if (!sw.enabled.empty())
            out.push_back(sw.enabled);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace kiln::material
