// ShaderLab lexer. Program blocks (CGPROGRAM ... ENDCG and friends) become one token holding the
// verbatim body, so the parser never sees HLSL. Bytes that start no token become kUnknown tokens
// (one per run) and are reported by the parser only where it meets them.
#ifndef KILN_SHADERLAB_LEXER_H_
#define KILN_SHADERLAB_LEXER_H_

#include <string_view>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/shaderlab/ast.h"
#include "kiln/source.h"

namespace kiln::shaderlab {

enum class TokenKind {
    kEof,
    kIdentifier,  // also `2D`, `3D`, `2DArray`: digits followed by letters
    kNumber,
    kString,  // text = the characters between the quotes, escapes not yet decoded
    kLBrace,
    kRBrace,
    kLParen,
    kRParen,
    kLBracket,
    kRBracket,
    kComma,
    kEquals,
    kMinus,
    kPlus,
    kProgram,  // text = body; program_kind, body_begin set
    kUnknown,
};

struct Token {
    TokenKind kind = TokenKind::kEof;
    SourceRange range;
    std::string_view text;  // points into the SourceFile
    ProgramKind program_kind = ProgramKind::kCgProgram;
    SourceLoc body_begin;
};

// Tokenizes the whole file; the result always ends with one kEof token.
std::vector<Token> Lex(const SourceFile& source, DiagnosticList& diags);

}  // namespace kiln::shaderlab

#endif  // KILN_SHADERLAB_LEXER_H_
