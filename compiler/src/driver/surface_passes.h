// Surface shaders (issue 39): each SubShader-level CGPROGRAM that a `#pragma surface` governs (in
// the program or in a CGINCLUDE it sees) is replaced by the passes Unity's surface-shader
// compiler generates for it (surface/generate.h), in its place among the SubShader's passes, so
// that everything after (variants, stripping, lint, kiln test, both render paths) treats them as
// hand-written passes. Each generated pass compiles, in order: its generated header, the
// CGINCLUDE blocks it sees, the shader's own program (at its own lines), its generated tail. The
// generated text is one file per surface program ("<shader> (generated)"): what `#line` names in
// generated code, what `kiln compile --emit-generated` writes, and where a diagnostic in
// generated code points, with a note naming the pass and the `#pragma surface` line.
#ifndef KILN_DRIVER_SURFACE_PASSES_H_
#define KILN_DRIVER_SURFACE_PASSES_H_

#include <memory>
#include <string>
#include <vector>

#include "hlsl/file_cache.h"
#include "hlsl/includer.h"
#include "kiln/diagnostic.h"
#include "kiln/shaderlab/ast.h"

namespace kiln::driver {

struct GeneratedSource {
    std::shared_ptr<const SourceFile> file;  // the generated ShaderLab
    std::string shader_file;                 // the .shader it was generated from
    SourceRange directive;                   // its `#pragma surface`
    struct PassLines {
        uint32_t first = 0, last = 0;  // lines of the generated file
        std::string name;              // FORWARD, FORWARD_DELTA, DEFERRED, ShadowCaster, Meta
    };
    std::vector<PassLines> passes;
};

// Generates the passes of every surface program of `shader` (read from `file`); the files their
// programs include are found through `paths`. Problems are K3008 (the surface function, its Input
// struct or the lighting model not found) and the directive's own (K4009, K4016).
void ExpandSurfaceShaders(shaderlab::Shader& shader,
                          const SourceFile& file,
                          const hlsl::IncludePaths& paths,
                          hlsl::FileCache& files,
                          std::vector<GeneratedSource>& generated,
                          DiagnosticList& diags);

// The generated source a diagnostic's file names, or null.
const GeneratedSource* FindGenerated(const std::vector<GeneratedSource>& generated,
                                     const std::string& file);

// Adds "in the code generated for pass X of the surface shader here" to a diagnostic placed in
// generated code.
void NoteGenerated(const std::vector<GeneratedSource>& generated, Diagnostic& d);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_SURFACE_PASSES_H_
