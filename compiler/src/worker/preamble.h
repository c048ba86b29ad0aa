// A stage program preprocessed with its pass's include prefix shared (hlsl/preamble.h): the
// prefix's output is made once per process and key, and each program then runs glslang's
// preprocessor over its directives and its own code only.
#ifndef KILN_WORKER_PREAMBLE_H_
#define KILN_WORKER_PREAMBLE_H_

#include <memory>
#include <optional>

#include "frontend/glslang_stage.h"
#include "hlsl/includer.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/preamble.h"
#include "worker/execute.h"

namespace kiln::worker {

// glslang's preprocessing of `r` (a kPreprocess request with `pinned` keywords), joined from the
// shared prefix's output and the program's own; nullopt when the prefix cannot be shared or the
// program gave any message (the caller then preprocesses it whole). `for_both` says whether the
// output holds for the partner stage's source too (its prefix and the rest do not read the
// stage). `used`, when given, receives the preamble the output starts with (its `output`, then a
// line break). `skeleton` is ScanSkeleton(r.source).
std::optional<frontend::StageOutput> PreprocessWithPreamble(
    const Request& r,
    ExecuteContext& context,
    hlsl::Includer& includer,
    const hlsl::PpSkeleton& skeleton,
    bool& for_both,
    std::shared_ptr<const hlsl::Preamble>* used = nullptr);

}  // namespace kiln::worker

#endif  // KILN_WORKER_PREAMBLE_H_
