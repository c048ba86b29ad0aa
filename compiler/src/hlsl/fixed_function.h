// Vertex and fragment programs for a pass written in legacy fixed-function ShaderLab, as Unity
// generates them (Unity manual, "ShaderLab: legacy fixed-function"): per-vertex lighting with
// the Material colours (Lighting On) or a constant / vertex colour (Lighting Off), then the
// SetTexture stages' combiners, SeparateSpecular and AlphaTest. The result is the body of a
// CGPROGRAM, compiled like any other (docs/unity-compat.md, "Fixed-function passes").
#ifndef KILN_HLSL_FIXED_FUNCTION_H_
#define KILN_HLSL_FIXED_FUNCTION_H_

#include <string>
#include <vector>

#include "kiln/shaderlab/ast.h"

namespace kiln::hlsl {

inline constexpr const char* kFixedFunctionVertex = "kiln_ff_vert";
inline constexpr const char* kFixedFunctionFragment = "kiln_ff_frag";

// `fixed` is the pass's settings merged over its SubShader and Category; `properties` are the
// shader's (texture dimensions and property types come from them).
std::string FixedFunctionProgram(const shaderlab::FixedFunction& fixed,
                                 const std::vector<shaderlab::Property>& properties);

// `inner` over `outer`: what `inner` sets wins; texture stages and bindings as a whole.
void MergeFixedFunction(shaderlab::FixedFunction& outer, const shaderlab::FixedFunction& inner);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_FIXED_FUNCTION_H_
