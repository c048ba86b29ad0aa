#include "driver/isolation.h"

#include <chrono>
#include <csignal>
#include <cstdio>

#include "driver/parallel.h"

namespace kiln::driver {
namespace {

using worker::Outcome;

std::string SignalName(int signal) {
    switch (signal) {
        case SIGSEGV:
            return "SIGSEGV, a segmentation fault";
        case SIGABRT:
            return "SIGABRT, an abort";
        case SIGBUS:
            return "SIGBUS, a bus error";
        case SIGFPE:
            return "SIGFPE, an arithmetic exception";
        case SIGILL:
            return "SIGILL, an illegal instruction";
        case SIGKILL:
            return "SIGKILL";
        default:
            return "signal " + std::to_string(signal);
    }
}

std::string Seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", s);
    return buf;
}

// "the fragment stage of shader "X" pass FORWARD".
std::string StageOfPass(const CompileState& st, const StageTask& task) {
    const PassUnit& pu = st.passes[task.pass];
    const ShaderUnit& unit = st.shaders[pu.shader];
    return std::string("the ") + pack::StageName(task.stage) + " stage of shader \"" +
           unit.ast->name + "\" pass \"" + unit.passes[pu.flat].label + "\"";
}

// Counts the time each request kind spends in the executor (CompileState::work_ns).
class TimedExecutor : public worker::Executor {
  public:
    TimedExecutor(std::unique_ptr<worker::Executor> inner, std::array<std::atomic<uint64_t>, 8>& ns)
        : inner_(std::move(inner)), ns_(ns) {}
    worker::Outcome Run(const worker::Request& request) override {
        const auto start = std::chrono::steady_clock::now();
        worker::Outcome o = inner_->Run(request);
        const auto spent = std::chrono::steady_clock::now() - start;
        ns_[size_t(request.kind) % ns_.size()] +=
            uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(spent).count());
        return o;
    }

  private:
    std::unique_ptr<worker::Executor> inner_;
    std::array<std::atomic<uint64_t>, 8>& ns_;
};

std::unique_ptr<worker::Executor> MakeUntimedExecutor(CompileState& st) {
    const CompileOptions& o = st.options;
    if (o.isolation == Isolation::kInProcess)
        return worker::MakeInProcessExecutor(st.files);
    worker::PoolOptions pool;
    pool.worker_path = worker::FindWorker(o.worker_path);
    if (pool.worker_path.empty()) {
        st.diags.Error(DiagCode::kWorkerUnavailable, "", kNoPosition,
                       (o.worker_path.empty()
                            ? std::string("cannot find the compile worker 'kiln-worker' (looked "
                                          "at $KILN_WORKER, beside this program and in the build "
                                          "tree)")
                            : "the compile worker '" + o.worker_path + "' is not an executable") +
                           "; compile with --in-process to run glslang inside kiln instead");
        return nullptr;
    }
    pool.workers = ResolveJobs(o.jobs);
    pool.timeout_seconds = o.program_timeout_seconds;
    pool.memory_limit_bytes = o.program_memory_mib << 20;
    return worker::MakeWorkerPool(pool, st.files);
}

}  // namespace

std::unique_ptr<worker::Executor> MakeExecutor(CompileState& st) {
    std::unique_ptr<worker::Executor> inner = MakeUntimedExecutor(st);
    if (!inner)
        return nullptr;
    return std::make_unique<TimedExecutor>(std::move(inner), st.work_ns);
}

hlsl::IncludePaths IncludePathsFor(const CompileOptions& o) {
    return {o.include_dirs, o.templates_dir.empty() ? DefaultTemplatesDir() : o.templates_dir,
            o.unity_version};
}

std::string OptimizationKey(const CompileOptions& o) {
    const std::string level = "O" + std::to_string(int(o.opt_level));
    return o.opt_level == OptimizationLevel::kPerformance ? level + "k1" : level;
}

worker::Request StageRequest(const CompileState& st,
                             const StageTask& task,
                             worker::RequestKind kind) {
    const PassUnit& pu = st.passes[task.pass];
    const hlsl::IncludePaths paths = IncludePathsFor(st.options);
    worker::Request r;
    r.kind = kind;
    r.stage = task.stage;
    r.name = st.shaders[pu.shader].file->path();
    r.entry = pu.pragmas.Entry(task.stage)->name;
    r.include_dirs = paths.dirs;
    r.templates_dir = paths.templates_dir;
    r.unity_version = paths.unity_version;
    r.debug_info = st.options.debug_info;
    r.half_arithmetic = st.options.precision == Precision::kHalf;
    switch (st.options.opt_level) {
        case OptimizationLevel::kNone:
            r.opt_level = 0;
            break;
        case OptimizationLevel::kPerformance:
            r.opt_level = 1;
            break;
        case OptimizationLevel::kSize:
            r.opt_level = 2;
            break;
        case OptimizationLevel::kPerformanceSpirvTools:
            r.opt_level = 3;
            break;
    }
    return r;
}

std::optional<Diagnostic> OutcomeDiagnostic(const CompileState& st,
                                            const StageTask& task,
                                            const Outcome& outcome) {
    const PassUnit& pu = st.passes[task.pass];
    const ShaderUnit& unit = st.shaders[pu.shader];
    const std::string who = worker::ComponentName(outcome.component);
    const std::string what = StageOfPass(st, task);
    Diagnostic d{Severity::kError,
                 DiagCode::kCompilerCrashed,
                 unit.file->path(),
                 unit.passes[pu.flat].program->range,
                 "",
                 {}};
    switch (outcome.status) {
        case Outcome::Status::kOk:
            return std::nullopt;
        case Outcome::Status::kCrashed: {
            const std::string how =
                outcome.signal != 0 ? SignalName(outcome.signal)
                                    : "it exited with status " + std::to_string(outcome.exit_code);
            const bool ours = outcome.component == worker::Component::kKilnReduction ||
                              outcome.component == worker::Component::kNone;
            d.message = who + " crashed (" + how + ") on " + what;
            if (ours) {
                d.severity = Severity::kInternal;  // Kiln's own code in the worker
                d.code = DiagCode::kInternalError;
                d.message += "; this is a Kiln bug: please report it with the input";
            } else {
                d.message +=
                    "; this is a fault in the third-party compiler, not a Kiln diagnostic of your "
                    "code: simplify the code it fails on, or report it upstream";
            }
            break;
        }
        case Outcome::Status::kTimedOut:
            d.code = DiagCode::kCompilerTimeLimit;
            d.message = who + " did not finish " + what + " within the limit of " +
                        Seconds(st.options.program_timeout_seconds) +
                        " s per program (--program-timeout)";
            break;
        case Outcome::Status::kOutOfMemory:
            d.code = DiagCode::kCompilerMemoryLimit;
            d.message = who + " used more than the limit of " +
                        std::to_string(st.options.program_memory_mib) + " MiB per program on " +
                        what + " (--program-memory)";
            break;
        case Outcome::Status::kUnavailable:
            d.code = DiagCode::kWorkerUnavailable;
            d.message = "no compile worker could be started for " + what + ": " + outcome.detail +
                        "; compile with --in-process to run glslang inside kiln";
            break;
        case Outcome::Status::kBroken:
            d.severity = Severity::kInternal;
            d.code = DiagCode::kInternalError;
            d.message = "the compile worker failed on " + what + ": " + outcome.detail;
            break;
    }
    const auto keywords = variants::EnabledKeywords(pu.pragmas.sets, pu.expansion.layout, task.key);
    d.notes.push_back(
        {unit.file->path(), kNoPosition, "in the variant " + pack::JoinKeywords(keywords)});
    return d;
}

}  // namespace kiln::driver
