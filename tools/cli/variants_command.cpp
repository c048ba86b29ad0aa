// kiln variants A.shader...: keyword sets, variant counts and what deduplication leaves to compile.
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.h"

namespace kiln::cli {

std::function<int()> AddVariantsCommand(CLI::App* cmd, const GlobalOptions& global) {
    struct Options {
        std::vector<std::string> files;
        CompilerFlags flags;
        bool json = false;
    };
    auto o = std::make_shared<Options>();
    cmd->add_option("files", o->files, "ShaderLab files")->required();
    AddCompilerOptions(*cmd, o->flags);
    cmd->add_flag("--json", o->json, "Print JSON");

    return [o, &global]() {
        DiagnosticList diags = global.NewDiagnostics();
        std::vector<std::unique_ptr<SourceFile>> material_files;
        const CompileOptions options = ToCompileOptions(o->flags, material_files, diags);
        if (diags.has_errors()) {
            PrintDiagnostics(diags, Views(CompileOutput{}, material_files), global);
            return ExitCodeFor(diags);
        }
        CompileOutput out = AnalyzeVariants(o->files, options, diags);
        if (o->json) {
            nlohmann::json passes = nlohmann::json::array();
            for (const PassReport& p : out.passes) {
                nlohmann::json sets = nlohmann::json::array();
                for (const KeywordSetReport& s : p.sets) {
                    sets.push_back({{"pragma", s.pragma},
                                    {"keywords", s.keywords},
                                    {"shader_feature", s.shader_feature},
                                    {"stage", s.stage}});
                }
                passes.push_back({{"shader", p.shader},
                                  {"pass", p.pass},
                                  {"light_mode", p.light_mode},
                                  {"keyword_sets", sets},
                                  {"permutations", p.permutations},
                                  {"variants", p.variants},
                                  {"profile_stripped", p.profile_stripped},
                                  {"profile_keywords", p.profile_keywords},
                                  {"unique_vertex", p.unique_vertex},
                                  {"unique_fragment", p.unique_fragment}});
            }
            const CompileStats& s = out.stats;
            nlohmann::json j = {{"passes", passes},
                                {"total",
                                 {{"permutations", s.permutations},
                                  {"variants", s.variants},
                                  {"stage_programs", s.stage_programs},
                                  {"unique_programs", s.unique_programs}}}};
            std::printf("%s\n", j.dump(2).c_str());
        } else {
            for (const PassReport& p : out.passes) {
                std::printf(
                    "Shader \"%s\" pass %s%s\n", p.shader.c_str(), p.pass.c_str(),
                    p.light_mode.empty() ? "" : (" (LightMode " + p.light_mode + ")").c_str());
                std::string formula;
                for (const KeywordSetReport& s : p.sets) {
                    std::string words;
                    for (const std::string& k : s.keywords)
                        words += " " + (k.empty() ? "_" : k);
                    std::printf("  %s:%s\n", s.pragma.c_str(), words.c_str());
                }
                std::printf(
                    "  %llu permutations, %zu variants; unique programs: vertex %zu, "
                    "fragment %zu\n",
                    static_cast<unsigned long long>(p.permutations), p.variants, p.unique_vertex,
                    p.unique_fragment);
                if (p.profile_stripped > 0) {
                    std::string words;
                    for (const std::string& k : p.profile_keywords)
                        words += (words.empty() ? "" : " ") + k;
                    std::printf(
                        "  %llu more left out by the default stripping profile (%s; "
                        "--strict-variants builds them)\n",
                        static_cast<unsigned long long>(p.profile_stripped), words.c_str());
                }
            }
            const CompileStats& s = out.stats;
            std::printf("total: %zu variants, %zu stage programs, %zu unique compiles\n",
                        s.variants, s.stage_programs, s.unique_programs);
        }
        PrintDiagnostics(diags, Views(out, material_files), global);
        return ExitCodeFor(diags);
    };
}

}  // namespace kiln::cli
