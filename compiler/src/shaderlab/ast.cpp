#include "kiln/shaderlab/ast.h"

#include "kiln/pack/format.h"

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

// The AST's property types are stored in packs as they are (pack_emit.cpp casts them), so the
// two enums must agree; the names live with the pack format.
static_assert(uint32_t(PropertyType::kColor) == uint32_t(pack::PropertyType::kColor));
static_assert(uint32_t(PropertyType::kRange) == uint32_t(pack::PropertyType::kRange));
static_assert(uint32_t(PropertyType::kTexture2D) == uint32_t(pack::PropertyType::kTexture2D));
static_assert(uint32_t(PropertyType::kCubeArray) == uint32_t(pack::PropertyType::kCubeArray));
static_assert(uint32_t(PropertyType::kTextureAny) == uint32_t(pack::PropertyType::kTextureAny));

const char* PropertyTypeName(PropertyType type) {
    return pack::PropertyTypeName(static_cast<pack::PropertyType>(type));
}

bool IsTextureType(PropertyType type) {
    return pack::IsTextureProperty(static_cast<pack::PropertyType>(type));
}

}  // namespace kiln::shaderlab
