// The command-line driver of kiln and kiln-render (RunCli, commands.h): a thin layer over the
// libraries: flags in, library calls, diagnostics out. Both programs run it over the one command
// table (command_list.h); kiln hands the commands kiln-render runs (those that link the renderer:
// Vulkan, OpenColorIO, tinygltf) to kiln-render beside it with the same arguments, so a build
// machine's kiln needs none of those libraries (docs/install.md).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "commands.h"
#include "kiln/base/files.h"
#include "kiln/pack/format.h"
#include "kiln/pack/names.h"

namespace kiln::cli {

void PrintDiagnostics(const DiagnosticList& diags,
                      const std::vector<const SourceFile*>& sources,
                      const GlobalOptions& global) {
    // Written whole: the text is escaped (kiln/base/text.h), and even so a NUL must not end it.
    const std::string text = global.diag_format == DiagFormat::kJson
                                 ? FormatDiagnosticsJson(diags) + "\n"
                                 : FormatDiagnosticsText(diags, sources, global.color);
    std::fwrite(text.data(), 1, text.size(), stderr);
}

int ReportError(const GlobalOptions& global,
                DiagCode code,
                const std::string& file,
                const std::string& message) {
    DiagnosticList diags;
    diags.Error(code, file, kNoPosition, message);
    PrintDiagnostics(diags, {}, global);
    return ExitCodeFor(diags);
}

int ExitCodeFor(const DiagnosticList& diags) {
    if (diags.has_internal_errors()) {
        return kExitInternalError;
    }
    return diags.has_errors() ? kExitInputError : kExitOk;
}

namespace {

// --color=auto: a terminal on stderr, NO_COLOR unset (no-color.org) and TERM not "dumb".
bool AutoColor() {
    const char* no_color = std::getenv("NO_COLOR");
    const char* term = std::getenv("TERM");
    return isatty(STDERR_FILENO) && (no_color == nullptr || *no_color == '\0') &&
           !(term != nullptr && std::strcmp(term, "dumb") == 0);
}

std::string VersionText() {
    return ProducerVersion() + "; pack format " + std::to_string(pack::kFormatMajor) + "." +
           std::to_string(pack::kFormatMinor);
}

// The value of a global option given as "--name value" or "--name=value", or "".
std::string GlobalValue(const std::vector<std::string>& args, const std::string& name) {
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == name && i + 1 < args.size())
            return args[i + 1];
        if (args[i].rfind(name + "=", 0) == 0)
            return args[i].substr(name.size() + 1);
    }
    return "";
}

// The first word that is not an option (or a global option's value): the subcommand the user
// meant, for the "did you mean" of a mistyped one.
std::string FirstWord(const std::vector<std::string>& args) {
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--diagnostics-format" || a == "--color") {
            ++i;
            continue;
        }
        if (!a.empty() && a[0] != '-')
            return a;
    }
    return "";
}

// A command line CLI11 rejected, as a K0003 diagnostic in the format the words ask for (the
// parse stopped early, so the global options are read from the words themselves); a mistyped
// subcommand gets the closest one.
int ReportParseError(const CLI::ParseError& e,
                     const std::vector<std::string>& words,
                     const std::vector<std::string>& commands) {
    GlobalOptions global;
    global.diag_format = GlobalValue(words, "--diagnostics-format") == "json" ? DiagFormat::kJson
                                                                              : DiagFormat::kText;
    const std::string c = GlobalValue(words, "--color");
    global.color = c == "always" || (c != "never" && AutoColor());
    const std::string word = FirstWord(words);
    if (!word.empty() && std::find(commands.begin(), commands.end(), word) == commands.end()) {
        std::string all;
        for (const std::string& n : commands)
            all += (all.empty() ? "" : ", ") + n;
        ReportError(global, DiagCode::kBadCommandLine, "",
                    "unknown command '" + word + "'" + pack::DidYouMean(word, commands) +
                        " (commands: " + all + ")");
        return kExitUsageError;
    }
    std::string what = e.what();
    if (what.rfind(": ", 0) == 0)
        what.erase(0, 2);  // a hidden option's empty name
    ReportError(global, DiagCode::kBadCommandLine, "", what);
    if (global.diag_format == DiagFormat::kText) {
        std::fprintf(stderr, "run 'kiln %s--help' for the options\n",
                     word.empty() ? "" : (word + " ").c_str());
    }
    return kExitUsageError;
}

// `kiln ... render ...`: kiln-render beside this kiln, with the whole command line. Returns only
// when it cannot be run (K0025).
int RunRenderTool(int argc, char** argv) {
    std::vector<char*> args(argv, argv + argc);
    const std::string path = RenderToolPath();
    args[0] = const_cast<char*>(path.c_str());
    args.push_back(nullptr);
    execv(path.c_str(), args.data());
    const std::vector<std::string> words(argv + 1, argv + argc);
    GlobalOptions global;
    global.diag_format = GlobalValue(words, "--diagnostics-format") == "json" ? DiagFormat::kJson
                                                                              : DiagFormat::kText;
    return ReportError(global, DiagCode::kRendererUnavailable, "",
                       "cannot run the renderer '" + path + "': " + std::strerror(errno) +
                           "; kiln render is kiln-render, installed beside kiln with the runtime");
}

// Compiler-style spellings CLI11 cannot declare: -O0/-O/-Os, -MD, -MF.
std::vector<std::string> RewriteArgs(int argc, char** argv) {
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "-O0") {
            args.push_back("--opt=0");
        } else if (a == "-O" || a == "-O1" || a == "-O2" || a == "-O3") {
            args.push_back("--opt=1");
        } else if (a == "-Os") {
            args.push_back("--opt=s");
        } else if (a.size() > 2 && a.rfind("-O", 0) == 0 && a[2] != '-') {
            args.push_back("--opt=" + a.substr(2));  // rejected with the valid spellings
        } else if (a.size() > 2 && a.rfind("-W", 0) == 0) {
            args.push_back("--warning-option=" + a);  // -Wno-K7001, -Werror=lint, -Werror
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

}  // namespace

int RunCli(int argc, char** argv, Binary self, const std::vector<Command>& table) {
    // No output of any command may replace a file the command reads (docs/runtime.md, "Files").
    kiln::base::GuardInputFiles();
    try {
        const std::string first = FirstWord(std::vector<std::string>(argv + 1, argv + argc));
        for (const Command& c : table) {
            if (self == Binary::kKiln && c.binary == Binary::kKilnRender && c.name == first)
                return RunRenderTool(argc, argv);
        }
        CLI::App app{"kiln: shader-variant compiler for Vulkan", "kiln"};
        app.require_subcommand(0, 1);
        app.set_version_flag("-V,--version", VersionText,
                             "Print kiln's version and those of "
                             "glslang and SPIRV-Tools it compiles with (packs record them)");
        GlobalOptions global;
        const std::map<std::string, DiagFormat> formats{{"text", DiagFormat::kText},
                                                        {"json", DiagFormat::kJson}};
        app.add_option("--diagnostics-format", global.diag_format,
                       "How diagnostics are printed on stderr: text or json")
            ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case))
            ->option_text("text|json");
        std::string color = "auto";
        app.add_option("--color", color,
                       "Colour text diagnostics: auto (a terminal, unless NO_COLOR is set), "
                       "always or never")
            ->check(CLI::IsMember({"auto", "always", "never"}))
            ->option_text("auto|always|never");
        std::vector<std::string> warning_options;
        app.add_option("--warning-option", warning_options)
            ->group("")
            ->allow_extra_args(false);  // -W..., rewritten
        app.footer(
            "Warning options, for every command, in clang's and GCC's spelling, where X is a "
            "code (K7001) or a group (all, runtime, shaderlab, variants, hlsl, interface, "
            "material, lint, lint-keywords, lint-state): -Wno-X silences X's warnings, -WX shows "
            "them again, -Werror=X makes them errors, -Wno-error=X keeps them warnings, -Werror "
            "makes every warning an error (docs/diagnostics.md, \"Warning options\").");
        app.fallthrough();
        app.add_subcommand("version", "Print the versions (as --version)");

        // The table's commands this program runs; kiln lists kiln-render's too (for --help and
        // "did you mean"), having handed them over above.
        std::map<std::string, std::function<int()>> commands;
        for (const Command& c : table) {
            if (c.binary != self && self == Binary::kKilnRender)
                continue;
            const std::string summary =
                std::string(c.summary) +
                (c.binary == self ? "" : " (runs kiln-render, beside kiln)");
            CLI::App* sub = app.add_subcommand(std::string(c.name), summary);
            commands[std::string(c.name)] =
                c.binary == self ? c.add(sub, global) : [] { return int(kExitUsageError); };
        }

        std::vector<std::string> args = RewriteArgs(argc, argv);
        std::vector<std::string> names;
        for (const auto& [name, run] : commands)
            names.push_back(name);
        names.push_back("version");
        const std::vector<std::string> words(args.rbegin(), args.rend());  // parse consumes args
        try {
            app.parse(args);
        } catch (const CLI::ParseError& e) {
            if (e.get_exit_code() == 0)
                return app.exit(e) == 0 ? kExitOk : kExitUsageError;  // --help, --version
            return ReportParseError(e, words, names);
        }
        global.color = color == "always" || (color == "auto" && AutoColor());
        for (const std::string& w : warning_options) {
            if (kiln::Status added = global.warnings.Add(w); !added.ok()) {
                ReportError(global, added.error().code, "", added.error().message);
                return kExitUsageError;
            }
        }
        if (app.get_subcommands().empty()) {
            std::fputs(app.help().c_str(), stderr);
            return kExitUsageError;
        }
        const std::string command = app.get_subcommands().front()->get_name();
        if (command == "version") {
            std::printf("%s\n", VersionText().c_str());
            return kExitOk;
        }
        return commands.at(command)();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "kiln: internal compiler error: %s [K9001]\n", e.what());
        return kExitInternalError;
    }
}

}  // namespace kiln::cli
