// Flattens a parsed shader into the passes Kiln compiles: each with its program block, the
// CGINCLUDE/HLSLINCLUDE blocks it sees (Shader, Category, SubShader, Pass levels in that order),
// its tags (its own, then inherited ones) and its render state resolved across Category,
// SubShader and Pass (an inner level overrides a setting; Blend/BlendOp/ColorMask lists and the
// Stencil block are replaced as a whole).
#ifndef KILN_DRIVER_SHADER_PASSES_H_
#define KILN_DRIVER_SHADER_PASSES_H_

#include <string>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/format.h"
#include "kiln/shaderlab/ast.h"

namespace kiln::driver {

struct PassTag {
    std::string key, value;
};

struct StateSetting {
    pack::StateField field;
    int target = -1;
    shaderlab::StateValue value;
};

struct FlatPass {
    const shaderlab::Pass* pass = nullptr;
    uint32_t subshader = 0;
    int lod = 0;
    std::string label;                                   // `"FORWARD"` or `#2 of SubShader 1`
    std::vector<const shaderlab::ProgramBlock*> blocks;  // include blocks, then the program
    const shaderlab::ProgramBlock* program = nullptr;
    std::vector<PassTag> tags;
    std::vector<StateSetting> state;
};

// Passes in source order. UsePass/GrabPass and passes without a program are reported (warning /
// error) and skipped.
std::vector<FlatPass> FlattenPasses(const shaderlab::Shader& shader,
                                    const std::string& file,
                                    DiagnosticList& diags);

std::string TagValue(const FlatPass& pass, const std::string& key);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_SHADER_PASSES_H_
