// Tokens of preprocessed HLSL text, for the source rewrites (rewrite.h): identifiers, numbers,
// strings and operators with their byte ranges; directive lines (#line, #pragma) are skipped.
// Also the helpers the rewrites share: bracket matching, replacement edits, and the place
// (#line file and line) of an offset, for the warnings a rewrite gives.
#ifndef KILN_HLSL_TOKENS_H_
#define KILN_HLSL_TOKENS_H_

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace kiln::hlsl {

struct Token {
    size_t begin = 0, end = 0;
    bool ident = false;
    std::string_view text;
};

std::vector<Token> Tokenize(const std::string& s);

// Tokenize(s) where s starts with the text `head` was made from, of `head_bytes` bytes, and a line
// break follows it: `head`'s tokens, moved onto s, and the rest's. The caller checks that s starts
// with that text.
std::vector<Token> TokenizeAfter(const std::string& s,
                                 size_t head_bytes,
                                 const std::vector<Token>& head);

// True when `a` and `b` are the same tokens of one text: the same byte ranges and kinds, each
// viewing the same bytes (so two lists of two copies of a text differ).
bool SameTokens(const std::vector<Token>& a, const std::vector<Token>& b);

// A replacement of bytes [begin, end) of the text.
struct Edit {
    size_t begin, end;
    std::string text;
};

// A warning a rewrite gives, placed by the text's #line directives.
struct RewriteWarning {
    std::string file;
    unsigned line = 0;
    std::string token;  // the word the message is about (its column on the line)
    std::string message;
};

bool IsAssignment(std::string_view op);

// The shape of an HLSL numeric type name (float, half, fixed, int, uint, bool, double and the
// min16/min10/min12 kinds): 0 not one, 1 a scalar (or a 1-vector), 2-4 a vector of that size,
// 5 a matrix. The one reading of type names the rewrites share.
int NumericShape(std::string_view t);

// Words that can precede `name ;` without declaring it (return, in, out, static, ...).
bool IsStatementWord(std::string_view t);

// Index of the bracket that opens the one closing at `close` (`)` or `]` or `}`), or SIZE_MAX.
size_t MatchBack(const std::vector<Token>& tok, size_t close);

// Index of the bracket that closes the one opening at `open` (`(`, `[` or `{`), or SIZE_MAX.
size_t MatchForward(const std::vector<Token>& tok, size_t open);

// The file and line of byte `offset` of preprocessed text, from its last `#line N "file"` before
// the offset and the newlines since.
RewriteWarning PlaceOf(const std::string& text, size_t offset);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_TOKENS_H_
