// Cheap checks of program text before glslang sees it, for inputs that glslang handles by
// recursing without limit (deep nesting, one expression of very many terms) or by expanding
// without limit (macros whose expansion doubles at every level). Each gives a normal diagnostic
// at the place in the .shader file; the worker's time and memory limits stay as the backstop for
// whatever these do not foresee. Comments and string literals are skipped.
#ifndef KILN_HLSL_PRECHECK_H_
#define KILN_HLSL_PRECHECK_H_

#include <cstdint>
#include <set>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/shaderlab/ast.h"
#include "kiln/source.h"

namespace kiln::hlsl {

struct PrecheckLimits {
    size_t max_nesting = 256;             // ( [ { open at once, and #if/#ifdef/#ifndef open at once
    size_t max_operators = 10000;         // binary operators in one expression statement
    uint64_t max_macro_tokens = 1 << 20;  // estimated tokens of one macro use, fully expanded
};

// Checks the blocks each pass compiles (include blocks, then its program), all from one file.
// Nesting and expression size are checked once per block; macros defined in a pass's earlier
// blocks count for the uses in its later ones, as in the assembled program. Each problem is
// reported once, however many passes share the block.
class Prechecker {
  public:
    Prechecker(const SourceFile& file, const PrecheckLimits& limits, DiagnosticList& diags)
        : file_(file), limits_(limits), diags_(diags) {}

    void CheckPass(const std::vector<const shaderlab::ProgramBlock*>& blocks);

  private:
    const SourceFile& file_;
    PrecheckLimits limits_;
    DiagnosticList& diags_;
    std::set<const shaderlab::ProgramBlock*> checked_;
    std::set<uint32_t> reported_;  // file offsets of macro uses reported
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_PRECHECK_H_
