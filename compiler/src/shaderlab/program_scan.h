// Finds `#pragma` lines in a program block body, skipping comments and string literals, and
// locates each pragma and argument in the .shader file.
#ifndef KILN_SHADERLAB_PROGRAM_SCAN_H_
#define KILN_SHADERLAB_PROGRAM_SCAN_H_

#include <string>
#include <string_view>
#include <vector>

#include "kiln/shaderlab/ast.h"

namespace kiln::shaderlab {

// A copy of `body` with comments and string literals blanked out; newlines and length kept, so
// offsets into the copy are offsets into the body.
std::string BlankComments(std::string_view body);

// `body_begin` is where `body` starts in its file.
std::vector<Pragma> ScanPragmas(std::string_view body, SourceLoc body_begin);

}  // namespace kiln::shaderlab

#endif  // KILN_SHADERLAB_PROGRAM_SCAN_H_
