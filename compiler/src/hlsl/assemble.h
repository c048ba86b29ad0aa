// Builds the HLSL text glslang compiles for one (variant, stage): the prelude (Unity's compile
// environment for the Vulkan target: the macros its compiler predefines and, for CGPROGRAM, the
// files it includes implicitly; docs/unity-compat.md), then the CGINCLUDE/HLSLINCLUDE blocks,
// then the program. Every block is preceded by a `#line` directive and indented to its column, so
// each glslang message names the .shader (or include) file's own line and column. This is the
// only place that writes `#line`.
#ifndef KILN_HLSL_ASSEMBLE_H_
#define KILN_HLSL_ASSEMBLE_H_

#include <string>
#include <utility>
#include <vector>

#include "kiln/pack/format.h"
#include "kiln/shaderlab/ast.h"

namespace kiln::hlsl {

inline constexpr const char* kPreludeName = "<kiln prelude>";

// Files Unity's compiler includes in front of every CGPROGRAM (not HLSLPROGRAM), in order.
inline constexpr const char* kImplicitIncludes[] = {
    "HLSLSupport.cginc", "UnityShaderVariables.cginc", "UnityShaderUtilities.cginc"};

// Unity's SHADER_STAGE_* macro of a stage, which the prelude defines to 1.
const char* StageMacro(pack::Stage stage);

struct AssembleInput {
    std::string file_name;                               // as given in #line (see LineName)
    std::vector<const shaderlab::ProgramBlock*> blocks;  // include blocks, then the program
    pack::Stage stage = pack::Stage::kVertex;
    int shader_target = 25;
    int unity_version = 202230;                          // UNITY_VERSION
    pack::Precision precision = pack::Precision::kFull;  // KILN_PRECISION_RELAXED / _HALF
    std::string light_mode;  // the pass's LightMode tag: UNITY_PASS_FORWARDBASE and so on
    std::vector<std::string> keywords;                         // enabled in this variant and stage
    std::vector<std::pair<std::string, std::string>> defines;  // -D NAME=VALUE
    std::vector<std::string> undefines;                        // -U NAME
    std::vector<std::string> forced_includes;                  // --include FILE
};

std::string AssembleSource(const AssembleInput& in);

// The prelude alone (documented in docs/unity-compat.md).
std::string Prelude(const AssembleInput& in);

// UNITY_PASS_<NAME> for a LightMode tag value (compared without case), or "" for none.
std::string PassMacro(const std::string& light_mode);

// The macros the prelude defines before -D and keywords: (name, value), in order.
std::vector<std::pair<std::string, std::string>> PredefinedMacros(const AssembleInput& in);

// A file name safe inside `#line N "name"`; false when the path has characters that cannot be.
bool IsLineSafeName(const std::string& path);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_ASSEMBLE_H_
