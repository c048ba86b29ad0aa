// The checks table (checks/checks.h): every check over a finished input, with its codes.
#include "checks/checks.h"

#include "checks/check_functions.h"
#include "hlsl/precheck.h"
#include "kiln/compile.h"
#include "kiln/shaderlab/parse.h"

namespace kiln::checks {

std::string_view InputName(Input input) {
    switch (input) {
        case Input::kAst:
            return "ast";
        case Input::kPrograms:
            return "programs";
        case Input::kReflection:
            return "reflection";
        case Input::kPack:
            return "pack";
    }
    return "?";
}

std::string_view WhenName(When when) {
    return when == When::kLint ? "lint" : "always";
}

void CheckShaderLab(Inputs& in) {
    shaderlab::Check(*in.ast, in.file->path(), in.diags);
}

void CheckProgramLimits(Inputs& in) {
    hlsl::Prechecker precheck(*in.file, {}, in.diags);
    for (const driver::FlatPass& fp : *in.passes)
        precheck.CheckPass(fp.blocks);
}

const std::vector<Check>& AllChecks() {
    using D = DiagCode;
    static const std::vector<Check> table = {
        {"shaderlab",
         {D::kDuplicateProperty, D::kUndeclaredProperty, D::kPropertyRefType, D::kBadRange,
          D::kDefaultOutOfRange, D::kMultiplePrograms, D::kUnsupportedGlsl, D::kBadSurfaceShader,
          D::kProgramOutsidePass, D::kUnknownTextureDefault, D::kDuplicatePassName,
          D::kUnknownLightMode, D::kMisspelledLightMode},
         Input::kAst,
         When::kAlways,
         CheckShaderLab,
         "properties, property references, ranges, program blocks, LightMode tags"},
        {"program-limits",
         {D::kProgramNestingTooDeep, D::kMacroExpansionTooLarge, D::kExpressionTooLong},
         Input::kPrograms,
         When::kAlways,
         CheckProgramLimits,
         "programs nested, expanded or long past what the HLSL compiler survives"},
        {"stage-interface",
         {D::kStageInterfaceMismatch, D::kBlockLayoutMismatch},
         Input::kReflection,
         When::kAlways,
         CheckStageInterfaces,
         "fragment inputs no earlier stage writes, uniform blocks laid out differently per stage"},
        {"properties",
         {D::kPropertyUnused, D::kGlobalNotAProperty, D::kPropertyTypeMismatch},
         Input::kReflection,
         When::kAlways,
         CheckProperties,
         "Properties without a shader variable, globals materials cannot set, mismatched types"},
        {"keyword-effect",
         {D::kLintKeywordChangesNothing, D::kLintKeywordOneStage, D::kLintRedundantKeywords},
         Input::kPack,
         When::kLint,
         LintKeywordEffects,
         "keywords that change no code, one stage only, or the same code as another"},
        {"keyword-declarations",
         {D::kLintEngineShaderFeature, D::kLintMaterialMultiCompile,
          D::kLintShaderFeatureLooksGlobal, D::kLintKeywordDeclaredTwoWays},
         Input::kPack,
         When::kLint,
         LintKeywordDeclarations,
         "keywords declared so that the renderer's or the materials' lookups miss"},
        {"keyword-limits",
         {D::kLintTooManyKeywords},
         Input::kPack,
         When::kLint,
         LintKeywordLimits,
         "more keywords than Unity's documented limits"},
        {"property-keywords",
         {D::kLintPropertyKeywordUndeclared, D::kLintKeywordWithoutToggle},
         Input::kPack,
         When::kLint,
         LintPropertyKeywords,
         "[Toggle] and [KeywordEnum] keywords no pass declares, and the reverse"},
        {"pass-state",
         {D::kLintStateContradictsPass},
         Input::kPack,
         When::kLint,
         LintPassState,
         "render state the pass's LightMode or Queue contradicts"},
    };
    return table;
}

void RunChecks(Input input, bool lint, Inputs& in) {
    for (const Check& c : AllChecks()) {
        if (c.input == input && (c.when == When::kAlways || lint))
            c.run(in);
    }
}

}  // namespace kiln::checks

namespace kiln {

std::vector<CheckInfo> ListChecks() {
    std::vector<CheckInfo> out;
    for (const checks::Check& c : checks::AllChecks()) {
        out.push_back({std::string(c.name), c.codes, std::string(checks::InputName(c.input)),
                       std::string(checks::WhenName(c.when)), std::string(c.summary)});
    }
    return out;
}

}  // namespace kiln
