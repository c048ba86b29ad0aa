// The -W options (kiln/diagnostic.h, WarningPolicy): which warnings a DiagnosticList drops, keeps
// or turns into errors, by code or by group.
#include "kiln/diagnostic.h"

#include "kiln/base/text.h"

namespace kiln {
namespace {

constexpr std::string_view kErrorPrefix = "error=";

// The codes `name` stands for ("K7001", or a group's name); empty when it names nothing.
std::vector<uint16_t> CodesNamed(std::string_view name) {
    std::vector<uint16_t> out;
    for (const WarningGroup& g : WarningGroups()) {
        if (g.name != name)
            continue;
        for (DiagCode c : AllDiagCodes()) {
            const auto n = static_cast<uint16_t>(c);
            for (const auto& [first, last] : g.ranges) {
                if (n >= first && n <= last) {
                    out.push_back(n);
                    break;
                }
            }
        }
        return out;
    }
    for (DiagCode c : AllDiagCodes()) {
        if (FormatDiagCode(c) == base::ToUpper(name))
            out.push_back(static_cast<uint16_t>(c));
    }
    return out;
}

std::vector<std::string> ValidNames() {
    std::vector<std::string> names;
    for (const WarningGroup& g : WarningGroups())
        names.emplace_back(g.name);
    for (DiagCode c : AllDiagCodes())
        names.push_back(FormatDiagCode(c));
    return names;
}

Error BadOption(std::string_view option, std::string_view what) {
    return Error{DiagCode::kBadCommandLine, "unknown warning option '" + std::string(option) +
                                                "': expected " + std::string(what)};
}

}  // namespace

const std::vector<DiagCode>& AllDiagCodes() {
    static const std::vector<DiagCode> codes = {
#define KILN_DIAG_CODE(name, number) DiagCode::name,
#include "kiln/diag_code_list.h"
#undef KILN_DIAG_CODE
    };
    return codes;
}

const std::vector<WarningGroup>& WarningGroups() {
    static const std::vector<WarningGroup> groups = {
        {"all", {{0, 9999}}, "every warning"},
        {"runtime", {{10, 17}, {24, 24}}, "what a render replaced or skipped (K0010-K0017, K0024)"},
        {"shaderlab", {{1000, 3999}}, "the ShaderLab lexer, parser and checks (K1xxx-K3xxx)"},
        {"variants", {{4000, 4999}}, "pragmas and variants (K4xxx)"},
        {"hlsl", {{5001, 5003}, {5009, 5014}}, "the HLSL compile and SPIR-V (K5001-K5003, ...)"},
        {"interface",
         {{5004, 5008}},
         "stage interfaces, block layouts and properties (K5004-K5008)"},
        {"material", {{6000, 6999}}, "material instances (K6xxx)"},
        {"lint", {{7000, 7999}}, "every kiln lint check (K7xxx)"},
        {"lint-keywords",
         {{7001, 7010}},
         "what keywords cost and how they are declared (K7001-K7010)"},
        {"lint-state", {{7011, 7011}}, "render state the pass contradicts (K7011)"},
    };
    return groups;
}

Status WarningPolicy::Add(std::string_view option) {
    std::string_view rest = option;
    if (rest.substr(0, 2) != "-W")
        return BadOption(option, "-W followed by a code or a group");
    rest.remove_prefix(2);
    const bool negated = rest.substr(0, 3) == "no-";
    if (negated)
        rest.remove_prefix(3);
    if (rest == "error") {
        werror_ = !negated;  // -Werror, -Wno-error
        return {};
    }
    const bool error = rest.substr(0, kErrorPrefix.size()) == kErrorPrefix;
    if (error)
        rest.remove_prefix(kErrorPrefix.size());
    const std::vector<uint16_t> codes = CodesNamed(rest);
    if (codes.empty()) {
        const std::string near = base::ClosestName(rest, ValidNames());
        return BadOption(option,
                         "a code (K7001) or a group (all, lint, interface, ...)" +
                             (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
    }
    for (uint16_t c : codes) {
        Entry& e = codes_[c];
        if (error) {
            e.error = negated ? 0 : 1;
            if (!negated)
                e.shown = 1;  // -Werror=X also shows X
        } else {
            e.shown = negated ? 0 : 1;
        }
    }
    return {};
}

WarningPolicy::Action WarningPolicy::For(DiagCode code) const {
    const auto it = codes_.find(static_cast<uint16_t>(code));
    const Entry e = it == codes_.end() ? Entry{} : it->second;
    if (e.shown == 0)
        return Action::kIgnore;
    return e.error == 1 || (e.error == -1 && werror_) ? Action::kError : Action::kWarn;
}

}  // namespace kiln
