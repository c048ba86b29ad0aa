// Carries out one worker request with the real components: glslang's preprocessor and HLSL front
// end, SPIRV-Tools' optimizer and validator. The worker process (worker/serve.cpp) and the
// in-process executor (worker/executor.h) both run requests through this one function, so the
// two modes cannot drift apart.
#ifndef KILN_WORKER_EXECUTE_H_
#define KILN_WORKER_EXECUTE_H_

#include <functional>

#include "hlsl/file_cache.h"
#include "hlsl/preamble.h"
#include "worker/protocol.h"

namespace kiln::worker {

struct ExecuteContext {
    hlsl::FileCache& files;  // includes are read through it (once per process)
    // Told each third-party component as the request enters it (may be empty).
    std::function<void(Component)> phase;
    // Include prefixes shared by a pass's programs (hlsl/preamble.h), kept as long as `files`;
    // null: none are shared.
    hlsl::PreambleCache* preambles = nullptr;
};

Response Execute(const Request& request, ExecuteContext& context);

}  // namespace kiln::worker

#endif  // KILN_WORKER_EXECUTE_H_
