// Keywords driven by material property values, as Unity's property drawers do: [Toggle],
// [Toggle(KW)], [ToggleOff], [ToggleOff(KW)] and [KeywordEnum(A, B, ...)]. The one definition used
// by the compiler (which properties are keyword switches, the shader_feature combinations a
// material needs), material validation and the runtime (the keywords a material enables).
#ifndef KILN_PACK_PROPERTY_KEYWORDS_H_
#define KILN_PACK_PROPERTY_KEYWORDS_H_

#include <string>
#include <string_view>
#include <vector>

namespace kiln::pack {

struct PropertyKeywords {
    enum class Kind { kNone, kToggle, kToggleOff, kKeywordEnum };
    Kind kind = Kind::kNone;
    // Toggle/ToggleOff: the one keyword; KeywordEnum: one per entry, in order.
    std::vector<std::string> keywords;
};

// What attribute `attribute` with raw arguments `args` (the text between its parentheses) on
// property `property` drives. Unity's names: [Toggle] on _Rim drives _RIM_ON, [ToggleOff] _RIM_OFF,
// [KeywordEnum(Low, High Quality)] on _Mode drives _MODE_LOW and _MODE_HIGH_QUALITY.
PropertyKeywords KeywordsDrivenBy(std::string_view property,
                                  std::string_view attribute,
                                  std::string_view args);

// The keyword `value` enables ("" for none): Toggle when value != 0, ToggleOff when value == 0,
// KeywordEnum entry int(value) clamped to the entries.
std::string KeywordEnabledBy(const PropertyKeywords& driven, double value);

}  // namespace kiln::pack

#endif  // KILN_PACK_PROPERTY_KEYWORDS_H_
