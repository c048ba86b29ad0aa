// Identifier characters of HLSL source text, for the passes that scan preprocessed text
// (reduce.cpp, rewrite.cpp) and for the inactive-text plan (pp_skeleton.cpp, pp_macros.cpp).
#ifndef KILN_HLSL_IDENTIFIER_H_
#define KILN_HLSL_IDENTIFIER_H_

#include <string_view>

namespace kiln::hlsl {

// ASCII letters, digits and '_' (glslang's classes; std::isalnum is a call per byte, and one the
// locale could widen: Kiln never sets one).
inline bool IdentStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

inline bool IdentChar(char c) {
    return IdentStart(c) || (c >= '0' && c <= '9');
}

// Calls `f` with each identifier of `text`: each run of identifier characters that does not
// start with a digit (text in comments or strings, when left in, counts too).
template <typename F>
void ForEachWord(std::string_view text, F f) {
    for (size_t i = 0; i < text.size();) {
        if (!IdentChar(text[i])) {
            ++i;
            continue;
        }
        const size_t start = i;
        while (i < text.size() && IdentChar(text[i]))
            ++i;
        if (IdentStart(text[start]))  // not a number
            f(text.substr(start, i - start));
    }
}

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_IDENTIFIER_H_
