// The compile driver's side of worker isolation (worker/executor.h): which executor a compile
// uses, the requests its phases send, and what a worker that crashed, ran out of time or memory,
// or could not start becomes as a diagnostic naming the shader, pass, variant and stage.
#ifndef KILN_DRIVER_ISOLATION_H_
#define KILN_DRIVER_ISOLATION_H_

#include <memory>
#include <optional>
#include <string>

#include "driver/compile_state.h"
#include "hlsl/includer.h"
#include "worker/executor.h"

namespace kiln::driver {

// The executor the options ask for; null with an error in st.diags when no worker can be found.
std::unique_ptr<worker::Executor> MakeExecutor(CompileState& st);

// -I directories and the templates folder the options name.
hlsl::IncludePaths IncludePathsFor(const CompileOptions& o);

// The optimizer settings as the cache's keys name them: "O0", "O1k1" (-O with Kiln's pass list,
// version 1: a changed list gets a new version, so no entry of another list is taken), "O2" (-Os),
// "O3" (-O with SPIRV-Tools' list).
std::string OptimizationKey(const CompileOptions& o);

// A request for a task's stage with the compile's include paths and options filled in.
worker::Request StageRequest(const CompileState& st,
                             const StageTask& task,
                             worker::RequestKind kind);

// The diagnostic for an outcome whose status is not kOk (nullopt for kOk), placed at the pass's
// program block.
std::optional<Diagnostic> OutcomeDiagnostic(const CompileState& st,
                                            const StageTask& task,
                                            const worker::Outcome& outcome);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_ISOLATION_H_
