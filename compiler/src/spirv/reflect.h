// Reflection of an optimized module with SPIRV-Cross (before debug names are stripped).
#ifndef KILN_SPIRV_REFLECT_H_
#define KILN_SPIRV_REFLECT_H_

#include <cstdint>
#include <string>
#include <vector>

#include "spirv/reflection.h"

namespace kiln::spirv {

// False with a message when SPIRV-Cross cannot parse the module (an internal error).
bool Reflect(const std::vector<uint32_t>& words, Reflection& out, std::string& error);

}  // namespace kiln::spirv

#endif  // KILN_SPIRV_REFLECT_H_
