// kiln: the command-line driver. A thin layer over the kiln_compiler library: flags in,
// library calls, diagnostics out.
#include <cstdio>
#include <exception>
#include <map>

#include "commands.h"

namespace kiln::cli {

void PrintDiagnostics(const DiagnosticList& diags,
                      const std::vector<const SourceFile*>& sources,
                      const GlobalOptions& global) {
    if (global.diag_format == DiagFormat::kJson) {
        std::fprintf(stderr, "%s\n", FormatDiagnosticsJson(diags).c_str());
    } else {
        std::fputs(FormatDiagnosticsText(diags, sources).c_str(), stderr);
    }
}

int ExitCodeFor(const DiagnosticList& diags) {
    if (diags.has_internal_errors()) {
        return kExitInternalError;
    }
    return diags.has_errors() ? kExitInputError : kExitOk;
}

}  // namespace kiln::cli

int main(int argc, char** argv) {
    using namespace kiln::cli;
    try {
        CLI::App app{"kiln: shader-variant compiler for Vulkan", "kiln"};
        app.require_subcommand(1);
        app.set_version_flag("--version", "kiln 0.1.0");
        GlobalOptions global;
        const std::map<std::string, DiagFormat> formats{{"text", DiagFormat::kText},
                                                        {"json", DiagFormat::kJson}};
        app.add_option("--diagnostics-format", global.diag_format,
                       "How diagnostics are printed on stderr: text or json")
            ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case))
            ->option_text("text|json");
        app.fallthrough();

        const std::map<std::string, std::function<int()>> commands{
            {"parse", AddParseCommand(app, global)}};

        try {
            app.parse(argc, argv);
        } catch (const CLI::ParseError& e) {
            const int code = app.exit(e);
            return code == 0 ? kExitOk : kExitUsageError;
        }
        // require_subcommand(1): exactly one subcommand was parsed.
        return commands.at(app.get_subcommands().front()->get_name())();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "kiln: internal compiler error: %s [K9001]\n", e.what());
        return kExitInternalError;
    }
}
