// glslang's HLSL front end, in-process: preprocessing and HLSL -> SPIR-V for one stage, with the
// DX9-compatible mode Unity-style Cg code needs (sampler2D, tex2D). glslang's global state is
// initialised once (InitializeGlslang) before any compile thread starts.
#ifndef KILN_FRONTEND_GLSLANG_STAGE_H_
#define KILN_FRONTEND_GLSLANG_STAGE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "kiln/pack/format.h"

namespace glslang {
class TShader;
}

namespace kiln::hlsl {
class Includer;
}

namespace kiln::frontend {

// Idempotent and thread-safe.
void InitializeGlslang();
// "12.0.0".
std::string GlslangVersion();

struct StageOutput {
    bool ok = false;
    std::string text;             // Preprocess: the preprocessed source
    std::vector<uint32_t> spirv;  // Compile: unoptimized SPIR-V
    std::string info_log;         // glslang's messages, converted by glslang_messages.h
    // Compile: glslang found no function named like the entry point (it would otherwise emit an
    // empty entry point and only warn); ok is false.
    bool entry_missing = false;
};

// `name` is the main file's name (an include's "including file" for the first level).
StageOutput Preprocess(pack::Stage stage,
                       const std::string& source,
                       const std::string& name,
                       hlsl::Includer& includer);

StageOutput Compile(pack::Stage stage,
                    const std::string& source,
                    const std::string& name,
                    const std::string& entry_point,
                    hlsl::Includer& includer,
                    bool debug_info);

}  // namespace kiln::frontend

#endif  // KILN_FRONTEND_GLSLANG_STAGE_H_
