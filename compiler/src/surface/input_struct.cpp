#include "surface/input_struct.h"

#include <algorithm>

#include "hlsl/tokens.h"
#include "shaderlab/program_scan.h"

namespace kiln::surface {
namespace {

using hlsl::Token;

bool IsModifier(std::string_view t) {
    return t == "nointerpolation" || t == "linear" || t == "centroid" || t == "noperspective" ||
           t == "sample" || t == "precise" || t == "const" || t == "uniform";
}

// The struct type of the first parameter of the function `name` (its definition, not a call).
std::optional<std::string> FirstParameterType(const std::vector<Token>& tok,
                                              std::string_view name) {
    for (size_t i = 1; i + 2 < tok.size(); ++i) {
        if (tok[i].text != name || tok[i + 1].text != "(" || !tok[i - 1].ident)
            continue;
        size_t k = i + 2;
        while (k < tok.size() && (tok[k].text == "in" || tok[k].text == "inout"))
            ++k;
        if (k + 1 < tok.size() && tok[k].ident && tok[k + 1].ident)
            return std::string(tok[k].text);
    }
    return std::nullopt;
}

void Classify(InputMember& m) {
    const std::string& n = m.name;
    for (int set = 0; set < 4; ++set) {
        const std::string prefix = set == 0 ? "uv_" : "uv" + std::to_string(set + 1) + "_";
        if (n.rfind(prefix, 0) == 0 && n.size() > prefix.size()) {
            m.kind = InputKind::kTexcoord;
            m.uv_set = set;
            m.texture = n.substr(prefix.size() - 1);  // uv_MainTex reads _MainTex
            return;
        }
    }
    std::string semantic = m.semantic;
    std::transform(semantic.begin(), semantic.end(), semantic.begin(), ::toupper);
    m.kind = n == "viewDir"                                        ? InputKind::kViewDir
             : n == "worldPos"                                     ? InputKind::kWorldPos
             : n == "worldNormal"                                  ? InputKind::kWorldNormal
             : n == "worldRefl"                                    ? InputKind::kWorldRefl
             : n == "screenPos"                                    ? InputKind::kScreenPos
             : semantic.rfind("COLOR", 0) == 0                     ? InputKind::kColor
             : semantic == "VFACE" || semantic == "SV_ISFRONTFACE" ? InputKind::kFacing
                                                                   : InputKind::kCustom;
}

// One member declaration (the tokens between two `;`): `[modifiers] type name [: SEMANTIC]`,
// several names separated by commas.
void ReadDeclaration(const std::vector<Token>& tok, size_t b, size_t e, InputStruct& out) {
    if (b < e && tok[b].text == "INTERNAL_DATA") {
        out.internal_data = true;
        ++b;
    }
    // UNITY_FOG_COORDS(n): the fog coordinate a finalcolor: function applies (the terrain's),
    // which exists only with fog on.
    if (b + 1 < e && tok[b].text == "UNITY_FOG_COORDS" && tok[b + 1].text == "(") {
        InputMember m;
        m.type = "float1";
        m.name = "fogCoord";
        m.semantic = "FOG";
        m.offset = tok[b].begin;
        out.members.push_back(std::move(m));
        const size_t close = hlsl::MatchForward(tok, b + 1);
        b = close == SIZE_MAX ? e : close + 1;
    }
    while (b < e && IsModifier(tok[b].text))
        ++b;
    if (b + 1 >= e || !tok[b].ident)
        return;
    const std::string type(tok[b].text);
    for (size_t k = b + 1; k < e;) {
        if (!tok[k].ident)
            return;
        InputMember m;
        m.type = type;
        m.name = std::string(tok[k].text);
        m.offset = tok[k].begin;
        ++k;
        if (k < e && tok[k].text == "[") {  // an array
            const size_t close = hlsl::MatchForward(tok, k);
            k = close == SIZE_MAX ? e : close + 1;
        }
        if (k + 1 < e && tok[k].text == ":" && tok[k + 1].ident) {
            m.semantic = std::string(tok[k + 1].text);
            k += 2;
        }
        Classify(m);
        out.members.push_back(std::move(m));
        if (k < e && tok[k].text == ",")
            ++k;
        else
            return;
    }
}

std::string Trim(std::string_view s) {
    const size_t b = s.find_first_not_of(" \t");
    const size_t e = s.find_last_not_of(" \t\r");
    return b == std::string_view::npos ? "" : std::string(s.substr(b, e - b + 1));
}

}  // namespace

const char* InputKindName(InputKind kind) {
    switch (kind) {
        case InputKind::kTexcoord:
            return "uv_<texture>";
        case InputKind::kViewDir:
            return "viewDir";
        case InputKind::kWorldPos:
            return "worldPos";
        case InputKind::kWorldNormal:
            return "worldNormal";
        case InputKind::kWorldRefl:
            return "worldRefl";
        case InputKind::kScreenPos:
            return "screenPos";
        case InputKind::kColor:
            return "COLOR";
        case InputKind::kFacing:
            return "VFACE";
        case InputKind::kCustom:
            return "custom";
    }
    return "custom";
}

bool InputStruct::Reads(InputKind kind) const {
    return std::any_of(members.begin(), members.end(),
                       [&](const InputMember& m) { return m.kind == kind; });
}

std::vector<std::string> ConditionsAt(std::string_view text, size_t from, size_t at) {
    std::vector<std::string> open;
    size_t line = from;
    while (line < at) {
        const size_t end = std::min(text.find('\n', line), text.size());
        const std::string l = Trim(text.substr(line, end - line));
        if (!l.empty() && l[0] == '#') {
            const std::string d = Trim(std::string_view(l).substr(1));
            auto word = [&](const char* w) { return d.rfind(w, 0) == 0; };
            if (word("ifdef") || word("ifndef") || word("if")) {
                open.push_back("#" + d);
            } else if (word("elif") && !open.empty()) {
                open.back() = "#if" + d.substr(4);
            } else if (word("else") && !open.empty()) {
                std::string& c = open.back();
                c = c.rfind("#ifdef", 0) == 0    ? "#ifndef" + c.substr(6)
                    : c.rfind("#ifndef", 0) == 0 ? "#ifdef" + c.substr(7)
                                                 : "#if !(" + Trim(c.substr(3)) + ")";
            } else if (word("endif") && !open.empty()) {
                open.pop_back();
            }
        }
        line = end + 1;
    }
    return open;
}

std::string ConditionExpression(const std::vector<std::string>& conditions) {
    std::string out;
    for (const std::string& c : conditions) {
        const std::string e = c.rfind("#ifdef", 0) == 0    ? "defined(" + Trim(c.substr(6)) + ")"
                              : c.rfind("#ifndef", 0) == 0 ? "!defined(" + Trim(c.substr(7)) + ")"
                                                           : "(" + Trim(c.substr(3)) + ")";
        out += (out.empty() ? "" : " && ") + e;
    }
    return out.empty() ? "1" : out;
}

std::optional<InputStruct> FindInputStruct(std::string_view text,
                                           std::string_view surface_function) {
    const std::string blank = shaderlab::BlankComments(text);
    const std::vector<Token> tok = hlsl::Tokenize(blank);
    const std::optional<std::string> type = FirstParameterType(tok, surface_function);
    if (!type)
        return std::nullopt;
    for (size_t i = 0; i + 2 < tok.size(); ++i) {
        if (tok[i].text != "struct" || tok[i + 1].text != *type || tok[i + 2].text != "{")
            continue;
        const size_t close = hlsl::MatchForward(tok, i + 2);
        if (close == SIZE_MAX)
            return std::nullopt;
        InputStruct out;
        out.name = *type;
        out.offset = tok[i + 1].begin;
        size_t b = i + 3;
        for (size_t k = b; k <= close; ++k) {
            if (k == close || tok[k].text == ";") {
                ReadDeclaration(tok, b, k, out);
                b = k + 1;
            }
        }
        for (InputMember& m : out.members)
            m.conditions = ConditionsAt(blank, tok[i + 2].begin, m.offset);
        return out;
    }
    return std::nullopt;
}

}  // namespace kiln::surface
