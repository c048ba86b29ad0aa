// The directive lines of one file, found once per file and kept: what the inactive-text plan
// (hlsl/inactive_text.h) walks instead of the file's bytes. Lines are split as glslang's
// preprocessor splits them (backslash-newline joins lines, comments are whitespace, "..." and
// '...' hide comment openers); a file this scan cannot model exactly is marked not `safe` and is
// then never blanked.
#ifndef KILN_HLSL_PP_SKELETON_H_
#define KILN_HLSL_PP_SKELETON_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace kiln::hlsl {

enum class PpKind {
    kIf,
    kIfdef,
    kIfndef,
    kElif,
    kElse,
    kEndif,
    kDefine,
    kUndef,
    kInclude,
    kPragma,
    kKnown,    // #line, #error, #extension, #version, #warning: no effect on macros or includes
    kUnknown,  // a name glslang does not know, or a line of a lone '#'
};

struct PpDirective {
    PpKind kind = PpKind::kUnknown;
    uint32_t first_line = 0;  // 0-based physical lines the directive spans
    uint32_t last_line = 0;
    // The text after the directive's name: continuations joined, each comment one space.
    std::string rest;
    // #if/#ifdef/#ifndef/#elif/#else: the index of the same conditional's next #elif, #else or
    // #endif in PpSkeleton::directives.
    uint32_t next = 0;
};

struct PpSkeleton {
    bool safe = true;
    // The names of the text's code and directives with the times each is spelled (comments left
    // out; words in string literals counted), and whether a #define's body pastes tokens (##): a
    // paste may make a name the text never spells, whose first piece is one of these words.
    std::unordered_map<std::string, uint32_t> words;
    bool pastes = false;
    uint32_t line_count = 0;            // physical lines ('\n'-separated; the last may be empty)
    std::vector<uint32_t> line_starts;  // byte offset of each physical line
    std::vector<PpDirective> directives;
};

// Scans `text` (a file's text after any byte-order mark).
PpSkeleton ScanSkeleton(std::string_view text);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_PP_SKELETON_H_
