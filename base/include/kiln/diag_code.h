// The stable diagnostic codes and severities every Kiln library reports with: compiler
// diagnostics, the runtime's errors and warnings, the pack reader and .material files. Once
// published a code keeps its meaning (docs/diagnostics.md).
#ifndef KILN_DIAG_CODE_H_
#define KILN_DIAG_CODE_H_

#include <cstdint>

namespace kiln {

enum class Severity : uint8_t { kNote, kWarning, kError, kInternal };

// Stable diagnostic codes, printed as K<number>. Ranges:
//   K0xxx  input/output          K1xxx  ShaderLab lexer
//   K2xxx  ShaderLab parser      K3xxx  ShaderLab semantic checks
//   K4xxx  pragmas and variants  K5xxx  HLSL compilation, SPIR-V, reflection, bindings
//   K6xxx  material instances    K7xxx  kiln lint
//   K9xxx  internal compiler errors
enum class DiagCode : uint16_t {
#define KILN_DIAG_CODE(name, number) name = number,
#include "kiln/diag_code_list.h"
#undef KILN_DIAG_CODE
};

}  // namespace kiln

#endif  // KILN_DIAG_CODE_H_
