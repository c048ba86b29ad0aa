// Flattens a parsed shader into the passes Kiln compiles: each with its program block, the
// CGINCLUDE/HLSLINCLUDE blocks it sees (Shader, Category, SubShader, Pass levels in that order),
// its tags (its own, then inherited ones) and its render state resolved across Category,
// SubShader and Pass (an inner level overrides a setting; Blend/BlendOp/ColorMask lists and the
// Stencil block are replaced as a whole).
#ifndef KILN_DRIVER_SHADER_PASSES_H_
#define KILN_DRIVER_SHADER_PASSES_H_

#include <memory>
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
    // `UsePass "Shader/PASS"`: set (and nothing else) until the compile resolves it to a copy of
    // that pass (driver/use_pass.cpp), whose blocks are in `source`'s file.
    const shaderlab::UsePass* use_pass = nullptr;
    // A GrabPass: no program; the pack records it (kPassGrab) with its texture, in its place.
    const shaderlab::GrabPass* grab = nullptr;
    std::shared_ptr<const SourceFile> source;  // null: the pass's own shader file
    uint32_t subshader = 0;
    int lod = 0;
    std::string light_mode;  // the LightMode tag, "" when untagged
    std::string label;  // the pass's one name (kiln/pack/pass_id.h): `FORWARD`, `ForwardBase`, `#2`
    std::vector<const shaderlab::ProgramBlock*> blocks;  // include blocks, then the program
    const shaderlab::ProgramBlock* program = nullptr;
    // The program generated from fixed-function commands (hlsl/fixed_function.h) when the pass
    // has none of its own; `program` then points here.
    std::shared_ptr<const shaderlab::ProgramBlock> generated;
    std::vector<PassTag> tags;
    std::vector<StateSetting> state;
};

// Passes in source order. A UsePass is a placeholder the compile resolves; a GrabPass has no
// program (it is compiled into nothing: the runtime copies the colour target); a pass without a
// program gets one generated from its fixed-function commands, as in Unity.
std::vector<FlatPass> FlattenPasses(const shaderlab::Shader& shader,
                                    const std::string& file,
                                    DiagnosticList& diags);

// Names each pass (FlatPass::label) by its Name, LightMode and place in its SubShader.
void LabelPasses(std::vector<FlatPass>& passes);

std::string TagValue(const FlatPass& pass, const std::string& key);

// The tag that sets a pass's variant budget ("KilnMaxVariants" = "48", on the Pass or its
// SubShader): the pass may have at most the smaller of it and --max-variants.
inline constexpr const char* kTagMaxVariants = "KilnMaxVariants";
// The most variants `pass` may have; a tag value that is not a positive integer is an error
// (K4020), and the limit is then `max_variants`.
uint64_t VariantBudget(const FlatPass& pass,
                       uint64_t max_variants,
                       const std::string& file,
                       DiagnosticList& diags);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_SHADER_PASSES_H_
