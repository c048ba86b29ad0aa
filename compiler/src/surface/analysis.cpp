#include "surface/analysis.h"

#include <map>
#include <vector>

#include "hlsl/tokens.h"
#include "shaderlab/program_scan.h"
#include "surface/functions.h"

namespace kiln::surface {
namespace {

using hlsl::Token;

// The member names of `struct type { ... }` in the tokens; false when it is not defined there.
bool StructMembers(const std::string& blank,
                   const std::vector<Token>& tok,
                   const std::string& type,
                   VertexInput& out) {
    for (size_t i = 0; i + 2 < tok.size(); ++i) {
        if (tok[i].text != "struct" || tok[i + 1].text != type || tok[i + 2].text != "{")
            continue;
        const size_t close = hlsl::MatchForward(tok, i + 2);
        if (close == SIZE_MAX)
            return false;
        out.instance_id = false;
        for (size_t k = i + 3; k < close; ++k) {
            if (tok[k].text == "UNITY_VERTEX_INPUT_INSTANCE_ID")
                out.instance_id = true;
            // A member's name: the identifier before `:` or `;` (or `[` of an array).
            if (tok[k].ident && k + 1 < close &&
                (tok[k + 1].text == ":" || tok[k + 1].text == ";" || tok[k + 1].text == "[") &&
                k > i + 3 && tok[k - 1].ident) {
                out.members.insert(std::string(tok[k].text));
                out.conditions[std::string(tok[k].text)] =
                    ConditionsAt(blank, tok[i + 2].begin, tok[k].begin);
            }
        }
        return true;
    }
    return false;
}

// UnityCG.cginc's vertex input structs.
bool BuiltinVertexInput(const std::string& type, VertexInput& out) {
    static const std::map<std::string, std::set<std::string>> kStructs = {
        {"appdata_base", {"vertex", "normal", "texcoord"}},
        {"appdata_tan", {"vertex", "tangent", "normal", "texcoord"}},
        {"appdata_full",
         {"vertex", "tangent", "normal", "texcoord", "texcoord1", "texcoord2", "texcoord3",
          "color"}},
    };
    auto it = kStructs.find(type);
    if (it == kStructs.end())
        return false;
    out.members = it->second;
    out.instance_id = true;
    return true;
}

bool MentionsNormal(const std::vector<Token>& tok, size_t body, const std::string& param) {
    const size_t end = hlsl::MatchForward(tok, body);
    for (size_t k = body; k + 2 < tok.size() && k < end; ++k) {
        if (tok[k].text == param && tok[k + 1].text == "." && tok[k + 2].text == "Normal")
            return true;
    }
    return false;
}

// The vertex: function's input struct and whether it fills the Input struct.
bool ReadVertexFunction(const std::vector<Token>& tok,
                        const std::string& vert,
                        SurfaceShader& out,
                        SurfaceProblem& problem) {
    size_t close = 0, body = 0;
    const size_t open = FindDefinition(tok, vert, close, body);
    const std::vector<Param> vp =
        open == SIZE_MAX ? std::vector<Param>{} : Params(tok, open, close);
    if (open == SIZE_MAX || vp.empty() || vp.size() > 2) {
        problem.message = "vertex function '" + vert + "' " +
                          (open == SIZE_MAX ? "is not defined"
                                            : "must take (inout appdata_full v) or (inout "
                                              "appdata_full v, out Input o)");
        return false;
    }
    out.vertex_input.type = vp[0].type;
    out.vertex_fills_input = vp.size() == 2;
    return true;
}

}  // namespace

bool SurfaceShader::PhysicallyBasedOutput() const {
    return output_type.rfind("SurfaceOutputStandard", 0) == 0;
}

LightingModel BuiltinLightingModel(std::string_view name) {
    LightingModel m;
    m.name = std::string(name);
    const std::string n(name);
    auto add = [&](const std::string& suffix, LightingForm form, const char* output) {
        m.functions.push_back({"Lighting" + n + suffix, form, output, 0});
    };
    if (n == "Lambert") {
        add("", LightingForm::kForward, "SurfaceOutput");
        add("_Deferred", LightingForm::kDeferred, "SurfaceOutput");
        add("_GI", LightingForm::kGI, "SurfaceOutput");
    } else if (n == "BlinnPhong" || n == "Standard" || n == "StandardSpecular") {
        const char* output = n == "BlinnPhong" ? "SurfaceOutput"
                             : n == "Standard" ? "SurfaceOutputStandard"
                                               : "SurfaceOutputStandardSpecular";
        add("", LightingForm::kForwardView, output);
        add("_Deferred", LightingForm::kDeferredView, output);
        add("_GI", LightingForm::kGI, output);
    }
    return m;
}

std::optional<SurfaceShader> AnalyzeSurface(std::string_view text,
                                            const SurfaceDirective& directive,
                                            SurfaceProblem& problem) {
    SurfaceShader out;
    out.directive = directive;
    const std::string blank = shaderlab::BlankComments(text);
    const std::vector<Token> tok = hlsl::Tokenize(blank);
    const std::string& surf = directive.function.text;
    size_t close = 0, body = 0;
    const size_t open = FindDefinition(tok, surf, close, body);
    if (open == SIZE_MAX) {
        problem.message = "surface function '" + surf + "' is not defined";
        return std::nullopt;
    }
    const std::vector<Param> params = Params(tok, open, close);
    if (params.size() != 2 || params[1].qualifier != "inout") {
        problem.message = "surface function '" + surf +
                          "' must take (Input IN, inout SurfaceOutput o), as Unity's does";
        return std::nullopt;
    }
    std::optional<InputStruct> input = FindInputStruct(blank, surf);
    if (!input) {
        problem.message = "the Input struct '" + params[0].type + "' of surface function '" + surf +
                          "' is not defined";
        return std::nullopt;
    }
    out.input = std::move(*input);
    out.output_param = params[1].name;
    out.tangent_space = MentionsNormal(tok, body, out.output_param);
    out.model = directive.BuiltinLighting() ? BuiltinLightingModel(directive.lighting.text)
                                            : FindLightingModel(blank, directive.lighting.text);
    const LightingFunction* forward = out.model.Forward();
    if (forward == nullptr) {
        problem.message = "lighting model '" + directive.lighting.text +
                          "' has no function 'Lighting" + directive.lighting.text +
                          "' in a form Unity documents";
        return std::nullopt;
    }
    out.output_type = forward->output_type;
    if (params[1].type != out.output_type) {
        problem.message = "surface function '" + surf + "' fills '" + params[1].type +
                          "' but lighting model '" + directive.lighting.text + "' reads '" +
                          out.output_type + "'";
        return std::nullopt;
    }
    if (directive.vertex && !ReadVertexFunction(tok, directive.vertex->text, out, problem))
        return std::nullopt;
    if (!BuiltinVertexInput(out.vertex_input.type, out.vertex_input) &&
        !StructMembers(blank, tok, out.vertex_input.type, out.vertex_input)) {
        problem.message = "the vertex input struct '" + out.vertex_input.type + "' is not defined";
        return std::nullopt;
    }
    for (const Token& t : tok) {
        if (t.ident)
            out.identifiers.insert(std::string(t.text));
    }
    for (size_t at = blank.find("LOD_FADE_CROSSFADE"); at != std::string::npos;
         at = blank.find("LOD_FADE_CROSSFADE", at + 1)) {
        const size_t line = blank.rfind('\n', at) + 1;  // npos + 1 == 0
        const size_t hash = blank.find_first_not_of(" \t", line);
        if (blank.compare(hash, 1, "#") == 0 && blank.find("pragma", hash) < at)
            out.declares_crossfade = true;
    }
    return out;
}

}  // namespace kiln::surface
