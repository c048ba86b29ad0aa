#include "surface/lighting_model.h"

#include "hlsl/tokens.h"
#include "shaderlab/program_scan.h"
#include "surface/functions.h"

namespace kiln::surface {
namespace {

using hlsl::Token;

bool IsVector3(const std::string& type) {
    return hlsl::NumericShape(type) == 3;
}

std::optional<LightingForm> FormOf(std::string_view suffix, const std::vector<Param>& p) {
    const size_t n = p.size();
    if (suffix == "_Deferred") {
        if (n == 5 && p[1].type == "UnityGI")
            return LightingForm::kDeferred;
        if (n == 6 && p[2].type == "UnityGI")
            return LightingForm::kDeferredView;
        return std::nullopt;
    }
    if (suffix == "_PrePass")
        return n == 2 ? std::optional(LightingForm::kPrePass) : std::nullopt;
    if (suffix == "_GI")
        return n == 3 && p[1].type == "UnityGIInput" ? std::optional(LightingForm::kGI)
                                                     : std::nullopt;
    if (!suffix.empty())
        return std::nullopt;
    if (n == 2 && p[1].type == "UnityGI")
        return LightingForm::kForward;
    if (n == 3 && p[2].type == "UnityGI")
        return LightingForm::kForwardView;
    if (n == 3 && IsVector3(p[1].type) && hlsl::NumericShape(p[2].type) == 1)
        return LightingForm::kForwardLegacy;
    if (n == 4 && IsVector3(p[1].type) && IsVector3(p[2].type) &&
        hlsl::NumericShape(p[3].type) == 1)
        return LightingForm::kForwardLegacyView;
    return std::nullopt;
}

}  // namespace

const char* LightingFormName(LightingForm form) {
    switch (form) {
        case LightingForm::kForward:
            return "forward";
        case LightingForm::kForwardView:
            return "forward with view direction";
        case LightingForm::kForwardLegacy:
            return "forward (light direction and attenuation)";
        case LightingForm::kForwardLegacyView:
            return "forward (light direction, view direction and attenuation)";
        case LightingForm::kDeferred:
            return "deferred";
        case LightingForm::kDeferredView:
            return "deferred with view direction";
        case LightingForm::kPrePass:
            return "light pre-pass";
        case LightingForm::kGI:
            return "global illumination";
    }
    return "forward";
}

const LightingFunction* LightingModel::Find(LightingForm form) const {
    for (const LightingFunction& f : functions) {
        if (f.form == form)
            return &f;
    }
    return nullptr;
}

const LightingFunction* LightingModel::Forward() const {
    for (LightingForm form : {LightingForm::kForward, LightingForm::kForwardView,
                              LightingForm::kForwardLegacy, LightingForm::kForwardLegacyView}) {
        if (const LightingFunction* f = Find(form))
            return f;
    }
    return nullptr;
}

bool LightingModel::UsesViewDir() const {
    const LightingFunction* f = Forward();
    return f != nullptr &&
           (f->form == LightingForm::kForwardView || f->form == LightingForm::kForwardLegacyView);
}

LightingModel FindLightingModel(std::string_view text, std::string_view name) {
    LightingModel model;
    model.name = std::string(name);
    const std::string blank = shaderlab::BlankComments(text);
    const std::vector<Token> tok = hlsl::Tokenize(blank);
    const std::string base = "Lighting" + std::string(name);
    for (size_t i = 1; i + 1 < tok.size(); ++i) {
        // A definition: a return type before the name, `(` after it, `{` after the `)`.
        if (!tok[i].ident || tok[i].text.rfind(base, 0) != 0 || tok[i + 1].text != "(" ||
            !tok[i - 1].ident)
            continue;
        const size_t close = hlsl::MatchForward(tok, i + 1);
        if (close == SIZE_MAX || close + 1 >= tok.size() || tok[close + 1].text != "{")
            continue;
        const std::vector<Param> params = Params(tok, i + 1, close);
        const std::optional<LightingForm> form =
            params.empty() ? std::nullopt : FormOf(tok[i].text.substr(base.size()), params);
        if (!form)
            continue;
        model.functions.push_back({std::string(tok[i].text), *form, params[0].type, tok[i].begin});
    }
    return model;
}

}  // namespace kiln::surface
