#include "kiln/pack/property_keywords.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace kiln::pack {
namespace {

std::string Upper(std::string_view s) {
    std::string out;
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        out += (c == ' ' || c == '\t') ? '_' : char(std::toupper(u));
    }
    return out;
}

std::string Trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
        s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
        s.remove_suffix(1);
    return std::string(s);
}

}  // namespace

PropertyKeywords KeywordsDrivenBy(std::string_view property,
                                  std::string_view attribute,
                                  std::string_view args) {
    PropertyKeywords out;
    const std::string arg = Trim(args);
    if (attribute == "Toggle" || attribute == "ToggleOff") {
        const bool off = attribute == "ToggleOff";
        out.kind = off ? PropertyKeywords::Kind::kToggleOff : PropertyKeywords::Kind::kToggle;
        out.keywords.push_back(arg.empty() ? Upper(property) + (off ? "_OFF" : "_ON") : arg);
    } else if (attribute == "KeywordEnum") {
        out.kind = PropertyKeywords::Kind::kKeywordEnum;
        size_t begin = 0;
        while (begin <= arg.size()) {
            size_t comma = arg.find(',', begin);
            if (comma == std::string::npos)
                comma = arg.size();
            const std::string entry = Trim(std::string_view(arg).substr(begin, comma - begin));
            if (!entry.empty())
                out.keywords.push_back(Upper(property) + "_" + Upper(entry));
            begin = comma + 1;
        }
        if (out.keywords.empty())
            out.kind = PropertyKeywords::Kind::kNone;
    }
    return out;
}

std::string KeywordEnabledBy(const PropertyKeywords& driven, double value) {
    switch (driven.kind) {
        case PropertyKeywords::Kind::kToggle:
            return value != 0 ? driven.keywords[0] : "";
        case PropertyKeywords::Kind::kToggleOff:
            return value == 0 ? driven.keywords[0] : "";
        case PropertyKeywords::Kind::kKeywordEnum: {
            const double last = double(driven.keywords.size() - 1);
            const double index =
                std::isfinite(value) ? std::clamp(std::floor(value), 0.0, last) : 0;
            return driven.keywords[size_t(index)];
        }
        case PropertyKeywords::Kind::kNone:
            break;
    }
    return "";
}

}  // namespace kiln::pack
