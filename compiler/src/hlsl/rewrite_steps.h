// The rewrites of rewrite.h that need more than one token's context, each in its own file. Each
// takes the text and its tokens and adds non-overlapping edits; RewriteForGlslang applies the
// steps one after another, each on the text the previous one produced.
#ifndef KILN_HLSL_REWRITE_STEPS_H_
#define KILN_HLSL_REWRITE_STEPS_H_

#include <string>
#include <string_view>
#include <vector>

#include "hlsl/tokens.h"

namespace kiln::hlsl {

// The name of a global's private copy is this prefix and the global's name.
inline constexpr std::string_view kPrivateCopyPrefix = "kiln_private_";

// rewrite_globals.cpp: globals the text writes get a private static copy. Returns how many.
size_t PrivateGlobals(const std::string& text,
                      const std::vector<Token>& tok,
                      std::vector<Edit>& edits);

// rewrite_calls.cpp: vector arguments to scalar parameters become their first component.
// Returns how many; a warning for each.
size_t TruncatedArguments(const std::string& text,
                          const std::vector<Token>& tok,
                          std::vector<Edit>& edits,
                          std::vector<RewriteWarning>& warnings);

// Applies edits (sorted here; an edit overlapping an earlier one is dropped).
std::string ApplyEdits(const std::string& text, std::vector<Edit> edits);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_REWRITE_STEPS_H_
