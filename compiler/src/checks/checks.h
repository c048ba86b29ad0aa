// Every check the compiler runs over a finished input, as data: one table of {name, codes,
// input, when, function} (checks.cpp). The compile driver runs the table's checks for an input
// once it has it; `kiln lint --list-checks` prints the table; the -W options (kiln/diagnostic.h)
// silence or promote a check's codes. docs/diagnostics.md, "Checks", lists them.
//
// Not here: what a parser reports as it reads (the lexer and parser's K1xxx/K2xxx, the pragma
// reader's K4xxx syntax and keyword errors) and what a compile step reports about its own work
// (glslang's K5001, spirv-val's K5003, the worker's K5009-K5011): those are not checks over a
// finished input but the step failing.
#ifndef KILN_CHECKS_CHECKS_H_
#define KILN_CHECKS_CHECKS_H_

#include <string_view>
#include <vector>

#include "driver/compile_state.h"
#include "kiln/diagnostic.h"
#include "kiln/pack/reader.h"

namespace kiln::checks {

// What a check reads, in the order a compile has it.
enum class Input : uint8_t {
    kAst,         // one shader's checked-in AST, before its passes are flattened
    kPrograms,    // one shader's flattened passes: the program text of each
    kReflection,  // every variant's final SPIR-V and its reflection (CompileState::finals)
    kPack,        // the pack built from them, and the finals (kiln lint only)
};
// When a check runs: every compile, or only `kiln lint` (which builds every variant).
enum class When : uint8_t { kAlways, kLint };

std::string_view InputName(Input input);
std::string_view WhenName(When when);

// A check's inputs: the fields its Input names are set (`diags` always).
struct Inputs {
    DiagnosticList& diags;
    const SourceFile* file = nullptr;                       // kAst, kPrograms
    const shaderlab::Shader* ast = nullptr;                 // kAst
    const std::vector<driver::FlatPass>* passes = nullptr;  // kPrograms
    driver::CompileState* st = nullptr;                     // kReflection, kPack
    const pack::Pack* pack = nullptr;                       // kPack
};

struct Check {
    std::string_view name;  // "stage-interface": lower-case words, unique
    std::vector<DiagCode> codes;
    Input input;
    When when;
    void (*run)(Inputs& in);
    std::string_view summary;  // one sentence: what it finds
};

// The table, in the order the checks run.
const std::vector<Check>& AllChecks();

// Runs every check of `input` (those of When::kLint only when `lint`), in the table's order.
void RunChecks(Input input, bool lint, Inputs& in);

}  // namespace kiln::checks

#endif  // KILN_CHECKS_CHECKS_H_
