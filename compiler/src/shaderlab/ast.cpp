#include "kiln/shaderlab/ast.h"

namespace kiln::shaderlab {

bool IsIncludeBlock(ProgramKind kind) {
    return kind == ProgramKind::kCgInclude || kind == ProgramKind::kHlslInclude ||
           kind == ProgramKind::kGlslInclude;
}

const char* ProgramKindName(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::kCgProgram:
            return "CGPROGRAM";
        case ProgramKind::kCgInclude:
            return "CGINCLUDE";
        case ProgramKind::kHlslProgram:
            return "HLSLPROGRAM";
        case ProgramKind::kHlslInclude:
            return "HLSLINCLUDE";
        case ProgramKind::kGlslProgram:
            return "GLSLPROGRAM";
        case ProgramKind::kGlslInclude:
            return "GLSLINCLUDE";
    }
    return "CGPROGRAM";
}

}  // namespace kiln::shaderlab
