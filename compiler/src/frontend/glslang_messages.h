// The one place where glslang's info log becomes Kiln diagnostics. glslang reports
// "ERROR: file:line: 'token' : message"; the file and line come from the `#line` directives the
// assembler wrote, so they already name the .shader or include file. glslang 12 prints no column
// for most messages: the column is the token's first whole-word occurrence on that line, or the
// column glslang gives in "error at column N" for parse errors, or the line's first non-blank.
#ifndef KILN_FRONTEND_GLSLANG_MESSAGES_H_
#define KILN_FRONTEND_GLSLANG_MESSAGES_H_

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kiln/diagnostic.h"

namespace kiln::frontend {

struct GlslangMessage {
    Severity severity = Severity::kError;
    std::string file;  // empty for messages without a place (link errors)
    uint32_t line = 0;
    uint32_t column = 0;  // 0: glslang gave none
    std::string token;
    std::string text;  // glslang's wording
};

// Splits an info log into messages; summary lines ("N compilation errors") are dropped and the
// column of "error at column N" lines is attached to the error on that line.
std::vector<GlslangMessage> ParseInfoLog(const std::string& log);

using SourceLookup = std::function<std::shared_ptr<const SourceFile>(const std::string& name)>;

// What the caller knows beyond the log, for better messages.
struct MessageContext {
    // Where #include looked, in order (a note on "cannot find include file").
    std::vector<std::string> include_search;
    // --unity-version (UNITY_VERSION; 0: none): a missing include of a file only some releases
    // ship gets a note naming them (hlsl/unity_versions.h).
    int unity_version = 0;
    // The identifiers of the program, for the "did you mean" of an unknown name; called only
    // when a message needs them.
    std::function<std::vector<std::string>()> identifiers;
    // The functions the program declares, for a call to no such function (which glslang reports
    // as "no matching overloaded function" too); called only when a message needs them.
    std::function<std::vector<std::string>()> functions;
};

// Converts to a Kiln diagnostic (K5001 error / K5002 warning) in Kiln's message style, with a
// range on the file's own line and column. A missing ';' is placed after the token it should
// follow (glslang reports it at the next token, often on the next line); a missing include file
// is placed on its name with the search path in a note; an unknown name gets the closest
// identifier of the program.
Diagnostic ToDiagnostic(const GlslangMessage& message,
                        const SourceLookup& lookup,
                        const MessageContext& context = {});

// House style for a glslang message: "'=' : cannot convert from ' const float'" -> "cannot
// convert from 'const float'".
std::string RewordMessage(const std::string& token, const std::string& text);

}  // namespace kiln::frontend

#endif  // KILN_FRONTEND_GLSLANG_MESSAGES_H_
