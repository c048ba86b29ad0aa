// A pass's include prefix preprocessed once and shared by its variants: a precompiled preamble,
// as clangd keeps one. The prefix is a program's text up to the line after its last #include;
// when the inactive-text plan proves glslang's output for it the same whatever the pass's
// keywords are (PlanOptions::unknown), that output is made once. Each variant is then
// preprocessed by glslang itself with the prefix's code lines blanked: glslang still reads every
// directive, so its macro table and messages are its own, but it no longer tokenizes the shared
// code. The two outputs are joined at the last line the prefix printed (the #line that returns
// from the last include), where glslang's output state is the same in both runs.
//
// Every step refuses what it cannot prove: a prefix whose output depends on a keyword, a text
// after the prefix that includes files or prints a directive (#line), output that is not shaped
// as expected, any message. The caller then preprocesses the program whole.
#ifndef KILN_HLSL_PREAMBLE_H_
#define KILN_HLSL_PREAMBLE_H_

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "hlsl/file_cache.h"
#include "hlsl/inactive_text.h"
#include "hlsl/reduce.h"
#include "hlsl/tokens.h"

namespace kiln::hlsl {

struct PpSkeleton;

// Where a program's prefix ends: after the physical line of its last #include, when the text
// after it has no #include and no directive glslang prints or reports (#line, #error, ...).
struct PrefixCut {
    size_t bytes = 0;    // the prefix is main[0, bytes)
    uint32_t lines = 0;  // its physical lines
};
std::optional<PrefixCut> FindPrefixCut(std::string_view main, const PpSkeleton& skeleton);

// `text` with every physical line before `end_line` that is not part of a directive blanked.
std::string DirectivesOnly(std::string_view text, const PpSkeleton& skeleton, uint32_t end_line);

// The lines of `prefix` that #define one of `pinned` as the key below finds them (a line that
// starts "#define NAME"), with their 0-based physical line numbers.
std::vector<std::pair<uint32_t, std::string_view>> PinnedDefines(
    std::string_view prefix,
    const std::vector<std::string>& pinned);

// The key under which variants share a prefix: `prefix` with the name of each `#define` of a
// `pinned` macro at a line's start replaced (so variants that differ only in which keywords they
// define share it), the pinned names and `context` (stage, include paths).
std::string PreambleKey(std::string_view prefix,
                        const std::vector<std::string>& pinned,
                        std::string_view context);

struct Preamble {
    bool usable = false;  // false: this prefix cannot be shared (remembered so it is tried once)
    std::string output;   // glslang's output for the prefix, through the last line it printed
    std::vector<Token> tokens;  // Tokenize(output), for each program's reduction (TokenizeAfter)
    std::shared_ptr<const ReducePrefix> reduce_prefix;  // MakeReducePrefix(output, tokens)
    std::vector<std::string> marks;  // the lines of `output` that directives printed, in order
    InactiveTextPlan served;         // the files the prefix includes, their directives only
    // The macro table where the prefix ends as #define lines, when the plan knows it exactly
    // (InactiveTextPlan::macros_exact): a program is then preprocessed from it, its own pinned
    // #define lines, the prefix's last #line and the rest, without reading the files.
    bool replayable = false;
    struct Macro {
        std::string line;  // "#define NAME ...\n"
        // The macros its body names, and those its pastes (##) may make: a pasted parameter
        // makes a name that starts or ends with the name pasted to it.
        std::vector<uint32_t> names;
        bool pastes_any = false;  // a paste that may make any name (two parameters pasted)
    };
    std::vector<Macro> macros;  // by name
    std::unordered_map<std::string, uint32_t> macro_index;
    std::vector<std::shared_ptr<const SourceFile>> files;  // what it was made from
};

// Fills `output` and `marks` from glslang's output for the prefix alone; false when it is not
// shaped as joining needs (it must end with the #line of the return from an include, and '#' may
// appear only in the lines #line and #pragma print).
bool CutPrefixOutput(const std::string& prefix_output, Preamble& preamble);

// glslang's output for the whole program, from the preamble and glslang's output `blanked` for
// the program with the prefix's code blanked; nullopt when `blanked` is not shaped as expected or
// its first line after the prefix could depend on the prefix's last token.
std::optional<std::string> JoinPreamble(const Preamble& preamble, std::string_view blanked);
// The same for glslang's output `replayed` for the program made from the preamble's macros
// (MacrosFor), the program's pinned #define lines, the preamble's last #line and the rest.
std::optional<std::string> JoinReplayedPreamble(const Preamble& preamble,
                                                std::string_view replayed);

// Sets `preamble`'s macro table from the plan's (InactiveTextPlan::macros).
void SetMacros(Preamble& preamble, const std::vector<std::pair<std::string, std::string>>& macros);

// The #define lines of the macros `rest` can expand: those it names, and those their bodies name
// or paste, transitively (every one when `rest` pastes, or a paste may make any name). The others
// cannot change its output.
std::string MacrosFor(const Preamble& preamble, std::string_view rest);

// Preambles by key, shared by a process's compile threads.
class PreambleCache {
  public:
    // The preamble under `key` made from the files `files` has now; null when there is none.
    std::shared_ptr<const Preamble> Find(const std::string& key, FileCache& files) const;
    void Remember(const std::string& key, std::shared_ptr<const Preamble> preamble);
    size_t size() const;  // preambles made, usable or not

  private:
    mutable std::mutex mu_;
    std::unordered_map<std::string, std::shared_ptr<const Preamble>> map_;
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_PREAMBLE_H_
