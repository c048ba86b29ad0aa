// The text glslang's preprocessor would skip, blanked before it reads it. Most of what a stage
// program's preprocessing reads is skipped: Unity's includes hold blocks for other platforms and
// features, and a file included again behind its guard is skipped whole (Unity's Standard reads
// 760 KB per program, of which about 70 KB make tokens). glslang tokenizes skipped text as it
// tokenizes the rest, so it spends most of its time there.
//
// The plan walks each file's directive lines (hlsl/pp_skeleton.h) in the order glslang reads
// them, with a table of the macros defined so far (hlsl/pp_macros.h), and blanks the lines of
// each conditional branch it knows to be skipped, keeping the directive lines themselves and
// every line break: glslang's output, messages and line numbers are unchanged. Where it does not
// know (a condition it cannot evaluate, a file it cannot model), it blanks nothing that depends on
// it, and where it cannot follow glslang any further (an #include it may or may not read), it
// stops: the files after that point are served as they are.
#ifndef KILN_HLSL_INACTIVE_TEXT_H_
#define KILN_HLSL_INACTIVE_TEXT_H_

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hlsl/includer.h"
#include "hlsl/output_memo.h"

namespace kiln::hlsl {

struct PpSkeleton;
struct SpliceChoice;

struct InactiveTextPlan {
    struct Inclusion {
        std::string path;  // as the Includer resolves it
        std::string text;  // the served text with its skipped lines blanked
    };
    std::string main_text;  // the main source with its skipped lines blanked
    // Every file glslang's preprocessor will ask for, in order, up to where the plan stopped.
    std::vector<Inclusion> inclusions;
    bool complete = false;  // the plan reached the end of the main source
    size_t blanked_lines = 0;
    // Branches glslang may or may not read, for what the plan did not know.
    size_t maybe_branches = 0;
    // Walks of an #include taken from an earlier plan's (hlsl/plan_memo.h) instead of made.
    size_t remembered_walks = 0;
    // Every line glslang reads that names one of PlanOptions::unknown is a condition, that
    // macro's own #define or #undef, or a #pragma (whose tokens glslang prints unexpanded), and
    // no paste (##) can make one (no proper prefix of one is a word of the files read).
    bool unknown_only_in_conditions = true;

    // With PlanOptions::record_macros, where the plan reached the end: each macro defined there
    // (not those of PlanOptions::unknown), by name, as its #define's text after "define".
    // `macros_exact` says the table is glslang's: every branch was decided, no name glslang may
    // define itself was defined or undefined, and each #define or #undef of an unknown macro is
    // a #define in the main source outside conditionals, on the lines `unknown_define_lines`.
    std::vector<std::pair<std::string, std::string>> macros;
    bool macros_exact = false;
    std::vector<uint32_t> unknown_define_lines;  // 0-based physical lines

    // With PlanOptions::splice: by inclusion, the runs of tokens of the file served as markers
    // (hlsl/splice.h; null where none were), for Unsplice on glslang's output; and how many.
    std::vector<std::shared_ptr<const SpliceChoice>> splices;
    size_t spliced_runs = 0;
    // With PlanOptions::splice: by inclusion, how many line breaks a blank inclusion served as
    // one holds (hlsl/blank_inclusions.h), 0 where it was served as it is; empty where none was.
    std::vector<uint32_t> blank_inclusions;
    // With PlanOptions::splice: the walks whose output is remembered (hlsl/output_memo.h), by
    // inclusion, replayed or to be recorded; and by inclusion, 1 + the index of its mark there
    // (0 where none), empty where there is none.
    std::vector<OutputMark> outputs;
    std::vector<uint32_t> output_marks;

    // True when glslang's output is the same whatever PlanOptions::unknown are defined to (for
    // sources that differ only in their #define lines): the plan reached the end, and decided
    // every branch without them, and no line glslang reads expands them.
    bool OutputIgnoresUnknown() const {
        return complete && maybe_branches == 0 && unknown_only_in_conditions;
    }
};

struct PlanOptions {
    // Macros taken as not known whatever the text defines: every branch the plan blanks is then
    // skipped whatever they are.
    std::vector<std::string> unknown;
    // Records the macro table where the plan ends (InactiveTextPlan::macros).
    bool record_macros = false;
    // Stops at the first branch the unknown macros may decide, or the first file that names one
    // elsewhere: the plan is then incomplete, so OutputIgnoresUnknown() is false at once (for a
    // caller that wants only a plan that holds whatever they are).
    bool stop_when_unknown_matters = false;
    // Also blanks the directives glslang does not need, where its output stays the same: the
    // #if, #elif, #else and #endif lines of a conditional whose every branch is decided, and each
    // #define of a macro no other line of the files read names. Only for a plan of a whole
    // program (a text after `main` could name such a macro).
    bool drop_needless = false;
    // Also serves the included files' plain lines short (hlsl/splice.h) and their blank
    // inclusions as one line break (hlsl/blank_inclusions.h), where the plan reached the end of
    // the program: glslang's output must then be given to MakeWhole.
    bool splice = false;
    // Takes walks of #includes from the FileCache's memo of earlier walks, and keeps its own
    // there (hlsl/plan_memo.h); not with record_macros.
    bool remember = true;
    // ScanSkeleton(main), when the caller has made it already.
    const PpSkeleton* main_skeleton = nullptr;
};

// The plan for preprocessing `main` (named `name`, as glslang is told) with `includer`.
InactiveTextPlan PlanInactiveText(std::string_view main,
                                  const std::string& name,
                                  const Includer& includer,
                                  FileCache& files,
                                  const PlanOptions& options = {});

// glslang's output for `plan`'s texts made as it is for the program's: the blank inclusions
// given back, then the spliced runs, then the remembered outputs; with `memo`, the outputs the
// plan marked to be recorded are kept there. False where the output is not as they expect (the
// program is then preprocessed again without PlanOptions::splice).
bool MakeWhole(std::string& text, const InactiveTextPlan& plan, OutputMemo* memo = nullptr);

// `text` with the physical lines of each of `ranges` (inclusive, ascending, from a PpSkeleton's
// `line_starts`) blanked: each keeps only its line break, and a last line without one stays
// without one. Adds the lines blanked to `blanked_lines`.
std::string BlankLines(std::string_view text,
                       const std::vector<uint32_t>& line_starts,
                       const std::vector<std::pair<uint32_t, uint32_t>>& ranges,
                       size_t& blanked_lines);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_INACTIVE_TEXT_H_
