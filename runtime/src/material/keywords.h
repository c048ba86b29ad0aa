// The keyword switches of a shader's properties as one material sets them (private to
// kiln_material: EnabledKeywords and validation).
#ifndef KILN_MATERIAL_KEYWORDS_H_
#define KILN_MATERIAL_KEYWORDS_H_

#include <string>
#include <vector>

#include "kiln/material/material.h"
#include "kiln/pack/property_keywords.h"

namespace kiln::material {

struct PropertySwitch {
    std::string property;
    pack::PropertyKeywords driven;
    double value = 0;              // the material's, else the property's default
    bool set_by_material = false;
    TextPos pos;                   // of the material's value, when set
    std::string enabled;           // the keyword the value enables, or ""
};

std::vector<PropertySwitch> PropertySwitches(const Material& m,
                                             const pack::Pack& pack,
                                             uint32_t shader);

}  // namespace kiln::material

#endif  // KILN_MATERIAL_KEYWORDS_H_
