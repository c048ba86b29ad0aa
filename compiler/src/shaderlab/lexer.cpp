#include "lexer.h"

#include <cstring>

namespace kiln::shaderlab {
namespace {

bool IsIdentStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool IsDigit(char c) {
    return c >= '0' && c <= '9';
}
bool IsIdentChar(char c) {
    return IsIdentStart(c) || IsDigit(c);
}
bool IsSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

struct ProgramMarker {
    const char* open;
    const char* close;
    ProgramKind kind;
};

constexpr ProgramMarker kMarkers[] = {
    {"CGPROGRAM", "ENDCG", ProgramKind::kCgProgram},
    {"CGINCLUDE", "ENDCG", ProgramKind::kCgInclude},
    {"HLSLPROGRAM", "ENDHLSL", ProgramKind::kHlslProgram},
    {"HLSLINCLUDE", "ENDHLSL", ProgramKind::kHlslInclude},
    {"GLSLPROGRAM", "ENDGLSL", ProgramKind::kGlslProgram},
    {"GLSLINCLUDE", "ENDGLSL", ProgramKind::kGlslInclude},
};

struct State {
    const SourceFile& source;
    DiagnosticList& diags;
    std::string_view text;
    uint32_t pos = 0;
    uint32_t line = 1;
    uint32_t column = 1;
    std::vector<Token> tokens;

    SourceLoc Loc() const { return SourceLoc{pos, line, column}; }
    bool AtEnd() const { return pos >= text.size(); }
    char Peek(uint32_t ahead = 0) const {
        return pos + ahead < text.size() ? text[pos + ahead] : '\0';
    }
    void Advance() {
        if (text[pos] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
        ++pos;
    }
    void AdvanceTo(uint32_t end) {
        while (pos < end) {
            Advance();
        }
    }
    Token& Emit(TokenKind kind, SourceLoc begin) {
        Token t;
        t.kind = kind;
        t.range = SourceRange{begin, Loc()};
        t.text = text.substr(begin.offset, pos - begin.offset);
        tokens.push_back(t);
        return tokens.back();
    }
    void Error(DiagCode code, SourceLoc begin, std::string message) {
        diags.Error(code, source.path(), SourceRange{begin, Loc()}, std::move(message));
    }

    void SkipSpaceAndComments();
    void LexString();
    void LexNumberOrIdentifier();
    void LexIdentifier();
    void LexProgram(const ProgramMarker& marker, SourceLoc begin);
};

void State::SkipSpaceAndComments() {
    while (!AtEnd()) {
        const char c = Peek();
        if (IsSpace(c)) {
            Advance();
        } else if (c == '/' && Peek(1) == '/') {
            while (!AtEnd() && Peek() != '\n') {
                Advance();
            }
        } else if (c == '/' && Peek(1) == '*') {
            const SourceLoc begin = Loc();
            const size_t close = text.find("*/", pos + 2);
            if (close == std::string_view::npos) {
                AdvanceTo(begin.offset + 2);
                diags.Error(DiagCode::kUnterminatedComment, source.path(),
                            SourceRange{begin, Loc()}, "unterminated block comment");
                AdvanceTo(static_cast<uint32_t>(text.size()));
                return;
            }
            AdvanceTo(static_cast<uint32_t>(close + 2));
        } else {
            return;
        }
    }
}

void State::LexString() {
    const SourceLoc begin = Loc();
    Advance();  // opening quote
    while (!AtEnd() && Peek() != '"' && Peek() != '\n') {
        if (Peek() == '\\' && (Peek(1) == '"' || Peek(1) == '\\')) {
            Advance();
        }
        Advance();
    }
    if (Peek() != '"') {
        // Recover by ending the string at the end of the line.
        Token& t = Emit(TokenKind::kString, begin);
        t.text = text.substr(begin.offset + 1, pos - begin.offset - 1);
        diags.Error(DiagCode::kUnterminatedString, source.path(),
                    SourceRange{begin, SourceLoc{begin.offset + 1, begin.line, begin.column + 1}},
                    "unterminated string; expected '\"' before the end of the line");
        return;
    }
    Advance();  // closing quote
    Token& t = Emit(TokenKind::kString, begin);
    t.text = text.substr(begin.offset + 1, pos - begin.offset - 2);
}

void State::LexNumberOrIdentifier() {
    const SourceLoc begin = Loc();
    bool fractional = false;
    while (IsDigit(Peek())) {
        Advance();
    }
    if (Peek() == '.' && (IsDigit(Peek(1)) || pos > begin.offset)) {
        fractional = true;
        Advance();
        while (IsDigit(Peek())) {
            Advance();
        }
    }
    if ((Peek() == 'e' || Peek() == 'E') &&
        (IsDigit(Peek(1)) || ((Peek(1) == '-' || Peek(1) == '+') && IsDigit(Peek(2))))) {
        fractional = true;
        Advance();
        Advance();
        while (IsDigit(Peek())) {
            Advance();
        }
    }
    if (!fractional && IsIdentStart(Peek())) {
        // `2D`, `3D`, `2DArray`: texture type names start with a digit.
        while (IsIdentChar(Peek())) {
            Advance();
        }
        Emit(TokenKind::kIdentifier, begin);
        return;
    }
    Emit(TokenKind::kNumber, begin);
}

void State::LexIdentifier() {
    const SourceLoc begin = Loc();
    while (IsIdentChar(Peek())) {
        Advance();
    }
    const std::string_view word = text.substr(begin.offset, pos - begin.offset);
    for (const ProgramMarker& m : kMarkers) {
        if (word == m.open) {
            LexProgram(m, begin);
            return;
        }
    }
    Emit(TokenKind::kIdentifier, begin);
}

// Finds `word` as a whole word at or after `from`; npos when absent.
size_t FindWord(std::string_view text, std::string_view word, size_t from) {
    while (true) {
        const size_t at = text.find(word, from);
        if (at == std::string_view::npos) {
            return at;
        }
        const bool left_ok = at == 0 || !IsIdentChar(text[at - 1]);
        const size_t end = at + word.size();
        const bool right_ok = end >= text.size() || !IsIdentChar(text[end]);
        if (left_ok && right_ok) {
            return at;
        }
        from = at + 1;
    }
}

void State::LexProgram(const ProgramMarker& marker, SourceLoc begin) {
    const SourceLoc body_begin = Loc();
    const size_t close = FindWord(text, marker.close, pos);
    Token t;
    t.kind = TokenKind::kProgram;
    t.program_kind = marker.kind;
    t.body_begin = body_begin;
    if (close == std::string_view::npos) {
        diags.Error(DiagCode::kUnterminatedProgramBlock, source.path(), SourceRange{begin, Loc()},
                    std::string("unterminated ") + marker.open + " block; expected " +
                        marker.close + " before the end of the file");
        AdvanceTo(static_cast<uint32_t>(text.size()));
        t.text = text.substr(body_begin.offset);
    } else {
        t.text = text.substr(body_begin.offset, close - body_begin.offset);
        AdvanceTo(static_cast<uint32_t>(close + std::strlen(marker.close)));
    }
    t.range = SourceRange{begin, Loc()};
    tokens.push_back(t);
}

}  // namespace

std::vector<Token> Lex(const SourceFile& source, DiagnosticList& diags) {
    State s{source, diags, source.text(), 0, 1, 1, {}};
    // A UTF-8 byte-order mark (many Unity project files start with one) is not part of the text;
    // columns on the first line still count from the first byte after it.
    if (s.text.substr(0, 3) == kUtf8Bom) {
        s.pos = 3;
    }
    while (true) {
        s.SkipSpaceAndComments();
        if (s.AtEnd()) {
            break;
        }
        const SourceLoc begin = s.Loc();
        const char c = s.Peek();
        TokenKind punct = TokenKind::kEof;
        switch (c) {
            case '{':
                punct = TokenKind::kLBrace;
                break;
            case '}':
                punct = TokenKind::kRBrace;
                break;
            case '(':
                punct = TokenKind::kLParen;
                break;
            case ')':
                punct = TokenKind::kRParen;
                break;
            case '[':
                punct = TokenKind::kLBracket;
                break;
            case ']':
                punct = TokenKind::kRBracket;
                break;
            case ',':
                punct = TokenKind::kComma;
                break;
            case '=':
                punct = TokenKind::kEquals;
                break;
            case '-':
                punct = TokenKind::kMinus;
                break;
            case '+':
                punct = TokenKind::kPlus;
                break;
            default:
                break;
        }
        if (punct != TokenKind::kEof) {
            s.Advance();
            s.Emit(punct, begin);
        } else if (c == '"') {
            s.LexString();
        } else if (IsDigit(c) || (c == '.' && IsDigit(s.Peek(1)))) {
            s.LexNumberOrIdentifier();
        } else if (IsIdentStart(c)) {
            s.LexIdentifier();
        } else {
            // One token for a whole run of bytes that start nothing, so binary garbage stays cheap.
            while (!s.AtEnd()) {
                const char d = s.Peek();
                if (IsSpace(d) || IsIdentChar(d) ||
                    (d != '\0' && std::strchr("{}()[],=-+\"/.", d) != nullptr)) {
                    break;
                }
                s.Advance();
            }
            if (s.pos == begin.offset) {
                s.Advance();  // a lone '/' or '.'
            }
            s.Emit(TokenKind::kUnknown, begin);
        }
    }
    s.Emit(TokenKind::kEof, s.Loc());
    return std::move(s.tokens);
}

}  // namespace kiln::shaderlab
