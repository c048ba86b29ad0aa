// kiln validate --pack PACK FILE.material... and kiln new --template T NAME.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "kiln/base/files.h"
#include "kiln/material/material.h"
#include "kiln/pack/reader.h"
#include "kiln/source.h"

namespace kiln::cli {
namespace fs = std::filesystem;

std::function<int()> AddValidateCommand(CLI::App* cmd, const GlobalOptions& global) {
    struct Args {
        std::string pack;
        std::vector<std::string> files;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("--pack", args->pack, "The compiled pack holding the materials' shaders")
        ->required();
    cmd->add_option("files", args->files, ".material files")->required();
    return [args, &global] {
        pack::MappedFile mapped;
        pack::Pack p;
        if (!OpenPack(args->pack, mapped, p, global))
            return int(kExitInputError);
        DiagnosticList diags = global.NewDiagnostics();
        std::vector<std::unique_ptr<SourceFile>> files;
        for (const std::string& path : args->files) {
            Result<SourceFile> read = ReadSourceFile(path, material::kMaxFileBytes);
            if (!read) {
                diags.Error(DiagCode::kCannotReadFile, path, kNoPosition, read.error().message);
                continue;
            }
            files.push_back(std::make_unique<SourceFile>(std::move(read).value()));
            DiagnosticList issues;
            material::Material m;
            material::ParseMaterial(files.back()->text(), path, m, issues);
            if (!m.shader.empty())  // empty when not JSON or without "shader" (both reported)
                material::ValidateMaterial(m, p, fs::path(path).parent_path().string(), issues);
            issues.SortByPosition();
            diags.Append(issues);
        }
        std::vector<const SourceFile*> views;
        for (const auto& f : files)
            views.push_back(f.get());
        PrintDiagnostics(diags, views, global);
        return ExitCodeFor(diags);
    };
}

std::function<int()> AddNewCommand(CLI::App* cmd, const GlobalOptions& global) {
    struct Args {
        std::string scaffold;
        std::string name;
        std::string output;
        std::string templates_dir;
        bool force = false;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("--template", args->scaffold, "Scaffold: lit, unlit, pbs or multilight")
        ->required()
        ->transform(CLI::IsMember({"lit", "unlit", "pbs", "multilight"}, CLI::ignore_case));
    cmd->add_option("name", args->name, "Shader name, e.g. MyGame/Rock (file: Rock.shader)")
        ->required();
    cmd->add_option("-o,--output", args->output, "Output file (default: <last name part>.shader)");
    cmd->add_option("--templates", args->templates_dir, "Templates folder (default: built-in)");
    cmd->add_flag("-f,--force", args->force, "Overwrite an existing file");
    return [args, &global] {
        const std::string templates =
            args->templates_dir.empty() ? DefaultTemplatesDir() : args->templates_dir;
        const std::string scaffold_path = templates + "/scaffolds/" + args->scaffold + ".shader";
        Result<SourceFile> scaffold = ReadSourceFile(scaffold_path);
        if (!scaffold) {
            return ReportError(global, DiagCode::kCannotReadFile, scaffold_path,
                               scaffold.error().message);
        }
        for (char c : args->name) {
            if (c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20) {
                ReportError(global, DiagCode::kBadCommandLine, "",
                            "shader name must not contain quotes, backslashes or control "
                            "characters");
                return int(kExitUsageError);
            }
        }
        std::string text = scaffold.value().text();
        const std::string placeholder = "KILN_SHADER_NAME";
        for (size_t at = text.find(placeholder); at != std::string::npos;
             at = text.find(placeholder, at + args->name.size())) {
            text.replace(at, placeholder.size(), args->name);
        }
        std::string output = args->output;
        if (output.empty()) {
            const size_t slash = args->name.find_last_of('/');
            output = (slash == std::string::npos ? args->name : args->name.substr(slash + 1)) +
                     ".shader";
        }
        if (fs::exists(output) && !args->force) {
            return ReportError(global, DiagCode::kCannotWriteFile, output,
                               "file exists; pass --force to overwrite");
        }
        Status written = base::WriteFileAtomically(output, text);
        if (!written.ok())
            return ReportError(global, DiagCode::kCannotWriteFile, output, written.error().message);
        std::printf("wrote %s (shader \"%s\", %s scaffold)\n", output.c_str(), args->name.c_str(),
                    args->scaffold.c_str());
        return int(kExitOk);
    };
}

}  // namespace kiln::cli
