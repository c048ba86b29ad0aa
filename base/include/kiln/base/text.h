// Text from inputs shown to a person: what a diagnostic echoes from a file (a name, a line) may be
// binary. Escaped, it can neither cut the output short (a NUL), nor drive the terminal (ESC and
// other control bytes), nor be invalid UTF-8.
#ifndef KILN_BASE_TEXT_H_
#define KILN_BASE_TEXT_H_

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace kiln::base {

// Length of the valid UTF-8 sequence at s[i] that is not a C1 control character, else 0.
size_t Utf8SequenceLength(std::string_view s, size_t i);

// Printable ASCII and valid UTF-8 are kept; a tab is kept; every other byte (NUL, ESC and the other
// C0/C1 controls, DEL, bytes of invalid UTF-8) becomes \xNN.
std::string EscapeForTerminal(std::string_view s);

// ASCII case folding, the one spelling of it (ShaderLab keywords, pass names, LightMode values and
// render-state names compare without case, as Unity does).
bool EqualsIgnoreCase(std::string_view a, std::string_view b);
std::string ToLower(std::string_view s);
std::string ToUpper(std::string_view s);

// Edit distance suggestion: the candidate closest to `name` within a third of its length, or "".
// Case-insensitive optimal string alignment distance (a swap of two neighbours is one edit).
std::string ClosestName(std::string_view name, const std::vector<std::string>& candidates);

// "; did you mean 'X'?" for the closest candidate, or "" when none is close: the one spelling of
// a suggestion appended to a diagnostic's message.
std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace kiln::base

#endif  // KILN_BASE_TEXT_H_
