// kiln lint A.shader... [-W options] [--json]: what the keywords cost and where they are wasted
// (docs/variants.md, "Lint"). Every variant of every pass is compiled (every shader_feature
// combination); the report gives each pass's variant count with the product that made it and its
// budget, then the K7xxx warnings with the compile's own diagnostics.
#include <cstdio>
#include <map>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.h"

namespace kiln::cli {
namespace {

std::string PassLine(const PassReport& p) {
    std::string line = "  pass \"" + p.pass + "\"";
    if (!p.light_mode.empty())
        line += " (LightMode " + p.light_mode + ")";
    line += ": " +
            (p.formula.find(" x ") == std::string::npos ? std::string() : p.formula + " = ") +
            std::to_string(p.permutations);
    if (p.variants != p.permutations)
        line += ", " + std::to_string(p.variants) + " after the shortcut rules and skip_variants";
    line += " variants";
    if (p.aliased > 0)
        line += " (" + std::to_string(p.aliased) + " stored as aliases)";
    return line + ", budget " + std::to_string(p.budget) + "\n";
}

void PrintText(const CompileOutput& out) {
    std::map<std::string, size_t> totals;
    for (const PassReport& p : out.passes)
        totals[p.shader] += p.variants;
    std::string shader;
    for (const PassReport& p : out.passes) {
        if (p.shader != shader) {
            shader = p.shader;
            std::printf("Shader \"%s\": %zu variants\n", shader.c_str(), totals[shader]);
        }
        std::printf("%s", PassLine(p).c_str());
    }
}

nlohmann::json Report(const CompileOutput& out, const DiagnosticList& diags) {
    nlohmann::ordered_json shaders = nlohmann::ordered_json::array();
    for (const PassReport& p : out.passes) {
        if (shaders.empty() || shaders.back()["name"] != p.shader)
            shaders.push_back(
                {{"name", p.shader}, {"variants", 0}, {"passes", nlohmann::json::array()}});
        auto& s = shaders.back();
        s["variants"] = s["variants"].get<size_t>() + p.variants;
        s["passes"].push_back({{"pass", p.pass},
                               {"light_mode", p.light_mode},
                               {"variants", p.variants},
                               {"permutations", p.permutations},
                               {"formula", p.formula},
                               {"aliased", p.aliased},
                               {"budget", p.budget}});
    }
    size_t warnings = 0;
    for (const Diagnostic& d : diags.all())
        warnings += d.severity == Severity::kWarning;
    return {{"kiln_lint", 1},
            {"shaders", shaders},
            {"errors", diags.error_count()},
            {"warnings", warnings},
            {"diagnostics", nlohmann::json::parse(FormatDiagnosticsJson(diags))}};
}

// --list-checks: the checks table (kiln/compile.h, ListChecks), as text or JSON.
int PrintChecks(bool json) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    std::string text = "check                 reads       runs    codes\n";
    for (const CheckInfo& c : ListChecks()) {
        std::string codes;
        nlohmann::json code_list = nlohmann::json::array();
        for (DiagCode code : c.codes) {
            codes += (codes.empty() ? "" : " ") + FormatDiagCode(code);
            code_list.push_back(FormatDiagCode(code));
        }
        list.push_back({{"name", c.name},
                        {"input", c.input},
                        {"when", c.when},
                        {"codes", code_list},
                        {"summary", c.summary}});
        char head[64];
        std::snprintf(head, sizeof head, "%-21s %-11s %-7s ", c.name.c_str(), c.input.c_str(),
                      c.when.c_str());
        text += head + codes + "\n" + std::string(22, ' ') + c.summary + "\n";
    }
    std::printf("%s", json ? (list.dump(2) + "\n").c_str() : text.c_str());
    return kExitOk;
}

}  // namespace

std::function<int()> AddLintCommand(CLI::App* cmd, const GlobalOptions& global) {
    struct Options {
        std::vector<std::string> files;
        CompilerFlags flags;
        bool json = false, no_cache = false, list_checks = false;
        std::string cache_dir;
    };
    auto o = std::make_shared<Options>();
    cmd->add_option("files", o->files, "ShaderLab files");
    cmd->add_flag("--list-checks", o->list_checks,
                  "Print every check: its name, what it reads, when it runs, its codes");
    AddCompilerOptions(*cmd, o->flags);
    cmd->add_option("--cache-dir", o->cache_dir, "Compile cache (default: the user cache folder)");
    cmd->add_flag("--no-cache", o->no_cache, "Do not read or write the compile cache");
    cmd->add_flag("--json", o->json,
                  "Print one JSON document on stdout: the counts and every diagnostic");
    cmd->footer(
        "-Werror fails the lint on any finding; -Wno-K7003, -Werror=K7011 and the groups "
        "(lint, lint-keywords, lint-state) choose per check (kiln --help)");
    return [o, &global]() {
        if (o->list_checks)
            return PrintChecks(o->json);
        if (o->files.empty()) {
            ReportError(global, DiagCode::kBadCommandLine, "",
                        "kiln lint needs at least one .shader file (or --list-checks)");
            return int(kExitUsageError);
        }
        DiagnosticList diags = global.NewDiagnostics();
        std::vector<std::unique_ptr<SourceFile>> material_files;
        CompileOptions options = ToCompileOptions(o->flags, material_files, diags);
        if (diags.has_errors()) {
            PrintDiagnostics(diags, Views(CompileOutput{}, material_files), global);
            return ExitCodeFor(diags);
        }
        options.cache_dir =
            o->no_cache ? "" : (o->cache_dir.empty() ? DefaultCacheDir() : o->cache_dir);
        const CompileOutput out = LintShaders(o->files, options, diags);
        diags.SortByPosition();
        if (o->json) {
            std::printf("%s\n", Report(out, diags).dump(2).c_str());
        } else {
            PrintText(out);
            std::fflush(stdout);  // the report, then the diagnostics, also when both are piped
            PrintDiagnostics(diags, Views(out, material_files), global);
        }
        return ExitCodeFor(diags);
    };
}

}  // namespace kiln::cli
