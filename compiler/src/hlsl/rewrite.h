// Source rewrites for constructs Unity's HLSL compiler accepts and glslang's HLSL front end does
// not, applied to the preprocessed text of a stage (macros expanded, includes inlined), so the
// rewrite sees what glslang will compile. Each rewrite keeps every line where it was, so #line
// positions stay right, and is applied only where it cannot change the program's meaning
// (docs/unity-compat.md, "Differences from Unity's compiler"):
//
// - Component writes through a 1-vector: `o.fogCoord.x = z` where fogCoord is a float1 (Unity's
//   UNITY_TRANSFER_FOG). glslang treats float1 as a scalar whose swizzle is not an l-value. The
//   `.x` / `.r` after a name is dropped when every declaration of that name in the text has a
//   1-vector type (float1, half1, fixed1, int1, uint1, bool1, min16float1, ...), so it is the
//   identity.
// - Multi-element matrix swizzles read as values: `M._14_24_34` (or `._m03_m13_m23`), which
//   glslang 12 compiles into invalid SPIR-V (or crashes on), becomes
//   `float3((M)._14, (M)._24, (M)._34)`. Writes through such swizzles are left alone.
// - fxc's infinity literal `1.#INF`, which glslang reads but its preprocessor prints as `1.INF`,
//   is put back as it was written.
#ifndef KILN_HLSL_REWRITE_H_
#define KILN_HLSL_REWRITE_H_

#include <string>

namespace kiln::hlsl {

struct RewriteResult {
    std::string text;
    size_t one_vector_swizzles = 0;  // `.x` dropped after a 1-vector
    size_t matrix_swizzles = 0;      // multi-element matrix swizzles expanded
    size_t infinity_literals = 0;    // `1.INF` from the preprocessor put back as `1.#INF`
    bool changed() const { return one_vector_swizzles + matrix_swizzles + infinity_literals > 0; }
};

RewriteResult RewriteForGlslang(const std::string& preprocessed);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_REWRITE_H_
