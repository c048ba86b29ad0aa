// Reduces preprocessed HLSL to what one entry point can reach, so that stages that do not depend
// on a keyword give the same text in every variant and are compiled once (dedup). Top-level
// functions that the entry point does not reach (transitively) are removed, keeping their
// newlines so line numbers hold, and so are the structs, cbuffers, resources and static
// variables nothing reached names (reduce_declarations.h); every other declaration (a loose
// uniform above all) is kept, so the `$Global` block's layout matches between the stages of a
// variant, and a cbuffer is kept or dropped whole. `#pragma` lines are blanked (they were read
// from the .shader already) and `#line` directives kept.
//
// It runs before the rewrite (rewrite.h), which then reads only what an entry point reaches; a
// variant's two entry points are reduced from one split of the text into items.
#ifndef KILN_HLSL_REDUCE_H_
#define KILN_HLSL_REDUCE_H_

#include <memory>
#include <string>
#include <vector>

#include "hlsl/tokens.h"

namespace kiln::hlsl {

struct Reduced {
    std::string text;
    // Tokenize(text), made from the whole text's tokens; they view `text`, so they hold only
    // while it is neither changed nor moved.
    std::vector<Token> tokens;
    // Set only when no top-level function is named like the entry point: every top-level
    // function's name, for the "did you mean" of a missing entry point.
    std::vector<std::string> functions_if_entry_missing;
};

Reduced ReduceToEntryPoint(const std::string& preprocessed, const std::string& entry_point);

// The split of a text's start into items, made once for every text that starts with it (a pass's
// preamble, hlsl/preamble.h): the items it closes, their words and its directive lines.
struct ReducePrefix;
// For `text` and `tokens` = Tokenize(text), where a text that starts with `text` goes on with a
// line break and its tokens start with `tokens` (TokenizeAfter).
std::shared_ptr<const ReducePrefix> MakeReducePrefix(const std::string& text,
                                                     const std::vector<Token>& tokens);

// The same for each entry point, from `tokens` = Tokenize(preprocessed) (only their byte ranges
// and identifier flags are read). With `prefix`, `preprocessed` and `tokens` start as the
// prefix's did, and its split is taken instead of made again: the same result. Without
// `drop_declarations`, only functions go (every declaration stays, as before
// reduce_declarations.h).
std::vector<Reduced> ReduceToEntryPoints(const std::string& preprocessed,
                                         const std::vector<Token>& tokens,
                                         const std::vector<std::string>& entry_points,
                                         const ReducePrefix* prefix = nullptr,
                                         bool drop_declarations = true);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_REDUCE_H_
