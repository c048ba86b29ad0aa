// A file's served text with what glslang reads in vain left out: a third of what it reads of
// Unity's includes is comments. Each line whose code is none keeps only its line break (a
// comment inside it, or the middle of a block comment), and each line of code loses what follows
// its last code character (spaces, a `//` comment, block comments closed on the line), where
// that leaves the next line as it was: no line continued by a backslash, no comment opened that
// a later line closes, no directive line touched. Line numbers, and the column of every line's
// first token (glslang copies it), stay; glslang's output is the same (the inactive-text check,
// KILN_CHECK_INACTIVE_TEXT, compares it with that of the file as it is).
#ifndef KILN_HLSL_LEAN_TEXT_H_
#define KILN_HLSL_LEAN_TEXT_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kiln::hlsl {

struct PpSkeleton;

struct LeanText {
    std::string text;
    std::vector<uint32_t> line_starts;  // as PpSkeleton::line_starts, of `text`
};

// `text` is a file's served text; `skeleton` = ScanSkeleton(text). An unsafe skeleton's text is
// kept as it is.
LeanText MakeLeanText(std::string_view text, const PpSkeleton& skeleton);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_LEAN_TEXT_H_
