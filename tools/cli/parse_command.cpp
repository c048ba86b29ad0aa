// kiln parse FILE... [--json]: parse and check ShaderLab files, print the AST.
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "kiln/shaderlab/parse.h"

namespace kiln::cli {

std::function<int()> AddParseCommand(CLI::App* cmd, const GlobalOptions& global) {
    struct Options {
        std::vector<std::string> files;
        bool json = false;
        bool quiet = false;
    };
    auto opts = std::make_shared<Options>();
    cmd->add_option("files", opts->files, "ShaderLab files")->required();
    cmd->add_flag("--json", opts->json, "Print the AST as JSON (format: docs/ast-json.md)");
    cmd->add_flag("-q,--quiet", opts->quiet, "Print only diagnostics");

    return [opts, &global]() {
        DiagnosticList diags = global.NewDiagnostics();
        std::vector<std::unique_ptr<SourceFile>> sources;
        std::string json_files;
        for (const std::string& path : opts->files) {
            Result<SourceFile> file = ReadSourceFile(path);
            if (!file) {
                diags.Error(DiagCode::kCannotReadFile, path, kNoPosition, file.error().message);
                continue;
            }
            sources.push_back(std::make_unique<SourceFile>(std::move(file).value()));
            const std::optional<shaderlab::Shader> shader =
                shaderlab::ParseAndCheck(*sources.back(), diags);
            if (opts->quiet) {
                continue;
            }
            if (opts->json) {
                json_files += json_files.empty() ? "" : ",\n";
                json_files += "{\"file\": " + nlohmann::json(path).dump() +
                              ", \"ast\": " + (shader ? shaderlab::DumpJson(*shader) : "null") +
                              "}";
            } else if (shader) {
                std::fputs(shaderlab::DumpText(*shader).c_str(), stdout);
            }
        }
        if (opts->json && !opts->quiet) {
            std::printf("{\"kiln_ast_version\": 1, \"files\": [\n%s\n]}\n", json_files.c_str());
        }
        std::vector<const SourceFile*> views;
        for (const auto& s : sources) {
            views.push_back(s.get());
        }
        PrintDiagnostics(diags, views, global);
        return ExitCodeFor(diags);
    };
}

}  // namespace kiln::cli
