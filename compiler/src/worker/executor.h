// Where worker requests run. The default is a pool of long-lived `kiln-worker` processes, as
// production shader compilers isolate theirs (Unity's UnityShaderCompiler, Unreal's
// ShaderCompileWorker): glslang and SPIRV-Tools crash, loop or exhaust memory on some inputs, and a
// worker that does so is killed and restarted while the compile reports a diagnostic. Each worker
// runs its requests on a deep stack, one at a time, under a wall-clock limit and a memory limit
// per request. The in-process executor runs the same requests in the calling process (for
// debugging: `kiln compile --in-process`).
#ifndef KILN_WORKER_EXECUTOR_H_
#define KILN_WORKER_EXECUTOR_H_

#include <cstdint>
#include <memory>
#include <string>

#include "hlsl/file_cache.h"
#include "worker/protocol.h"

namespace kiln::worker {

struct Outcome {
    enum class Status {
        kOk,           // `response` is the request's answer (which may report a failed compile)
        kCrashed,      // the worker died (`signal`, or `exit_code` when it exited)
        kTimedOut,     // over the time limit; the worker was killed
        kOutOfMemory,  // over the memory limit; the worker was killed or gave up
        kUnavailable,  // no worker could be started (`detail` says why)
        kBroken,       // the worker answered something that is not the protocol (`detail`)
    };
    Status status = Status::kOk;
    Component component = Component::kNone;  // the component the request was in when it ended
    int signal = 0;
    int exit_code = -1;
    std::string detail;
    Response response;
};

class Executor {
  public:
    virtual ~Executor() = default;
    // Thread-safe; blocks until the request ends one way or another.
    virtual Outcome Run(const Request& request) = 0;
};

struct PoolOptions {
    std::string worker_path;  // the kiln-worker executable (FindWorker)
    unsigned workers = 1;     // at most this many processes (the compile's -j)
    double timeout_seconds = 60;
    uint64_t memory_limit_bytes = uint64_t{2} << 30;
    uint64_t stack_bytes = uint64_t{256} << 20;
    std::string working_dir;  // where the workers run (empty: this process's directory)
};

// Both read the files a request looks for through `files` (the compile's), and hand them over
// through the protocol (worker/file_exchange.h): a worker needs no access to them.
std::unique_ptr<Executor> MakeInProcessExecutor(hlsl::FileCache& files);
// Workers start on first use and after each failure, each with a hello (a worker of another
// version is refused: kUnavailable).
std::unique_ptr<Executor> MakeWorkerPool(const PoolOptions& options, hlsl::FileCache& files);

// The worker executable: `explicit_path` when given, else $KILN_WORKER, else kiln-worker beside
// the running executable, else the build tree's. "" when none is executable.
std::string FindWorker(const std::string& explicit_path);

}  // namespace kiln::worker

#endif  // KILN_WORKER_EXECUTOR_H_
