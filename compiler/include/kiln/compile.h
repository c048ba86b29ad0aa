// The variant compiler: .shader files in, a variant pack out (docs/pack-format.md). Every keyword
// permutation of every pass is assembled (prelude + include blocks + program, with #line),
// preprocessed, reduced to what each stage's entry point reaches, and each distinct stage text is
// compiled once: glslang (HLSL, DX9-compatible), SPIRV-Tools legalize/optimize, bindings from
// docs/binding-model.md, SPIRV-Cross reflection, spirv-val. Results are cached by content.
#ifndef KILN_COMPILE_H_
#define KILN_COMPILE_H_

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/variant_selector.h"
#include "kiln/source.h"

namespace kiln {

// One material instance's part in the shader_feature combinations (CompileOptions::materials).
struct MaterialRequest {
    std::set<std::string> keywords;        // its "keywords"
    std::map<std::string, double> values;  // its scalar property values
};

using pack::Precision;  // --precision full|relaxed|half

// -O0, -O (Kiln's pass list), -Os, -O with SPIRV-Tools' own list (--perf-passes spirv-tools).
enum class OptimizationLevel { kNone, kPerformance, kSize, kPerformanceSpirvTools };

// Where glslang and SPIRV-Tools run: in `kiln-worker` processes (the default: a crash, a hang or
// an exhausted allocation in them becomes a diagnostic) or inside the calling process
// (--in-process, for debugging).
enum class Isolation { kWorkers, kInProcess };

// Unity 2022.3: the UNITY_VERSION Kiln's compile environment reproduces by default
// (docs/unity-compat.md).
inline constexpr int kDefaultUnityVersion = 202230;

// What half and fixed are when --precision is not given, as that Unity release's Vulkan back end
// makes them on desktop: relaxed (min16float) before 2019.1, full (32-bit) from it.
pack::Precision DefaultPrecisionFor(int unity_version);

struct CompileOptions {
    std::vector<std::string> include_dirs;                     // -I, searched in order
    std::vector<std::pair<std::string, std::string>> defines;  // -D NAME[=VALUE]
    std::vector<std::string> undefines;  // -U NAME: predefined macros left undefined
    // --include FILE: included into every program after Unity's implicit includes.
    std::vector<std::string> forced_includes;
    int unity_version = kDefaultUnityVersion;  // UNITY_VERSION (--unity-version 2022.3)
    std::string templates_dir;  // the built-in include library; empty: DefaultTemplatesDir()
    OptimizationLevel opt_level = OptimizationLevel::kPerformance;
    bool debug_info = false;                 // -g: keep names and debug info in the SPIR-V
    Precision precision = Precision::kFull;  // --precision: what half and fixed are
    // Store a keyword whose variants duplicate another keyword's as an alias of it (pack format
    // 1.1); false (--no-keyword-aliases) stores every variant, for readers of format 1.0.
    bool keyword_aliases = true;
    unsigned jobs = 0;  // 0: all cores
    // shader_feature variants, as in Unity: the all-off combination plus one combination per
    // material instance of the shader (keyed by shader name), plus `keywords` (--keywords) for
    // every shader; or, with all_features (--all-features), every combination. A material's
    // combination is its keywords and those its values of [Toggle]/[ToggleOff]/[KeywordEnum]
    // properties enable (unset properties: their defaults).
    std::map<std::string, std::vector<MaterialRequest>> materials;
    std::optional<std::set<std::string>> keywords;
    bool all_features = false;
    // Every multi_compile combination (--strict-variants). Default: Unity's stripping of engine
    // keywords no scene uses (lightmap modes, fog modes, instancing: variants/strip_profile.h),
    // as a Unity build with Graphics Settings at their defaults; --scene strips by lookups.
    bool strict_variants = false;
    // Per pass; a pass (or its SubShader) tagged "KilnMaxVariants" = "N" has the smaller of both.
    uint64_t max_variants = 4096;
    std::string cache_dir;  // empty: no cache
    Isolation isolation = Isolation::kWorkers;
    std::string worker_path;  // empty: $KILN_WORKER, else kiln-worker beside the program
    // Per program (one stage of one variant, or its preprocessing), in a worker: the wall-clock
    // limit (--program-timeout) and the resident-memory limit (--program-memory).
    double program_timeout_seconds = 60;
    uint64_t program_memory_mib = 2048;
    // Scene-driven stripping (kiln compile --scene, --usage): when set, every pass builds exactly
    // the variants these lookups ask for (matched by shader name and pass name, keywords mapped
    // as the runtime maps them), and a shader that is neither looked up nor used by one of the
    // log's materials is left out of the pack. Passes keep their records (so pass names stay
    // the same) with only the requested variants. The product of a pass's keyword sets is never
    // enumerated. shader_feature narrowing, --keywords and --all-features do not apply.
    std::optional<pack::UsageLog> requests;
    // Keep the text glslang compiles of every distinct stage program (CompileOutput::programs):
    // kiln show --hlsl and kiln compile -E. Set cache_dir empty with it: a program the cache's
    // direct mode knows is not preprocessed, so it has no text.
    bool keep_programs = false;
    // Called from the driver thread as work completes (phase, done, total).
    std::function<void(const char*, size_t, size_t)> progress;
};

struct CompileStats {
    uint64_t permutations = 0;      // product of keyword-set sizes, all passes
    size_t variants = 0;            // after shader_feature narrowing and skip_variants
    uint64_t profile_stripped = 0;  // left out by the default stripping profile, all passes
    size_t stage_programs = 0;      // variants x 2 stages
    size_t unique_programs = 0;     // distinct reduced stage texts (what dedup leaves)
    size_t glslang_compiles = 0;    // unique programs compiled by glslang in this run
    size_t cache_hits = 0;          // unique programs taken from the cache
    // Stage programs not preprocessed: the cache's direct mode knew their result (every file
    // they read unchanged) and held its SPIR-V.
    size_t direct_hits = 0;
    // Stage programs not preprocessed on their own: another one of the same shader, stage and
    // entry point had the same assembled text (variants differing only in the other stage's
    // keywords), or the variant's vertex preprocess served it (nothing read tests the stage).
    size_t shared_preprocesses = 0;
    size_t modules = 0;  // distinct SPIR-V modules in the pack
    // Variants not stored because their keyword is an alias of another (identical SPIR-V in
    // both stages): lookups of them find the other keyword's variants.
    size_t aliased_variants = 0;
    // Wall-clock milliseconds of each phase of this run (kiln compile --stats): reading, parsing
    // and checking the shaders; expanding variants into stage programs; preprocessing and
    // reducing them to their entry points, and deduplicating (in the workers); glslang and
    // SPIRV-Tools on the unique programs, or the cache; bindings, reflection and validation;
    // building the pack's bytes. Phases that did not run are 0.
    struct Phases {
        double load = 0, expand = 0, preprocess = 0, compile = 0, finish = 0, emit = 0, total = 0;
    } ms;
    // Milliseconds inside worker requests of each kind, summed over the parallel jobs:
    // preprocessing (glslang's preprocessor, Kiln's rewrites and reduction), compiling (glslang
    // and SPIRV-Tools on the unique programs; validating cache entries), finishing (strip and
    // spirv-val). A program compiles as soon as it is preprocessed, so the phases of `ms`
    // overlap; these say where the work went.
    struct Work {
        double preprocess = 0, compile = 0, finish = 0;
    } work_ms;
    // Peak resident memory in KiB of this process and of the largest worker process (0 with
    // --in-process), from getrusage.
    uint64_t peak_rss_kib = 0, peak_worker_rss_kib = 0;
};

struct KeywordSetReport {
    std::string pragma;                 // "multi_compile", "shader_feature_local", ...
    std::vector<std::string> keywords;  // "" = no keyword
    bool shader_feature = false;
    std::string stage;  // "", "vertex" or "fragment"
};

// A variant a stripped compile (CompileOptions::requests) built or left out, and who asked.
struct RequestedVariantReport {
    std::vector<std::string> keywords;
    std::vector<std::string> requested_by;  // from the lookups (kiln/pack/variant_selector.h)
    uint64_t requesters = 0;
    std::string excluded_because;  // set when it was asked for but is not built
};

struct PassReport {
    std::string shader;
    std::string pass;  // "FORWARD" or "#2" when unnamed
    std::string light_mode;
    std::vector<KeywordSetReport> sets;
    uint64_t permutations = 0;  // saturates at UINT64_MAX
    std::string formula;        // the product as written: "3 x 2 x 4 shader_feature combinations"
    uint64_t budget = 0;        // the most variants the pass may have (--max-variants, its tag)
    size_t variants = 0;
    size_t aliased = 0;  // of `variants`, those stored as another keyword's (an alias)
    // Variants the default stripping profile left out (CompileOptions::strict_variants), and
    // the keywords it stripped.
    uint64_t profile_stripped = 0;
    std::vector<std::string> profile_keywords;
    size_t unique_vertex = 0, unique_fragment = 0;
    // Stripped compiles: the variants built (in key order) and those asked for but not built.
    std::vector<RequestedVariantReport> kept, excluded;
};

// What a stripped compile left out beyond variants.
struct StripReport {
    bool active = false;                        // CompileOptions::requests was set
    std::vector<std::string> shaders_left_out;  // no lookup and no material use them
    // Lookups of shaders that are not in this compile (another pack's): (shader, count).
    std::vector<std::pair<std::string, size_t>> other_shaders;
};

// One distinct stage program's text as glslang compiles it (CompileOptions::keep_programs):
// preprocessed, rewritten for glslang and reduced to what the entry point reaches, with #line
// directives back to the .shader and its includes.
struct ProgramText {
    std::string shader;
    std::string pass;                   // its label, as kiln info names it
    std::vector<std::string> keywords;  // of the first variant that has this text
    pack::Stage stage = pack::Stage::kVertex;
    std::string entry;    // the entry point
    size_t variants = 1;  // stage programs of this pass with the same text
    std::string text;
};

struct CompileOutput {
    bool ok = false;
    std::vector<ProgramText> programs;  // CompileOptions::keep_programs, in task order
    std::vector<uint8_t> pack;          // empty unless ok and a pack was requested
    CompileStats stats;
    std::vector<PassReport> passes;
    StripReport strip;
    // Every file read (shaders and includes), for diagnostics output and depfiles.
    std::vector<std::shared_ptr<const SourceFile>> files;
    // The ShaderLab generated for surface shaders, one per `#pragma surface`, named
    // "<shader> (generated)" (no file of that name exists; diagnostics in generated code name
    // it, and kiln compile --emit-generated writes it).
    std::vector<std::shared_ptr<const SourceFile>> generated;
};

// Compiles to a pack. Diagnostics go to `diags`; `ok` is false when there are errors.
CompileOutput CompileShaders(const std::vector<std::string>& paths,
                             const CompileOptions& options,
                             DiagnosticList& diags);

// Everything up to deduplication, without compiling: keyword sets, counts, unique programs.
CompileOutput AnalyzeVariants(const std::vector<std::string>& paths,
                              const CompileOptions& options,
                              DiagnosticList& diags);

// A pack of the shaders' passes, tags, render state, keyword sets and Properties without any
// variant (nothing is compiled): what a planner needs to know which variants a scene will look
// up (kiln render --dry-run, for kiln compile --scene). `pack` holds it when `ok`.
CompileOutput BuildSkeletonPack(const std::vector<std::string>& paths,
                                const CompileOptions& options,
                                DiagnosticList& diags);

// One of the compiler's checks over a finished input (docs/diagnostics.md, "Checks"): its name,
// the codes it reports, what it reads (ast, programs, reflection, pack), when it runs (always, or
// lint) and what it finds. `kiln lint --list-checks` prints them.
struct CheckInfo {
    std::string name;
    std::vector<DiagCode> codes;
    std::string input, when, summary;
};
std::vector<CheckInfo> ListChecks();

// kiln lint: compiles every variant of every pass (every shader_feature combination, within the
// variant budgets) and reports, as K7xxx warnings at the pragma, property or pass concerned, what
// the keywords cost and where they are wasted (docs/variants.md, "Lint"); the compile's own
// diagnostics come too. The PassReports hold each pass's variant count, the product that made it
// and its budget; `pack` the pack the checks read.
CompileOutput LintShaders(const std::vector<std::string>& paths,
                          const CompileOptions& options,
                          DiagnosticList& diags);

// The templates/ directory this build of Kiln uses: $KILN_TEMPLATES_DIR, else the source tree's.
std::string DefaultTemplatesDir();
// $KILN_CACHE_DIR, else $XDG_CACHE_HOME/kiln, else $HOME/.cache/kiln; empty if none is set.
std::string DefaultCacheDir();
// "kiln 0.2.0; glslang 12.0.0; SPIRV-Tools v2023.1".
std::string ProducerVersion();

}  // namespace kiln

#endif  // KILN_COMPILE_H_
