// Functions in a surface shader's tokenized text (hlsl/tokens.h): where one is defined and its
// parameters, for the surface, vertex and lighting functions the generator calls.
#ifndef KILN_SURFACE_FUNCTIONS_H_
#define KILN_SURFACE_FUNCTIONS_H_

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "hlsl/tokens.h"

namespace kiln::surface {

struct Param {
    std::string qualifier;  // in, out, inout, uniform or ""
    std::string type, name;
};

// The definition of function `name` (not a call or a prototype): the index of its `(`, or
// SIZE_MAX. `close` gets its `)`, `body` its `{`.
size_t FindDefinition(const std::vector<hlsl::Token>& tok,
                      std::string_view name,
                      size_t& close,
                      size_t& body);

// The parameters between the `(` at `open` and the `)` at `close`.
std::vector<Param> Params(const std::vector<hlsl::Token>& tok, size_t open, size_t close);

}  // namespace kiln::surface

#endif  // KILN_SURFACE_FUNCTIONS_H_
