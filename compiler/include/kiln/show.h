// kiln show: what Kiln compiled, for one stage of one variant. The text glslang compiled comes
// from the compile itself (CompileOptions::keep_programs); the other views are made here from the
// SPIR-V module: SPIRV-Tools' disassembly, SPIRV-Cross's GLSL, ESSL, MSL and HLSL, and the
// reflection the pack records for the module.
#ifndef KILN_SHOW_H_
#define KILN_SHOW_H_

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "kiln/compile.h"
#include "kiln/pack/reader.h"
#include "kiln/result.h"

namespace kiln {

enum class ModuleView {
    kSpirv,      // SPIR-V assembly with friendly names (spirv-dis --friendly-names)
    kGlsl,       // GLSL 450 with Vulkan semantics (what glslangValidator -V reads)
    kEssl,       // ESSL 310 (OpenGL ES 3.1; images and samplers combined)
    kMsl,        // Metal Shading Language 2.1 (macOS)
    kCrossHlsl,  // HLSL shader model 5.0
};

// "spirv", "glsl", "essl", "msl", "cross-hlsl".
std::string_view ModuleViewName(ModuleView view);

// The text of `view` of a SPIR-V module. The module is validated (spirv-val, Vulkan 1.1) before
// any view is made, so bytes from an untrusted pack never reach SPIRV-Cross unchecked. Errors
// (K0031) give the validator's or SPIRV-Cross's message. Kiln strips names from the modules it
// stores: given the pack and the module's record, SPIRV-Cross's views name the uniform blocks and
// their members, push constants, resources and stage inputs and outputs as the pack's reflection
// records do (made into identifiers: "i.uv" -> "i_uv").
Result<std::string> ViewModule(std::span<const uint32_t> words,
                               ModuleView view,
                               const pack::Pack* pack = nullptr,
                               const pack::ModuleRec* module = nullptr);

// A preprocessed program's text (ProgramText::text) without its blank lines: each line keeps its
// file and line through `#line` directives, written only where a line does not follow the one
// before it, and redundant directives are dropped. What glslang reports against the text still
// maps to the same places.
std::string CompactProgramText(const std::string& text);

// One kept program as kiln show --hlsl and kiln compile -E print it: a comment naming its shader,
// pass, keywords (and how many more variants share the text), stage and entry point, then its
// compacted text.
std::string ProgramView(const ProgramText& program);

// The reflection a pack records for one of its modules (inputs and outputs, uniform blocks and
// push constants with their members, resources and their bindings), as text or as JSON.
std::string ReflectionText(const pack::Pack& pack, const pack::ModuleRec& module, bool json);

}  // namespace kiln

#endif  // KILN_SHOW_H_
