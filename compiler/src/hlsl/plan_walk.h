// The inactive-text plan's walk of a program's directives (hlsl/inactive_text.h): each file in
// the order glslang reads it, with the macros defined so far, remembering each #include's walk
// (hlsl/plan_memo.h). Private to the plan.
#ifndef KILN_HLSL_PLAN_WALK_H_
#define KILN_HLSL_PLAN_WALK_H_

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "hlsl/file_cache.h"
#include "hlsl/inactive_text.h"
#include "hlsl/includer.h"
#include "hlsl/plan_memo.h"
#include "hlsl/pp_macros.h"
#include "hlsl/pp_skeleton.h"

namespace kiln::hlsl {

// One file as the walk reads it.
struct PlanFile {
    const std::string& name;  // as glslang names it to the Includer
    std::string_view text;
    const PpSkeleton& skeleton;
    const std::vector<uint32_t>& line_starts;  // of `text`: the skeleton's, or the lean text's
    LineRanges blank;
    std::vector<DefineLine> defines;  // with PlanOptions::drop_needless
};

struct PlanWalk {
    const Includer& includer;
    FileCache& files;
    const PlanOptions& options;
    InactiveTextPlan& plan;
    PpMacros macros;
    size_t depth = 0;  // files open, as glslang counts them for the Includer
    bool stopped = false;
    // PlanOptions::record_macros: the table as #define texts, and whether it is glslang's.
    const PlanFile* main = nullptr;
    size_t conditionals = 0;  // conditionals open around the directive walked
    std::map<std::string, std::string> table;
    bool exact = true;
    std::vector<Pending> pending;
    // What a walk of an #include depends on besides its file, the macros and the depth (the
    // include paths and the options), for the memo; empty when the walk is not remembered.
    std::string memo_context;
};

// Walks the main file `f` (s.main) to its end, or to where the walk stops.
void WalkMain(PlanWalk& s, PlanFile& f);

// Whether `f`'s lines that glslang reads name PlanOptions::unknown only in conditions, in their
// own #define and #undef, or in a #pragma.
bool MentionsOnlyInConditions(const PlanWalk& s, const PlanFile& f);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_PLAN_WALK_H_
