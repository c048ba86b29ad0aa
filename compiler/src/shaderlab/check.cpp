// Semantic checks over a parsed Shader (see Check() in kiln/shaderlab/parse.h).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>

#include "kiln/pack/engine_names.h"
#include "kiln/pack/names.h"
#include "kiln/shaderlab/parse.h"
#include "parser.h"

namespace kiln::shaderlab {
namespace {

std::string Num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// The range of a program block's opening marker alone (the block itself may be long).
SourceRange MarkerRange(const ProgramBlock& block) {
    const auto len = static_cast<uint32_t>(std::strlen(ProgramKindName(block.kind)));
    SourceLoc end = block.range.begin;
    end.offset += len;
    end.column += len;
    return {block.range.begin, end};
}

const Pragma* FindPragma(const ProgramBlock& block, std::string_view name) {
    for (const Pragma& p : block.pragmas) {
        if (p.name == name) {
            return &p;
        }
    }
    return nullptr;
}

struct State {
    const Shader& shader;
    const std::string& file;
    DiagnosticList& diags;
    std::map<std::string, const Property*, std::less<>> props;
    // Enclosing levels (Shader, Category) whose CGINCLUDE declares `#pragma surface`: their
    // SubShader-level CGPROGRAMs are that surface shader's programs, not misplaced ones.
    int surface_includes = 0;

    Diagnostic& Error(DiagCode code, SourceRange range, std::string message) {
        return diags.Error(code, file, range, std::move(message));
    }
    Diagnostic& Warning(DiagCode code, SourceRange range, std::string message) {
        return diags.Warning(code, file, range, std::move(message));
    }

    void CheckProperties();
    void CheckValue(const StateValue& value);
    void CheckState(const RenderState& state);
    // Returns whether an include block of `programs` declares `#pragma surface`.
    bool CheckPrograms(const std::vector<ProgramBlock>& programs, bool in_pass);
    void CheckEntries(const std::vector<SubShaderEntry>& entries);
    void CheckSubShader(const SubShader& sub);
    void CheckLightMode(const std::vector<Tag>& tags);
};

void State::CheckProperties() {
    for (const Property& p : shader.properties) {
        auto [it, inserted] = props.emplace(p.name, &p);
        if (!inserted) {
            Diagnostic& d = Error(DiagCode::kDuplicateProperty, p.name_range,
                                  "duplicate property '" + p.name + "'");
            d.notes.push_back({file, it->second->name_range, "first declared here"});
        }
        if (p.type == PropertyType::kRange) {
            // Unity accepts a Range whose minimum is above its maximum (its slider runs from
            // one to the other): a warning, and the range is the interval between the two.
            const double lo = std::min(p.range_min, p.range_max);
            const double hi = std::max(p.range_min, p.range_max);
            if (p.range_min > p.range_max) {
                Warning(DiagCode::kBadRange, p.type_range,
                        "range minimum " + Num(p.range_min) + " is greater than its maximum " +
                            Num(p.range_max) + "; Unity accepts it, and values between the two " +
                            "are in range");
            }
            if (!p.default_value.empty() && (p.default_value[0] < lo || p.default_value[0] > hi)) {
                Warning(DiagCode::kDefaultOutOfRange, p.default_range,
                        "default " + Num(p.default_value[0]) + " of '" + p.name +
                            "' is outside its Range(" + Num(p.range_min) + ", " + Num(p.range_max) +
                            ")");
            }
        }
        if (IsTextureType(p.type)) {
            if (!p.default_texture.empty() && !pack::FindDefaultTexture(p.default_texture)) {
                Warning(DiagCode::kUnknownTextureDefault, p.default_range,
                        "unknown default texture \"" + p.default_texture + "\" for '" + p.name +
                            "'; expected white, black, gray, bump, red or \"\"; gray is used");
            }
        }
    }
}

void State::CheckValue(const StateValue& value) {
    if (value.kind != StateValue::Kind::kPropertyRef) {
        return;
    }
    auto it = props.find(value.text);
    if (it == props.end()) {
        if (shader.properties_incomplete) {
            return;  // the declaration may be the one that failed to parse
        }
        // Unity reads an undeclared name from the global shader properties (unity_GUIZTestMode
        // in its UI shaders): a warning, with the closest declared name in case of a typo.
        std::vector<std::string> names;
        for (const auto& [name, prop] : props) {
            names.push_back(name);
        }
        const std::string near = pack::ClosestName(value.text, names);
        Diagnostic& d =
            Warning(DiagCode::kUndeclaredProperty, value.range,
                    "'" + value.text +
                        "' is not declared in Properties; as in Unity its value is a global "
                        "property that the material or the runtime must set" +
                        (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
        if (!near.empty()) {
            d.notes.push_back(
                {file, props.find(near)->second->name_range, "'" + near + "' declared here"});
        } else if (shader.properties_range) {
            d.notes.push_back({file, *shader.properties_range, "properties are declared here"});
        }
        return;
    }
    const PropertyType t = it->second->type;
    if (t != PropertyType::kFloat && t != PropertyType::kInt && t != PropertyType::kInteger &&
        t != PropertyType::kRange) {
        Diagnostic& d = Error(DiagCode::kPropertyRefType, value.range,
                              "property '" + value.text + "' of type " + PropertyTypeName(t) +
                                  " cannot set render state; expected a Float, Int, Integer or "
                                  "Range property");
        d.notes.push_back({file, it->second->range, "declared here"});
    }
}

void State::CheckState(const RenderState& s) {
    for (const auto* simple :
         {&s.cull, &s.ztest, &s.zwrite, &s.zclip, &s.alpha_to_mask, &s.conservative}) {
        if (*simple) {
            CheckValue((*simple)->value);
        }
    }
    if (s.offset) {
        CheckValue(s.offset->factor);
        CheckValue(s.offset->units);
    }
    for (const BlendState& b : s.blend) {
        if (!b.off) {
            CheckValue(b.src);
            CheckValue(b.dst);
        }
        if (b.src_alpha) {
            CheckValue(*b.src_alpha);
            CheckValue(*b.dst_alpha);
        }
    }
    for (const BlendOpState& b : s.blend_op) {
        CheckValue(b.op);
        if (b.op_alpha) {
            CheckValue(*b.op_alpha);
        }
    }
    for (const ColorMaskState& c : s.color_mask) {
        CheckValue(c.mask);
    }
    if (s.stencil) {
        for (const StencilEntry& e : s.stencil->entries) {
            CheckValue(e.value);
        }
    }
}

bool State::CheckPrograms(const std::vector<ProgramBlock>& programs, bool in_pass) {
    const ProgramBlock* first_program = nullptr;
    const bool surface_include =
        std::any_of(programs.begin(), programs.end(), [](const ProgramBlock& b) {
            return IsIncludeBlock(b.kind) && FindPragma(b, "surface") != nullptr;
        });
    for (const ProgramBlock& block : programs) {
        if (block.kind == ProgramKind::kGlslProgram || block.kind == ProgramKind::kGlslInclude) {
            Error(
                DiagCode::kUnsupportedGlsl, MarkerRange(block),
                "'" + std::string(ProgramKindName(block.kind)) +
                    "' blocks are not supported; Kiln compiles HLSL, use CGPROGRAM or HLSLPROGRAM");
            continue;
        }
        if (const Pragma* surface = FindPragma(block, "surface")) {
            // The generator (driver/surface_passes.h) turns a SubShader's surface program into
            // passes; inside a Pass, Unity refuses it too.
            if (in_pass) {
                Error(DiagCode::kBadSurfaceShader, surface->range,
                      "a surface shader's program belongs in a SubShader, not in a Pass; Unity "
                      "generates its passes");
            }
            continue;
        }
        if (IsIncludeBlock(block.kind)) {
            continue;
        }
        if (!in_pass && (surface_include || surface_includes > 0)) {
            continue;  // a program of the surface shader declared in the CGINCLUDE
        }
        if (!in_pass) {
            Error(DiagCode::kProgramOutsidePass, MarkerRange(block),
                  "'" + std::string(ProgramKindName(block.kind)) +
                      "' must be inside a Pass; only CGINCLUDE and HLSLINCLUDE may appear here");
        } else if (first_program != nullptr) {
            Diagnostic& d = Error(DiagCode::kMultiplePrograms, MarkerRange(block),
                                  "a Pass has at most one program block");
            d.notes.push_back({file, MarkerRange(*first_program), "first program block here"});
        } else {
            first_program = &block;
        }
    }
    return surface_include;
}

// A LightMode no pipeline knows means the pass is never drawn. One spelled like a known value is a
// typo: an error with that value (as for pragmas, K4016). Others may belong to a custom pipeline:
// a warning.
void State::CheckLightMode(const std::vector<Tag>& tags) {
    for (const Tag& t : tags) {
        if (t.key != "LightMode")
            continue;
        const auto& modes = pack::KnownLightModes();
        const bool known = std::any_of(modes.begin(), modes.end(), [&](const std::string& m) {
            return EqualsIgnoreCase(m, t.value);
        });
        if (known)
            continue;
        const std::string near = pack::ClosestName(t.value, modes);
        if (!near.empty()) {
            Error(DiagCode::kMisspelledLightMode, t.range,
                  "unknown LightMode '" + t.value + "'; did you mean '" + near +
                      "'? as written no pipeline draws this pass");
        } else {
            Warning(DiagCode::kUnknownLightMode, t.range,
                    "unknown LightMode '" + t.value +
                        "': no Unity pipeline draws this pass (a custom pipeline may)");
        }
    }
}

void State::CheckSubShader(const SubShader& sub) {
    CheckState(sub.state);
    CheckPrograms(sub.programs, false);
    std::map<std::string, const Pass*> names;
    for (const PassEntry& entry : sub.passes) {
        const Pass* pass = std::get_if<Pass>(&entry);
        if (pass == nullptr) {
            continue;
        }
        CheckState(pass->state);
        CheckPrograms(pass->programs, true);
        CheckLightMode(pass->tags);
        if (pass->name.empty()) {
            continue;
        }
        std::string upper = pass->name;  // pass names are matched case-insensitively (UsePass)
        for (char& c : upper) {
            c = (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c;
        }
        auto [it, inserted] = names.emplace(upper, pass);
        if (!inserted) {
            Diagnostic& d = Warning(DiagCode::kDuplicatePassName, pass->range,
                                    "duplicate pass name '" + pass->name + "' in this SubShader");
            d.notes.push_back({file, it->second->range, "first pass with this name"});
        }
    }
}

void State::CheckEntries(const std::vector<SubShaderEntry>& entries) {
    for (const SubShaderEntry& entry : entries) {
        if (const SubShader* sub = std::get_if<SubShader>(&entry)) {
            CheckSubShader(*sub);
        } else if (const auto* cat = std::get_if<std::unique_ptr<Category>>(&entry)) {
            CheckState((*cat)->state);
            const int surface = CheckPrograms((*cat)->programs, false) ? 1 : 0;
            surface_includes += surface;
            CheckEntries((*cat)->children);  // depth bounded by ParseOptions::max_nesting
            surface_includes -= surface;
        }
    }
}

}  // namespace

void Check(const Shader& shader, const std::string& file, DiagnosticList& diags) {
    State s{shader, file, diags, {}};
    s.CheckProperties();
    s.surface_includes = s.CheckPrograms(shader.programs, false) ? 1 : 0;
    s.CheckEntries(shader.subshaders);
}

}  // namespace kiln::shaderlab
