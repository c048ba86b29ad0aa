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

const char* PropertyTypeName(PropertyType type) {
    switch (type) {
        case PropertyType::kColor:
            return "Color";
        case PropertyType::kVector:
            return "Vector";
        case PropertyType::kFloat:
            return "Float";
        case PropertyType::kInt:
            return "Int";
        case PropertyType::kInteger:
            return "Integer";
        case PropertyType::kRange:
            return "Range";
        case PropertyType::kTexture2D:
            return "2D";
        case PropertyType::kTexture3D:
            return "3D";
        case PropertyType::kCube:
            return "Cube";
        case PropertyType::kTexture2DArray:
            return "2DArray";
        case PropertyType::kCubeArray:
            return "CubeArray";
    }
    return "Float";
}

bool IsTextureType(PropertyType type) {
    return type == PropertyType::kTexture2D || type == PropertyType::kTexture3D ||
           type == PropertyType::kCube || type == PropertyType::kTexture2DArray ||
           type == PropertyType::kCubeArray;
}

}  // namespace kiln::shaderlab
