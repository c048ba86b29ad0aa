// Phase 4 of the compile driver: each unique program compiled by glslang and SPIRV-Tools in a
// worker (or taken from the cache once spirv-val accepts the entry), and glslang's messages
// turned into diagnostics.
#include <atomic>
#include <optional>
#include <regex>
#include <set>

#include "driver/cache.h"
#include "driver/compile_state.h"
#include "driver/isolation.h"
#include "driver/module_store.h"
#include "driver/parallel.h"
#include "frontend/glslang_messages.h"
#include "hlsl/identifier.h"
#include "hlsl/unity_versions.h"
#include "kiln/pack/names.h"

namespace kiln::driver {
namespace {

// The names the program declares as functions (`type name(` where the type is a word other than
// a statement keyword), for an unknown function's message.
std::vector<std::string> FunctionNames(const std::string& text) {
    static const std::regex kDeclaration(R"(\b([A-Za-z_]\w*)\s+([A-Za-z_]\w*)\s*\()");
    static const std::set<std::string> kNotTypes = {"return", "else", "case", "new", "delete",
                                                    "throw",  "do",   "in",   "out", "inout"};
    std::set<std::string> names;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), kDeclaration);
         it != std::sregex_iterator(); ++it) {
        if (!kNotTypes.count((*it)[1].str()))
            names.insert((*it)[2].str());
    }
    return {names.begin(), names.end()};
}

// The distinct identifiers of a program text, for "did you mean" on an unknown name.
std::vector<std::string> Identifiers(const std::string& text) {
    std::set<std::string> names;
    for (size_t i = 0; i < text.size();) {
        if (hlsl::IdentStart(text[i]) && (i == 0 || !hlsl::IdentChar(text[i - 1]))) {
            size_t j = i;
            while (j < text.size() && hlsl::IdentChar(text[j]))
                ++j;
            names.insert(text.substr(i, j - i));
            i = j;
        } else {
            ++i;
        }
    }
    return {names.begin(), names.end()};
}

// The `#pragma vertex|fragment` of a stage whose function does not exist, with the closest name.
Diagnostic MissingEntryPoint(const CompileState& st, const StageTask& t) {
    const auto& pr = st.passes[t.pass].pragmas;
    const variants::EntryPoint& e = *pr.Entry(t.stage);
    Diagnostic d{Severity::kError,
                 DiagCode::kEntryPointNotFound,
                 st.shaders[st.passes[t.pass].shader].file->path(),
                 e.range,
                 std::string(pack::StageName(t.stage)) + " entry point '" + e.name +
                     "' is not a function of this program",
                 {}};
    d.message += pack::DidYouMean(e.name, t.functions_if_entry_missing);
    return d;
}

// The messages of a variant's own program (reduced to what its entry point reaches), each placed
// by the unreduced compile's message on the same line where there is one (the reduced text is
// preprocessed: its lines are the files' own, its columns are not). glslang stops at the first
// errors of a text, and the unreduced text may fail first in a function nothing calls: those are
// not the variant's errors and are dropped. Without reduced messages, the unreduced ones.
std::vector<frontend::GlslangMessage> OwnMessages(const std::string& reduced_log,
                                                  const std::string& exact_log) {
    const std::vector<frontend::GlslangMessage> exact = frontend::ParseInfoLog(exact_log);
    std::vector<frontend::GlslangMessage> own = frontend::ParseInfoLog(reduced_log);
    if (own.empty())
        return exact;
    for (frontend::GlslangMessage& m : own) {
        const frontend::GlslangMessage* placed = nullptr;
        for (const frontend::GlslangMessage& e : exact) {
            if (e.file == m.file && e.line == m.line && e.severity == m.severity &&
                (placed == nullptr || (e.text == m.text && placed->text != m.text)))
                placed = &e;
        }
        if (placed != nullptr && placed->text == m.text)
            m = *placed;
        else
            m.column = 0;  // the line is right; a column in preprocessed text would not be
    }
    return own;
}

// One job through glslang and SPIRV-Tools in a worker; its diagnostics go to job.diags.
void CompileJob(CompileState& st, Job& job) {
    const StageTask& task = st.tasks[job.first_task];
    const std::string& main = st.shaders[st.passes[task.pass].shader].file->path();
    worker::Request request = StageRequest(st, task, worker::RequestKind::kCompile);
    request.source = task.reduced;
    worker::Outcome o = st.exec->Run(request);
    if (auto failure = OutcomeDiagnostic(st, task, o)) {
        job.diags.push_back(std::move(*failure));
        return;
    }
    const worker::Response& out = o.response;
    if (out.entry_missing) {
        job.diags.push_back(MissingEntryPoint(st, task));
        return;
    }
    if (out.failed_in == worker::Component::kGlslang) {
        // Positions in the reduced text are lines of the original files but not their columns:
        // compile the assembled source once more for exact diagnostics (or, when a rewrite was
        // needed, the rewritten text, whose lines are right).
        const std::string reduced_log = out.info_log;
        request.source = task.rewritten.empty() ? SourceOf(st, task) : task.rewritten;
        request.optimize = false;
        o = st.exec->Run(request);
        if (auto failure = OutcomeDiagnostic(st, task, o)) {
            job.diags.push_back(std::move(*failure));
            return;
        }
        AppendMessages(st, OwnMessages(reduced_log, o.response.info_log), job.diags, &task.reduced,
                       &request.source, &task);
        if (o.response.ok || job.diags.empty()) {
            job.diags.push_back({Severity::kInternal,
                                 DiagCode::kInternalError,
                                 main,
                                 {},
                                 "stage compiles from its source but not after reduction to its "
                                 "entry point",
                                 {}});
        }
        return;
    }
    AppendGlslangLog(st, out.info_log, job.diags);  // warnings
    if (!out.ok) {
        job.diags.push_back({Severity::kError,
                             DiagCode::kSpirvInvalid,
                             main,
                             {},
                             "SPIR-V legalization failed: " + out.messages,
                             {}});
        return;
    }
    job.words = std::move(o.response.words);
    job.ok = true;
}

}  // namespace

bool CompileOrLoad(CompileState& st, Job& job) {
    const std::string& shader = ShaderOf(st, st.tasks[job.first_task]);
    if (auto cached = LoadCached(st, job.cache_key, shader)) {
        job.words = std::move(*cached);
        job.ok = job.from_cache = true;
        return false;
    }
    CompileJob(st, job);
    if (job.ok && st.modules)
        st.modules->Store(job.cache_key, job.words, shader);
    return true;
}

// A cache entry is used only once spirv-val accepts it: a damaged or forged entry is a miss, and
// the compile that follows replaces it.
std::optional<std::vector<uint32_t>> LoadCached(CompileState& st,
                                                const std::string& key,
                                                const std::string& shader) {
    if (!st.modules)
        return std::nullopt;
    std::optional<std::vector<uint32_t>> cached = st.modules->Load(key, shader);
    if (!cached)
        return std::nullopt;
    worker::Request check;
    check.kind = worker::RequestKind::kValidate;
    check.words = *cached;
    const worker::Outcome o = st.exec->Run(check);
    if (o.status != worker::Outcome::Status::kOk || !o.response.ok)
        return std::nullopt;
    return cached;
}

const std::string& EntryOf(const CompileState& st, const StageTask& t) {
    return st.passes[t.pass].pragmas.Entry(t.stage)->name;
}

const std::string& ShaderOf(const CompileState& st, const StageTask& t) {
    return st.shaders[st.passes[t.pass].shader].file->path();
}

void AppendGlslangLog(CompileState& st,
                      const std::string& log,
                      std::vector<Diagnostic>& out,
                      const std::string* program) {
    if (log.empty())
        return;  // the common case: a clean compile
    AppendMessages(st, frontend::ParseInfoLog(log), out, program);
}

void AppendMessages(CompileState& st,
                    const std::vector<frontend::GlslangMessage>& messages,
                    std::vector<Diagnostic>& out,
                    const std::string* program,
                    const std::string* unreduced,
                    const StageTask* task) {
    if (messages.empty())
        return;
    auto lookup = [&st](const std::string& name) {
        const GeneratedSource* g = FindGenerated(st.generated, name);
        return g ? g->file : st.files.Get(name);
    };
    frontend::MessageContext context;
    const hlsl::IncludePaths paths = IncludePathsFor(st.options);
    context.include_search.push_back("the including file's folder");
    for (const std::string& dir : paths.dirs)
        context.include_search.push_back(dir + " (-I)");
    context.include_search.push_back(paths.templates_dir + " (Kiln's templates, Unity " +
                                     hlsl::ReleaseName(paths.unity_version) + "'s files)");
    context.unity_version = paths.unity_version;
    if (program != nullptr) {
        // Read once for every unknown name of the log (with `task`, a worker's round trip).
        context.identifiers = [&st, program, task,
                               names = std::optional<std::vector<std::string>>()]() mutable {
            if (names)
                return *names;
            if (task == nullptr) {
                names = Identifiers(*program);
                return *names;
            }
            worker::Request request = StageRequest(st, *task, worker::RequestKind::kPreprocess);
            request.source = SourceOf(st, *task);
            request.keep_declarations = true;
            const worker::Outcome o = st.exec->Run(request);
            const bool whole = !OutcomeDiagnostic(st, *task, o) && o.response.ok;
            names = Identifiers(whole ? o.response.text : *program);
            return *names;
        };
        context.functions = [program, unreduced] {
            std::vector<std::string> names = FunctionNames(*program);
            if (unreduced != nullptr) {  // functions the reduction left out, too
                const std::vector<std::string> more = FunctionNames(*unreduced);
                names.insert(names.end(), more.begin(), more.end());
            }
            return names;
        };
    }
    for (const auto& m : messages) {
        out.push_back(frontend::ToDiagnostic(m, lookup, context));
        NoteGenerated(st.generated, out.back());
    }
}

void CompileJobs(CompileState& st, CompileStats& stats) {
    std::atomic<size_t> compiles{0}, hits{0};
    ParallelFor(
        st.jobs.size(), st.options.jobs,
        [&](size_t j) {
            Job& job = st.jobs[j];
            if (!st.tasks[job.first_task].preprocess_ok || job.done)
                return;  // reported by PreprocessAndDedup, or compiled there
            if (job.ok) {
                ++hits;  // taken from the cache with the direct mode's manifest
                return;
            }
            if (!CompileOrLoad(st, job)) {
                ++hits;
                return;
            }
            ++compiles;
            if (job.ok) {
                // Its texts are needed no more (streaming memory).
                StageTask& t = st.tasks[job.first_task];
                std::string().swap(t.reduced);
                std::string().swap(t.rewritten);
            }
        },
        [&](size_t done) { Progress(st.options, "compiling", done, st.jobs.size()); });
    stats.glslang_compiles += compiles;
    stats.cache_hits += hits;
}

}  // namespace kiln::driver
