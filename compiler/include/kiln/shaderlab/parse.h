// The ShaderLab front end: parse a .shader file into an AST, check it, and dump it.
#ifndef KILN_SHADERLAB_PARSE_H_
#define KILN_SHADERLAB_PARSE_H_

#include <cstddef>
#include <optional>
#include <string>

#include "kiln/diagnostic.h"
#include "kiln/shaderlab/ast.h"
#include "kiln/source.h"

namespace kiln::shaderlab {

struct ParseOptions {
    // Blocks nested deeper than this are rejected with kNestingTooDeep (and skipped), which keeps
    // every recursive walk of the tree bounded.
    size_t max_nesting = 64;
};

// Parses `source`. Errors are appended to `diags`; the parser recovers and keeps going, so the
// returned tree holds everything it could make sense of. Returns nullopt only when no
// `Shader "Name" { ... }` was found at all.
std::optional<Shader> Parse(const SourceFile& source,
                            DiagnosticList& diags,
                            const ParseOptions& options = {});

// Semantic checks on a parsed shader: duplicate or undeclared properties, property references of
// the wrong type, ranges, program blocks at the wrong level, unsupported GLSL and surface shaders.
void Check(const Shader& shader, const std::string& file, DiagnosticList& diags);

// Parse followed by Check.
std::optional<Shader> ParseAndCheck(const SourceFile& source,
                                    DiagnosticList& diags,
                                    const ParseOptions& options = {});

// Stable JSON dump of the tree (docs/ast-json.md) and an indented human-readable dump.
std::string DumpJson(const Shader& shader);
std::string DumpText(const Shader& shader);

}  // namespace kiln::shaderlab

#endif  // KILN_SHADERLAB_PARSE_H_
