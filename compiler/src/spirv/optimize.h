// SPIRV-Tools over one module: HLSL legalization plus -O/-Os (or nothing for -O0), debug-info
// stripping, and validation for Vulkan 1.1.
#ifndef KILN_SPIRV_OPTIMIZE_H_
#define KILN_SPIRV_OPTIMIZE_H_

#include <cstdint>
#include <string>
#include <vector>

namespace kiln::spirv {

// -O0, -O (Kiln's recipe), -Os, and -O with SPIRV-Tools' own performance list (--perf-passes
// spirv-tools).
enum class OptLevel { kNone, kPerformance, kSize, kPerformanceSpirvTools };

// "v2023.1".
std::string SpirvToolsVersion();

// Legalizes (always: glslang's HLSL output needs it) and optimizes in place; with
// `half_arithmetic`, RelaxedPrecision arithmetic becomes binary16 after legalization (inputs,
// outputs, uniforms and images stay 32-bit, so no 16-bit storage feature is needed). Returns
// false with the optimizer's messages on failure.
bool Optimize(std::vector<uint32_t>& words,
              OptLevel level,
              bool half_arithmetic,
              std::string& messages);

// Removes debug names and HLSL semantic decorations (after reflection has read them).
bool StripReflectionInfo(std::vector<uint32_t>& words, bool keep_debug_info, std::string& messages);

// spirv-val with Vulkan 1.1 rules; false with the validator's message on failure.
bool Validate(const std::vector<uint32_t>& words, std::string& messages);

}  // namespace kiln::spirv

#endif  // KILN_SPIRV_OPTIMIZE_H_
