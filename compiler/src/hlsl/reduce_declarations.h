// The top-level declarations the reduction (reduce.h) may drop when nothing an entry point reaches
// names them: a struct, a cbuffer or tbuffer, one resource (texture, buffer or sampler) and a
// `static` variable. What the compiler does with them unreached is drop them too (a type nothing
// uses declares nothing; the optimizer removes a block, resource or private variable nothing
// reads), so the program compiles to the same code, only sooner: Unity's includes declare a
// dozen cbuffers and some textures every program carries to glslang and the optimizer otherwise.
// Every other declaration stays: a loose uniform is a member of the `$Global` block, whose layout
// the stages of a variant share.
#ifndef KILN_HLSL_REDUCE_DECLARATIONS_H_
#define KILN_HLSL_REDUCE_DECLARATIONS_H_

#include <string_view>
#include <vector>

#include "hlsl/tokens.h"

namespace kiln::hlsl {

// For the item made of tokens [first, end) of `text` (a top-level declaration, not a function
// definition): true when it is one of the droppable kinds, its names then appended to `names`
// (a struct's or a resource's name, a cbuffer's and its members', a static variable's). Any
// shape not read with certainty gives false: the item is then kept as before.
bool DroppableDeclaration(std::string_view text,
                          const std::vector<Token>& tok,
                          size_t first,
                          size_t end,
                          std::vector<std::string_view>& names);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_REDUCE_DECLARATIONS_H_
