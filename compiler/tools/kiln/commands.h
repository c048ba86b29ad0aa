// Subcommands of the kiln CLI. Each registers itself on the CLI11 app and runs after parsing.
#ifndef KILN_TOOLS_KILN_COMMANDS_H_
#define KILN_TOOLS_KILN_COMMANDS_H_

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "kiln/diagnostic.h"

namespace kiln::cli {

// Process exit codes, documented in README.md.
enum ExitCode : int {
    kExitOk = 0,
    kExitInputError = 1,     // the inputs have errors (diagnostics printed)
    kExitUsageError = 2,     // bad command line
    kExitInternalError = 3,  // internal compiler error: a Kiln bug
};

enum class DiagFormat { kText, kJson };

struct GlobalOptions {
    DiagFormat diag_format = DiagFormat::kText;
};

// Prints diagnostics to stderr in the chosen format.
void PrintDiagnostics(const DiagnosticList& diags,
                      const std::vector<const SourceFile*>& sources,
                      const GlobalOptions& global);
int ExitCodeFor(const DiagnosticList& diags);

// Registers `kiln parse`; the returned function runs it.
std::function<int()> AddParseCommand(CLI::App& app, const GlobalOptions& global);

}  // namespace kiln::cli

#endif  // KILN_TOOLS_KILN_COMMANDS_H_
