// State shared by the phases of one compile (driver-private).
#ifndef KILN_DRIVER_COMPILE_STATE_H_
#define KILN_DRIVER_COMPILE_STATE_H_

#include <array>
#include <atomic>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "driver/shader_passes.h"
#include "driver/surface_passes.h"
#include "frontend/glslang_messages.h"
#include "hlsl/file_cache.h"
#include "kiln/compile.h"
#include "kiln/pack/variant_key.h"
#include "kiln/shaderlab/ast.h"
#include "spirv/reflection.h"
#include "variants/alias_merge.h"
#include "variants/expand.h"
#include "variants/pass_pragmas.h"
#include "worker/executor.h"

namespace kiln::driver {

class Cache;
class DirectCache;
class ModuleStore;

struct ShaderUnit {
    std::shared_ptr<const SourceFile> file;
    std::optional<shaderlab::Shader> ast;
    std::vector<FlatPass> passes;
    bool emit = true;  // false: a stripped compile leaves the shader out of the pack
};

struct PassUnit {
    size_t shader = 0;
    size_t flat = 0;  // index into ShaderUnit::passes
    variants::PassPragmas pragmas;
    variants::Expansion expansion;
    // StageTask indices, variant-major: per variant one per stage of pragmas.Stages() (vertex,
    // fragment, then geometry, hull, domain where the program has them).
    std::vector<size_t> tasks;
    // pragmas.Stages().size(), without building the list (TaskOf is on every variant's path).
    size_t stride() const {
        return 2 + (pragmas.geometry ? 1 : 0) + (pragmas.hull && pragmas.domain ? 2 : 0);
    }
    size_t TaskOf(size_t variant, size_t stage_slot) const {
        return tasks[variant * stride() + stage_slot];
    }
    // A stripped compile's lookups of this pass, and those it does not build (requests.cpp).
    std::vector<const pack::UsageEntry*> requests;
    std::vector<variants::ExcludedRequest> excluded;
};

// One (variant, stage) of a pass.
struct StageTask {
    size_t pass = 0;
    pack::VariantKey key;
    pack::Stage stage = pack::Stage::kVertex;
    std::string reduced;    // preprocessed, rewritten (hlsl/rewrite.h), reduced to the entry point
    std::string rewritten;  // preprocessed and rewritten, kept only when a rewrite applied
    bool preprocess_ok = false;
    std::string preprocess_log;
    std::vector<std::string> functions_if_entry_missing;  // hlsl::Reduced's, for suggestions
    std::optional<Diagnostic> failure;  // preprocessing crashed, timed out, or was refused
    std::string result_key;             // the compile cache's key of `reduced` (CodeOf), once known
    bool direct = false;                // taken from the direct mode's manifest: not preprocessed
    size_t job = 0;
};

// One distinct reduced stage program.
struct Job {
    pack::Stage stage = pack::Stage::kVertex;
    std::string entry;
    size_t first_task = 0;
    std::string cache_key;
    bool ok = false;
    bool from_cache = false;
    bool done = false;  // compiled (or taken from the cache) as soon as it was preprocessed
    std::vector<uint32_t> words;    // optimized, before bindings
    std::vector<Diagnostic> diags;  // glslang errors/warnings, or internal errors
};

// A module as it goes into the pack: bindings applied, reflected, stripped, validated.
struct FinalModule {
    bool ok = false;
    std::vector<uint32_t> words;
    spirv::Reflection reflection;
    std::string error;
    bool internal = false;              // `error` is Kiln's fault (K9001), not the program's
    std::optional<Diagnostic> failure;  // the worker crashed or ran out of time or memory
};

struct CompileState {
    const CompileOptions& options;
    DiagnosticList& diags;
    worker::Executor* exec = nullptr;  // where glslang and SPIRV-Tools run (driver/isolation.h)
    hlsl::FileCache files;
    // The text generated for surface shaders (driver/surface_passes.h), which `#line` names.
    std::vector<GeneratedSource> generated;
    std::vector<ShaderUnit> shaders;
    // Shaders read only for the passes a UsePass copies (driver/use_pass.h); a deque, so the
    // units' addresses hold.
    std::deque<ShaderUnit> libraries;
    std::vector<PassUnit> passes;
    std::vector<StageTask> tasks;
    std::vector<Job> jobs;
    // Per pass: (job index -> final module), filled by the binding phase.
    std::vector<std::map<size_t, FinalModule>> finals;
    // Keyword aliases the pack records (EmitPack): (pass index, alias).
    std::vector<std::pair<size_t, variants::KeywordAlias>> aliases;
    // The cache's direct mode (null without a cache) and each task's direct key.
    std::shared_ptr<DirectCache> direct;
    std::vector<std::string> direct_keys;
    // The cache's modules (null without a cache), written by one Flush after the compile phase.
    std::shared_ptr<ModuleStore> modules;
    // Nanoseconds inside worker requests, by worker::RequestKind (CompileStats::work_ms).
    std::array<std::atomic<uint64_t>, 8> work_ns{};
};

// The entry point of a task's stage.
const std::string& EntryOf(const CompileState& st, const StageTask& t);
// The path of a task's shader.
const std::string& ShaderOf(const CompileState& st, const StageTask& t);
// glslang's info log as Kiln diagnostics (positions resolved against the files read). `program`,
// when given, is the text compiled (its identifiers feed suggestions).
void AppendGlslangLog(CompileState& st,
                      const std::string& log,
                      std::vector<Diagnostic>& out,
                      const std::string* program = nullptr);
// The same for messages parsed already (frontend::ParseInfoLog).
// `unreduced`, when given, is the program before reduction (its functions feed the suggestion for
// an unknown function). `task`, when given, is the one `program` was reduced for: the suggestion
// for an unknown name then reads its text reduced again with every declaration kept (those the
// reduction dropped, a cbuffer's members among them, are names the program could have meant).
void AppendMessages(CompileState& st,
                    const std::vector<frontend::GlslangMessage>& messages,
                    std::vector<Diagnostic>& out,
                    const std::string* program = nullptr,
                    const std::string* unreduced = nullptr,
                    const StageTask* task = nullptr);
inline void Progress(const CompileOptions& o, const char* phase, size_t done, size_t total) {
    if (o.progress)
        o.progress(phase, done, total);
}

// Phase 2 (expand_passes.cpp): pragmas and variant keys of every pass, then a StageTask per
// (variant, stage) with its assembled source. ReadPass reads one flattened pass's pragmas
// (nullopt after reporting errors).
std::optional<PassUnit> ReadPass(CompileState& st, size_t shader, size_t flat);
void ExpandPasses(CompileState& st);
void CreateTasks(CompileState& st);
// A task's assembled source (hlsl/assemble.h), built each time it is needed: the sources of all
// tasks at once would be most of a large compile's memory.
std::string SourceOf(const CompileState& st, const StageTask& t);

// Phase 2 of a stripped compile or a skeleton pack (requests.cpp): every pass of a kept shader
// expands exactly its requested variants (none for a skeleton).
void ExpandRequestedPasses(CompileState& st, bool skeleton);
// The stripped compile's report: kept and excluded variants with who asked, shaders left out.
void FillStripReport(const CompileState& st, CompileOutput& out);

// Phase 3 (preprocess.cpp). LookUpDirect: each task's result key from the direct mode's
// manifest (driver/direct_cache.h), where nothing it read changed; true when every task has one.
// PreprocessAndDedup: every other task preprocessed in the workers (and recorded in a manifest),
// then the tasks deduplicated by result key into jobs; jobs whose SPIR-V the cache holds are
// loaded (validated). DedupKnown: only the dedup, for a pack taken whole from the cache.
bool LookUpDirect(CompileState& st);
// With `compile`, each new program is compiled (or taken from the cache) by the thread that
// preprocessed it, right away, and its texts dropped when the compile said nothing: texts never
// wait for a whole phase, so memory does not grow with the unique programs. The job's outcome is
// the one CompileJobs would give: a program with messages is compiled again from the first task
// of its key when another task got there first (positions in messages are that task's).
void PreprocessAndDedup(CompileState& st, CompileStats& stats, bool compile);
void DedupKnown(CompileState& st, CompileStats& stats);

// The whole pack in the cache (pack_cache.cpp): its key (empty unless every task's result key is
// known), a pack that opens (its stored warnings reported again into st.diags), and storing one
// with the warnings from `first_warning` on (those of the steps a hit skips).
std::string PackKey(const CompileState& st);
std::optional<std::vector<uint8_t>> LoadCachedPack(const CompileState& st, CompileStats& stats);
void StoreCachedPack(const CompileState& st,
                     const CompileStats& stats,
                     const std::vector<uint8_t>& pack,
                     size_t first_warning);

// Phase 4, in compile_jobs.cpp: compile each job (or take it from the cache).
void CompileJobs(CompileState& st, CompileStats& stats);
// A job's SPIR-V from the cache (once validated), else compiled from its first task's texts by
// glslang and SPIRV-Tools and stored (diagnostics to job.diags). True when it was compiled.
// The module is stored under the file name of its first task's shader (driver/module_store.h).
bool CompileOrLoad(CompileState& st, Job& job);
// A module of the cache, once spirv-val accepts it (a damaged or forged entry is a miss); looked
// for first among the modules of `shader`'s file name.
std::optional<std::vector<uint32_t>> LoadCached(CompileState& st,
                                                const std::string& key,
                                                const std::string& shader);

// Phases implemented in pack_emit.cpp.
void FinishModules(CompileState& st);  // bindings, reflection, strip, validate
std::vector<uint8_t> EmitPack(CompileState& st, CompileStats& stats);
// "shader "S" pass "P", variant A B" for a diagnostic about one variant of pass `p`.
std::string VariantName(const CompileState& st, size_t p, pack::VariantKey key);
// The final module of pass `p` that `task` compiled.
const FinalModule& FinalFor(const CompileState& st, size_t p, size_t task);

// Reports errors shared by many variants once each (error_merge.cpp).
void ReportJobDiagnostics(CompileState& st);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_COMPILE_STATE_H_
