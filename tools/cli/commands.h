// The kiln CLI (library kiln_cli, and kiln_cli_render for the commands that link the renderer):
// the commands' Add functions, each filling its CLI11 subcommand and returning what runs after
// parsing, and the driver both programs run over the one command table (command_list.h).
#ifndef KILN_TOOLS_KILN_COMMANDS_H_
#define KILN_TOOLS_KILN_COMMANDS_H_

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "kiln/compile.h"
#include "kiln/diagnostic.h"
#include "kiln/material/material.h"
#include "kiln/pack/reader.h"

namespace kiln::cli {

struct GlobalOptions;

// The program that runs a command: kiln, or kiln-render (the commands that link the renderer).
enum class Binary { kKiln, kKilnRender };
using AddCommandFn = std::function<int()> (*)(CLI::App* cmd, const GlobalOptions& global);
// One row of the command table (command_list.h); `add` is null in the program that does not run
// the command.
struct Command {
    std::string_view name;
    std::string_view summary;
    Binary binary;
    AddCommandFn add;
};
// The driver: global options, -W, the table's subcommands, then the chosen command. kiln hands a
// kiln-render command to kiln-render beside it (K0025 when it cannot be run).
int RunCli(int argc, char** argv, Binary self, const std::vector<Command>& table);

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
    bool color = false;      // --color, resolved: ANSI colours in text diagnostics
    WarningPolicy warnings;  // the -W options, in order
    // An empty list under the -W options: every command reports into one.
    DiagnosticList NewDiagnostics() const { return DiagnosticList(warnings); }
};

// Prints diagnostics to stderr in the chosen format.
void PrintDiagnostics(const DiagnosticList& diags,
                      const std::vector<const SourceFile*>& sources,
                      const GlobalOptions& global);
int ExitCodeFor(const DiagnosticList& diags);
// A command's diagnostics, printed once when it ends (kiln test, report, stability).
struct CommandDiagnostics {
    explicit CommandDiagnostics(const GlobalOptions& g) : global(g), diags(g.NewDiagnostics()) {}
    const GlobalOptions& global;
    DiagnosticList diags;
    // Prints them; returns `code`.
    int Finish(int code) {
        PrintDiagnostics(diags, {}, global);
        return code;
    }
    // Adds `e` (at `file`) and finishes as an input error.
    int Fail(const kiln::Error& e, const std::string& file = "") {
        diags.Error(e.code, file, kNoPosition, e.message);
        return Finish(int(kExitInputError));
    }
};

// One error without a source position (a command-line value, a pack, a scene), printed in the
// chosen format; returns its exit code.
int ReportError(const GlobalOptions& global,
                DiagCode code,
                const std::string& file,
                const std::string& message);

// Maps and opens a pack, or reports why not (K0004) and returns false.
bool OpenPack(const std::string& path,
              pack::MappedFile& file,
              pack::Pack& pack,
              const GlobalOptions& global);

// One variant of a pack by name (kiln extract, kiln show): --shader, --pass, --keywords.
struct VariantName {
    std::string shader, pass;
    std::vector<std::string> keywords;
};
void AddVariantNameOptions(CLI::App& cmd, VariantName& name);
// The pass `name` means in `pack` (read from `file`), its keywords checked against the pass's;
// what does not resolve is reported (K0005 with the closest names, K4015) and gives nullopt.
std::optional<uint32_t> ResolvePass(const pack::Pack& pack,
                                    const std::string& file,
                                    const VariantName& name,
                                    const GlobalOptions& global);
// The same, then the variant (K0006 when the pack does not hold it).
std::optional<pack::VariantRec> ResolveVariant(const pack::Pack& pack,
                                               const std::string& file,
                                               const VariantName& name,
                                               const GlobalOptions& global);

// --stage of kiln extract and kiln show: vert, frag (or vertex, fragment), geometry, hull,
// domain.
void AddStageOption(CLI::Option* option);
pack::Stage StageOf(const std::string& option);
// The module of `variant` at `stage`; where it has none, an error naming the stages it has
// (K0006) and nullopt.
std::optional<uint32_t> ModuleAt(const pack::Pack& pack,
                                 const pack::VariantRec& variant,
                                 pack::Stage stage,
                                 const std::string& file,
                                 const GlobalOptions& global);

// Flags shared by `compile` and `variants`.
struct CompilerFlags {
    std::vector<std::string> include_dirs;
    std::string project_root;
    std::vector<std::string> defines;
    std::vector<std::string> undefines;
    std::vector<std::string> forced_includes;
    std::string unity_version;
    std::string precision;  // --precision; empty: the --unity-version release's
    std::vector<std::string> keywords;
    std::vector<std::string> materials;  // .material files and <scene>.kiln.json sidecars
    bool all_features = false;
    bool strict_variants = false;
    uint64_t max_variants = 4096;
    std::string templates_dir;
    unsigned jobs = 0;
    bool in_process = false;
    double program_timeout = 60;
    uint64_t program_memory = 2048;
};
// With `variant_choice` false (kiln show), the options that choose which variants to build
// (--materials, --keywords, --all-features, --max-variants) are left out.
void AddCompilerOptions(CLI::App& cmd, CompilerFlags& flags, bool variant_choice = true);
// The library's options from the flags; reads the --materials files (kept in `files` for the
// diagnostics that point into them). Problems go to `diags`.
CompileOptions ToCompileOptions(const CompilerFlags& flags,
                                std::vector<std::unique_ptr<SourceFile>>& files,
                                DiagnosticList& diags);
// "2022.3" -> 202230 (UNITY_VERSION: major x 100 + minor x 10 + patch, patch capped at 9), or a
// plain number; nullopt when it is neither.
std::optional<int> ParseUnityVersion(const std::string& text);
std::vector<const SourceFile*> Views(const CompileOutput& out,
                                     const std::vector<std::unique_ptr<SourceFile>>& more = {});

// kiln-render beside this program; a shipped pack (../share/kiln/NAME when installed,
// ../materials/NAME in the build tree): materials.kpack, or materials-half.kpack (the same shaders
// compiled with --precision half).
std::string RenderToolPath();
inline constexpr const char* kShippedPack = "materials.kpack";
inline constexpr const char* kShippedHalfPack = "materials-half.kpack";
std::string ShippedPackPath(const std::string& name = kShippedPack);
// The demo scene (scenes/demo/demo.gltf) of the source tree kiln was built from; empty when it
// is not there (an installed kiln).
std::string DemoScenePath();

// Scene-driven stripping for kiln compile (scene_strip.cpp): --scene, --usage, --path,
// --pixel-lights, --explain, --verify-scene.
struct SceneStripFlags {
    std::vector<std::string> scenes, usage_files;
    std::string path = "forward";
    uint32_t pixel_lights = 4;
    std::string light_mode = "auto";
    std::string shadows = "off";
    bool explain = false, explain_json = false, verify = false;
    bool active() const { return !scenes.empty() || !usage_files.empty(); }
};
void AddSceneStripOptions(CLI::App& cmd, SceneStripFlags& flags);
// The files scene-driven stripping reads: usage files, scenes and the buffers and images each
// scene's uris name, the sidecars (`sidecars`, else the one beside each scene) and the .material
// files they map (kiln-render reads those in the dry runs), for the output-safety check.
std::vector<std::string> SceneStripInputs(const SceneStripFlags& flags,
                                          const std::vector<std::string>& sidecars);
// Fills options.requests from the usage files and a dry run of each scene (kiln-render) over a
// pack of the shaders without variants; `sidecars` are --materials. False after errors.
bool PlanRequests(const SceneStripFlags& flags,
                  const std::vector<std::string>& shaders,
                  const std::vector<std::string>& sidecars,
                  CompileOptions& options,
                  DiagnosticList& diags);
// --verify-scene: each scene's dry run against the stripped pack; every lookup it misses is a
// K4019 error. False after errors.
bool VerifyScenes(const SceneStripFlags& flags,
                  const std::vector<uint8_t>& pack,
                  const std::vector<std::string>& sidecars,
                  DiagnosticList& diags);
// --explain / --explain-json on stdout: what was kept and why, what was left out, and what that
// saved, given the compile's wall time and the size of the same pack without variants.
void PrintExplain(const SceneStripFlags& flags,
                  const CompileOutput& out,
                  double seconds,
                  size_t skeleton_bytes);

// Each registers its subcommand; the returned function runs it.
std::function<int()> AddParseCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddCompileCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddVariantsCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddWatchCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddLintCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddDiffCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddInfoCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddExtractCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddShowCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddValidateCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddNewCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddRenderCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddTestCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddReportCommand(CLI::App* cmd, const GlobalOptions& global);
std::function<int()> AddStabilityCommand(CLI::App* cmd, const GlobalOptions& global);

}  // namespace kiln::cli

#endif  // KILN_TOOLS_KILN_COMMANDS_H_
