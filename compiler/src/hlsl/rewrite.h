// Source rewrites for constructs Unity's HLSL compiler accepts and glslang's HLSL front end does
// not, applied to the preprocessed text of a stage (macros expanded, includes inlined) reduced to
// what its entry point reaches (reduce.h), so the rewrite sees what glslang will compile. Each
// rewrite keeps every line where it was, so #line positions stay right, and is applied only where
// it cannot change the program's meaning (docs/unity-compat.md, "Differences from Unity's
// compiler"):
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
// - Minimum-precision matrices (`min16float3x3`, what Unity 2018's HLSLSupport.cginc makes of
//   `half3x3` on Vulkan), which glslang 12 lacks, become 32-bit matrices (`float3x3`), as
//   `--precision full` makes every half matrix; the name is padded so columns hold.
// - fxc's `VPOS` pixel-shader input semantic becomes `SV_Position` (glslang would make it a
//   varying no stage writes), and a `switch` selector is converted to int as fxc converts it
//   (`switch ((int)(x))`: glslang requires an integer, and fxc truncates a float).
// - Writes to a global (rewrite_globals.cpp): fxc keeps the written value private to the
//   invocation. A global that the text writes gets a `static` copy initialized from it, and
//   every use outside declarations is renamed to the copy.
// - A vector argument to a scalar `in` parameter (rewrite_calls.cpp), which fxc truncates with
//   warning X3206: where the call has one candidate function of that name and arity, and the
//   argument is known to be a vector, it becomes `(argument).x`, with Unity's warning.
#ifndef KILN_HLSL_REWRITE_H_
#define KILN_HLSL_REWRITE_H_

#include <string>
#include <vector>

#include "hlsl/tokens.h"

namespace kiln::hlsl {

struct RewriteResult {
    std::string text;
    size_t one_vector_swizzles = 0;     // `.x` dropped after a 1-vector
    size_t matrix_swizzles = 0;         // multi-element matrix swizzles expanded
    size_t infinity_literals = 0;       // `1.INF` from the preprocessor put back as `1.#INF`
    size_t min_precision_matrices = 0;  // `min16float3x3` -> `float3x3`
    size_t vpos_semantics = 0;          // `: VPOS` -> `: SV_Position`
    size_t switch_selectors = 0;        // `switch (x)` -> `switch ((int)(x))`
    size_t private_globals = 0;         // globals given a private copy because the text writes them
    size_t truncated_arguments = 0;     // vector arguments to scalar parameters
    std::vector<RewriteWarning> warnings;  // Unity's warnings for what was rewritten (X3206)
    bool changed() const {
        return one_vector_swizzles + matrix_swizzles + infinity_literals + min_precision_matrices +
                   vpos_semantics + switch_selectors + private_globals + truncated_arguments >
               0;
    }
};

RewriteResult RewriteForGlslang(const std::string& preprocessed);
// The same with `tokens` = Tokenize(preprocessed), made already (hlsl/reduce.h gives them).
RewriteResult RewriteForGlslang(const std::string& preprocessed, std::vector<Token> tokens);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_REWRITE_H_
