// The functions of the checks table (checks.cpp), one per check; private to checks/.
#ifndef KILN_CHECKS_CHECK_FUNCTIONS_H_
#define KILN_CHECKS_CHECK_FUNCTIONS_H_

#include "checks/checks.h"

namespace kiln::checks {

// Input::kAst, kPrograms (checks.cpp: the shaderlab checks and the program prechecker).
void CheckShaderLab(Inputs& in);
void CheckProgramLimits(Inputs& in);
// Input::kReflection (stage_interface.cpp, properties.cpp).
void CheckStageInterfaces(Inputs& in);
void CheckProperties(Inputs& in);
// Input::kPack, kiln lint (lint_keywords.cpp, lint_state.cpp).
void LintKeywordEffects(Inputs& in);
void LintKeywordDeclarations(Inputs& in);
void LintKeywordLimits(Inputs& in);
void LintPropertyKeywords(Inputs& in);
void LintPassState(Inputs& in);

}  // namespace kiln::checks

#endif  // KILN_CHECKS_CHECK_FUNCTIONS_H_
