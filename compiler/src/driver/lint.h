// kiln lint's checks (docs/variants.md, "Lint"), run on a compile of every variant (every
// shader_feature combination) after the pack is built:
//   lint_keywords.cpp  what each keyword changes, read off the final SPIR-V of every variant:
//                      keywords that change nothing or duplicate another (the pack's aliases),
//                      sets that change one stage only; keywords declared so that the
//                      renderer's or the materials' lookups miss; Unity's keyword limits
//   lint_state.cpp     Properties and keywords that do not meet ([Toggle(KW)] without a
//                      pragma, a keyword [Toggle] would drive without it), and render state the
//                      pass's LightMode or Queue contradicts (resolved from the pack, as engines
//                      resolve it)
// Every finding is a warning with a K7xxx code at the pragma, property or pass it is about.
#ifndef KILN_DRIVER_LINT_H_
#define KILN_DRIVER_LINT_H_

#include "driver/compile_state.h"
#include "kiln/pack/reader.h"

namespace kiln::driver {

void LintKeywords(CompileState& st);
void LintPropertiesAndState(CompileState& st, const pack::Pack& pack);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_LINT_H_
