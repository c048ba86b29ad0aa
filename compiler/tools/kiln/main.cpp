// kiln: the command-line driver. A thin layer over the kiln_compiler library: flags in,
// library calls, diagnostics out.
#include <algorithm>
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

// Compiler-style spellings CLI11 cannot declare: -O0/-O/-Os, -MD, -MF.
std::vector<std::string> RewriteArgs(int argc, char** argv) {
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "-O0") {
            args.push_back("--opt=0");
        } else if (a == "-O") {
            args.push_back("--opt=1");
        } else if (a == "-Os") {
            args.push_back("--opt=s");
        } else if (a == "-MD") {
            args.push_back("--md");
        } else if (a == "-MF") {
            args.push_back("--mf");
        } else {
            args.push_back(a);
        }
    }
    std::reverse(args.begin(), args.end());  // CLI11 takes them in reverse order
    return args;
}

int main(int argc, char** argv) {
    using namespace kiln::cli;
    try {
        CLI::App app{"kiln: shader-variant compiler for Vulkan", "kiln"};
        app.require_subcommand(1);
        app.set_version_flag("--version", "kiln 0.2.0");
        GlobalOptions global;
        const std::map<std::string, DiagFormat> formats{{"text", DiagFormat::kText},
                                                        {"json", DiagFormat::kJson}};
        app.add_option("--diagnostics-format", global.diag_format,
                       "How diagnostics are printed on stderr: text or json")
            ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case))
            ->option_text("text|json");
        app.fallthrough();

        const std::map<std::string, std::function<int()>> commands{
            {"parse", AddParseCommand(app, global)},
            {"compile", AddCompileCommand(app, global)},
            {"variants", AddVariantsCommand(app, global)},
            {"info", AddInfoCommand(app, global)},
            {"extract", AddExtractCommand(app, global)},
            {"validate", AddValidateCommand(app, global)},
            {"new", AddNewCommand(app, global)},
            {"render", AddRenderCommand(app, global)}};

        try {
            std::vector<std::string> args = RewriteArgs(argc, argv);
            app.parse(args);
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
