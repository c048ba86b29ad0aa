// Identifier characters of HLSL source text, for the passes that scan preprocessed text
// (reduce.cpp, rewrite.cpp) and for the inactive-text plan (pp_skeleton.cpp, pp_macros.cpp).
#ifndef KILN_HLSL_IDENTIFIER_H_
#define KILN_HLSL_IDENTIFIER_H_

#include <cctype>

namespace kiln::hlsl {

inline bool IdentStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}

inline bool IdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_IDENTIFIER_H_
