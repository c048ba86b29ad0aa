// RelaxedPrecision as HLSL's types give it. glslang decorates an operation RelaxedPrecision when
// any operand is (GLSL's rule, where an unqualified float has no precision of its own), so
// `min16float * float` becomes relaxed; in HLSL that product is float. With --precision half,
// SPIRV-Tools then computes every relaxed operation in binary16, and a float expression that
// merely touches a half value (a light colour times a half albedo) would overflow at 65504.
//
// MatchHlslPromotion removes the decoration from every arithmetic result that has a 32-bit float
// operand which is neither relaxed nor a constant (literals take their context's precision, as
// in both languages), repeated through phis until nothing changes. What stays relaxed is
// arithmetic on half values alone. Loads, image operations and other producers keep glslang's
// decoration, so run on glslang's output, before legalization, a load of a half variable or
// parameter is relaxed: assigning a float to a half narrows it, as in HLSL.
#ifndef KILN_SPIRV_HLSL_PRECISION_H_
#define KILN_SPIRV_HLSL_PRECISION_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace kiln::spirv {

// Edits `words` (a valid module) in place; returns the number of decorations removed.
size_t MatchHlslPromotion(std::vector<uint32_t>& words);

// Removes RelaxedPrecision from every value an image access reads besides the image: its
// coordinates, level of detail, bias, gradients, offsets and Dref. SPIRV-Tools'
// convert-relaxed-to-half converts only a Dref back to 32 bits and leaves binary16 coordinates
// and levels, which Vulkan does not allow without VK_AMD_gpu_shader_half_float_fetch (LLVM 15 in
// llvmpipe aborts on them). Undecorated, those values are computed in 32 bits from their
// relaxed inputs. Run after legalization (on SSA values), before the conversion.
size_t KeepImageOperandsFloat(std::vector<uint32_t>& words);

}  // namespace kiln::spirv

#endif  // KILN_SPIRV_HLSL_PRECISION_H_
