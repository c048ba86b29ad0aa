// Builds the HLSL text glslang compiles for one (variant, stage): the prelude (what shader code
// expects from a Unity-style compiler), then the CGINCLUDE/HLSLINCLUDE blocks, then the program.
// Every block is preceded by a `#line` directive and indented to its column, so each glslang
// message names the .shader (or include) file's own line and column. This is the only place
// that writes `#line`.
#ifndef KILN_HLSL_ASSEMBLE_H_
#define KILN_HLSL_ASSEMBLE_H_

#include <string>
#include <utility>
#include <vector>

#include "kiln/pack/format.h"
#include "kiln/shaderlab/ast.h"

namespace kiln::hlsl {

inline constexpr const char* kPreludeName = "<kiln prelude>";
inline constexpr int kUnityVersion = 201940;  // the Unity API level the templates follow

struct AssembleInput {
    std::string file_name;                               // as given in #line (see LineName)
    std::vector<const shaderlab::ProgramBlock*> blocks;  // include blocks, then the program
    pack::Stage stage = pack::Stage::kVertex;
    int shader_target = 25;
    std::vector<std::string> keywords;                         // enabled in this variant and stage
    std::vector<std::pair<std::string, std::string>> defines;  // -D NAME=VALUE
};

std::string AssembleSource(const AssembleInput& in);

// The prelude alone (documented in docs/variants.md).
std::string Prelude(const AssembleInput& in);

// A file name safe inside `#line N "name"`; false when the path has characters that cannot be.
bool IsLineSafeName(const std::string& path);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_ASSEMBLE_H_
