// Reflection of an optimized module with SPIRV-Cross (before debug names are stripped).
#ifndef KILN_SPIRV_REFLECT_H_
#define KILN_SPIRV_REFLECT_H_

#include <cstdint>
#include <string>
#include <vector>

#include "kiln/result.h"
#include "spirv/reflection.h"

namespace kiln::spirv {

// An internal error when SPIRV-Cross cannot parse the module.
Result<Reflection> Reflect(const std::vector<uint32_t>& words);

}  // namespace kiln::spirv

#endif  // KILN_SPIRV_REFLECT_H_
