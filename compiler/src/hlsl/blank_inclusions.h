// Files glslang reads in vain, served as one line break and given back after. Most inclusions of
// a program are a file included again behind its guard: the plan blanks it whole, and glslang
// still reads each of its line breaks (Unity's Standard: 11,000 of the 18,600 lines a program
// serves; the shipped materials: 28 of 54 inclusions). glslang prints an inclusion as the
// `#line <n> "<name>"` of its prologue, a line break per line break of the file when it holds no
// token, and the `#line` of its return to the includer (CPPinclude in glslang's Pp.cpp), so a
// blank file served as a single line break differs only in how many empty lines follow its
// prologue. Such a file is served under a marked name, which its prologue prints, and the
// output's empty lines are put back where that name is found.
#ifndef KILN_HLSL_BLANK_INCLUSIONS_H_
#define KILN_HLSL_BLANK_INCLUSIONS_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kiln::hlsl {

// Fewer line breaks than this are served as they are.
inline constexpr size_t kMinBlankInclusion = 8;

// Whether `text` (an inclusion's served text) is only line breaks, at least kMinBlankInclusion,
// and `path` can be printed in a #line of glslang's output unchanged.
bool ServableAsBlank(std::string_view text, std::string_view path);

// The name a blank inclusion is served under: `path` marked with the inclusion's index in the
// plan (the splice marker's prefix, hlsl/splice.h, which no text of a spliced program spells).
std::string BlankInclusionName(size_t inclusion, std::string_view path);

// An inclusion's name marked with `tag` and its index in the plan: `qKsP<tag><index>|<path>`
// (blank inclusions here, remembered outputs in hlsl/output_memo.h).
std::string MarkedName(char tag, size_t inclusion, std::string_view path);
// `name` without its mark, where it is a marked name.
std::string_view UnmarkedName(std::string_view name);
// What ends a marked name's mark.
inline constexpr char kMarkedPathStart = '|';
// Whether `at` (a quote) ends a `#line <digits> ` that starts a line of `text`: where glslang's
// output prints a marked name.
bool InLineDirective(const std::string& text, size_t at);

// glslang's output for a program whose blank inclusions were served as one line break each,
// given back as glslang prints them whole: `newlines` by inclusion index, 0 where the inclusion
// was served as it is. False, with `text` unchanged, where a marked name is missing, out of
// order, or not in a prologue followed by the one empty line and the return's #line.
bool RestoreBlankInclusions(std::string& text, const std::vector<uint32_t>& newlines);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_BLANK_INCLUSIONS_H_
