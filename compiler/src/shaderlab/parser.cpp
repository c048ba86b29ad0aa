#include "parser.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "kiln/pack/names.h"
#include "program_scan.h"

namespace kiln::shaderlab {

std::optional<double> ParseDouble(std::string_view text) {
    double v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) {
        return std::nullopt;
    }
    return v;
}

namespace {

std::string Clip(std::string_view text, size_t max = 48) {
    return text.size() <= max ? std::string(text) : std::string(text.substr(0, max)) + "...";
}

std::string DecodeString(std::string_view raw) {
    std::string out;
    out.reserve(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] == '\\' && i + 1 < raw.size() && (raw[i + 1] == '"' || raw[i + 1] == '\\')) {
            ++i;
        }
        out += raw[i];
    }
    return out;
}

const char* LevelName(int level) {
    static const char* const kNames[] = {"Shader", "Category", "SubShader", "Pass", "GrabPass"};
    return kNames[level];
}

// Where a command belongs, for "'X' is not allowed in a Pass; it belongs in ..." messages.
const char* HomeOf(std::string_view word) {
    struct Home {
        const char* word;
        const char* home;
    };
    static const Home kHomes[] = {
        {"Pass", "a SubShader"},
        {"UsePass", "a SubShader"},
        {"GrabPass", "a SubShader"},
        {"LOD", "a SubShader, Pass or Category"},
        {"SubShader", "a Shader or Category"},
        {"Category", "a Shader or Category"},
        {"Properties", "the Shader block"},
        {"Fallback", "the Shader block"},
        {"CustomEditor", "the Shader block"},
        {"Dependency", "the Shader block"},
        {"Name", "a Pass or GrabPass"},
        {"Tags", "a SubShader, Pass or Category"},
        {"Cull", "a SubShader, Pass or Category"},
        {"ZTest", "a SubShader, Pass or Category"},
        {"ZWrite", "a SubShader, Pass or Category"},
        {"ZClip", "a SubShader, Pass or Category"},
        {"Blend", "a SubShader, Pass or Category"},
        {"BlendOp", "a SubShader, Pass or Category"},
        {"ColorMask", "a SubShader, Pass or Category"},
        {"Offset", "a SubShader, Pass or Category"},
        {"AlphaToMask", "a SubShader, Pass or Category"},
        {"Stencil", "a SubShader, Pass or Category"},
        {"Conservative", "a SubShader, Pass or Category"},
    };
    for (const Home& h : kHomes) {
        if (EqualsIgnoreCase(word, h.word)) {
            return h.home;
        }
    }
    return nullptr;
}

bool IsLegacyCommand(std::string_view word) {
    // Fixed-function commands Kiln does not translate (parser_fixed_function.cpp has the rest).
    static const char* const kLegacy[] = {"PackageRequirements", "TexGen", "Matrix"};
    for (const char* w : kLegacy) {
        if (EqualsIgnoreCase(word, w)) {
            return true;
        }
    }
    return false;
}

}  // namespace

Parser::Parser(const SourceFile& source,
               std::vector<Token> tokens,
               DiagnosticList& diags,
               const ParseOptions& options)
    : source_(source), tokens_(std::move(tokens)), diags_(diags), options_(options) {}

const Token& Parser::Peek(size_t ahead) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
}

const Token& Parser::Next() {
    const Token& t = tokens_[pos_];
    if (pos_ + 1 < tokens_.size()) {
        ++pos_;
    }
    return t;
}

bool Parser::AtWord(std::string_view word) const {
    return Peek().kind == TokenKind::kIdentifier && EqualsIgnoreCase(Peek().text, word);
}

bool Parser::Accept(TokenKind kind) {
    if (!At(kind)) {
        return false;
    }
    Next();
    return true;
}

const Token* Parser::Expect(TokenKind kind, std::string_view what, std::string_view context) {
    if (At(kind)) {
        return &Next();
    }
    const Token& t = Peek();
    Error(t.kind == TokenKind::kUnknown ? DiagCode::kUnexpectedCharacter : DiagCode::kExpectedToken,
          t.range,
          "expected " + std::string(what) + " " + std::string(context) + ", found " + Describe(t));
    return nullptr;
}

std::string Parser::Describe(const Token& t) {
    switch (t.kind) {
        case TokenKind::kEof:
            return "end of file";
        case TokenKind::kNumber:
            return "number " + Clip(t.text);
        case TokenKind::kString:
            return "string \"" + Clip(t.text) + "\"";
        case TokenKind::kProgram:
            return std::string("'") + ProgramKindName(t.program_kind) + "' block";
        case TokenKind::kUnknown: {
            const unsigned char c = static_cast<unsigned char>(t.text.empty() ? 0 : t.text[0]);
            if (c >= 0x20 && c < 0x7f) {
                return std::string("character '") + char(c) + "'";
            }
            char buf[16];
            std::snprintf(buf, sizeof buf, "byte 0x%02x", c);
            return buf;
        }
        default:
            return "'" + Clip(t.text) + "'";
    }
}

SourceRange Parser::RangeFrom(const Token& first) const {
    const SourceLoc end = pos_ > 0 ? tokens_[pos_ - 1].range.end : first.range.end;
    return SourceRange{first.range.begin,
                       end.offset >= first.range.end.offset ? end : first.range.end};
}

Diagnostic& Parser::Error(DiagCode code, SourceRange range, std::string message) {
    return diags_.Error(code, source_.path(), range, std::move(message));
}

Diagnostic& Parser::Warning(DiagCode code, SourceRange range, std::string message) {
    return diags_.Warning(code, source_.path(), range, std::move(message));
}

void Parser::ErrorUnexpected(const Token& t, std::string_view context) {
    Error(
        t.kind == TokenKind::kUnknown ? DiagCode::kUnexpectedCharacter : DiagCode::kUnexpectedToken,
        t.range, "unexpected " + Describe(t) + " " + std::string(context));
}

void Parser::WarnDuplicate(DiagCode code,
                           SourceRange range,
                           const std::string& what,
                           SourceRange previous) {
    Warning(code, range, "duplicate " + what + "; the last one wins")
        .notes.push_back({source_.path(), previous, "previous one here"});
}

bool Parser::ParseBlock(std::string_view what, const std::function<bool()>& item) {
    const Token* open = Expect(TokenKind::kLBrace, "'{'", "after " + std::string(what));
    if (open == nullptr) {
        return false;
    }
    const Token open_token = *open;
    if (depth_ >= options_.max_nesting) {
        Error(DiagCode::kNestingTooDeep, open_token.range,
              "blocks are nested more than " + std::to_string(options_.max_nesting) +
                  " levels deep; this block is skipped");
        --pos_;  // back onto the '{'
        SkipBalanced();
        return true;
    }
    ++depth_;
    while (true) {
        if (Accept(TokenKind::kRBrace)) {
            break;
        }
        if (At(TokenKind::kEof) || diags_.saturated()) {
            if (!reported_eof_ && !diags_.saturated()) {
                reported_eof_ = true;
                Diagnostic& d =
                    Error(DiagCode::kUnclosedBlock, Peek().range,
                          "expected '}' to close " + std::string(what) + ", found end of file");
                d.notes.push_back(
                    {source_.path(), open_token.range, std::string(what) + " block opened here"});
            }
            pos_ = tokens_.size() - 1;
            break;
        }
        const size_t start = pos_;
        const uint32_t line = Peek().range.begin.line;
        if (!item()) {
            SkipCommand(start, line);
        }
        if (pos_ == start && !At(TokenKind::kRBrace)) {
            Next();  // always make progress
        }
    }
    --depth_;
    return true;
}

void Parser::SkipCommand(size_t start, uint32_t line) {
    while (true) {
        const Token& t = Peek();
        if (t.kind == TokenKind::kEof || t.kind == TokenKind::kRBrace) {
            return;
        }
        if (pos_ > start && t.range.begin.line != line) {
            return;
        }
        if (t.kind == TokenKind::kLBrace) {
            SkipBalanced();
            return;
        }
        Next();
    }
}

void Parser::SkipBalanced() {
    size_t depth = 0;
    do {
        const Token& t = Next();
        if (t.kind == TokenKind::kLBrace) {
            ++depth;
        } else if (t.kind == TokenKind::kRBrace) {
            --depth;
        } else if (t.kind == TokenKind::kEof) {
            return;
        }
    } while (depth > 0);
}

std::optional<Shader> Parser::ParseFile() {
    if (!AtWord("Shader")) {
        const Token& t = Peek();
        Error(t.kind == TokenKind::kUnknown ? DiagCode::kUnexpectedCharacter
                                            : DiagCode::kExpectedShader,
              t.range, "expected 'Shader \"Name\" { ... }', found " + Describe(t));
        while (!At(TokenKind::kEof) && !AtWord("Shader")) {
            Next();
        }
        if (At(TokenKind::kEof)) {
            return std::nullopt;
        }
    }
    Shader shader = ParseShader();
    if (!At(TokenKind::kEof) && !diags_.saturated()) {
        ErrorUnexpected(Peek(), "after the end of the Shader block");
    }
    return shader;
}

Shader Parser::ParseShader() {
    const Token& kw = Next();
    Shader shader;
    if (const Token* name = Expect(TokenKind::kString, "a shader name string", "after 'Shader'")) {
        shader.name = DecodeString(name->text);
        shader.name_range = name->range;
    }
    ParseBlock("'Shader'", [&] { return ParseShaderItem(shader); });
    shader.range = RangeFrom(kw);
    return shader;
}

bool Parser::ParseShaderItem(Shader& shader) {
    if (At(TokenKind::kProgram)) {
        return ParseProgram(shader.programs);
    }
    if (AtWord("Properties")) {
        return ParseProperties(shader);
    }
    if (AtWord("SubShader")) {
        SubShader sub;
        const bool ok = ParseSubShader(sub);
        shader.subshaders.emplace_back(std::move(sub));
        return ok;
    }
    if (AtWord("Category")) {
        std::unique_ptr<Category> cat;
        const bool ok = ParseCategory(cat);
        shader.subshaders.emplace_back(std::move(cat));
        return ok;
    }
    if (AtWord("Fallback")) {
        return ParseFallback(shader);
    }
    if (AtWord("CustomEditor")) {
        std::string editor;
        const bool ok = ParseStringArg(editor, "CustomEditor");
        shader.custom_editor = std::move(editor);
        return ok;
    }
    if (AtWord("Dependency")) {
        return ParseDependency(shader);
    }
    return ReportMisplacedOrUnknown(Level::kShader);
}

bool Parser::ParseFallback(Shader& shader) {
    const Token& kw = Next();
    Fallback fb;
    if (AtWord("Off")) {
        Next();
        fb.off = true;
    } else if (const Token* name =
                   Expect(TokenKind::kString, "a shader name or 'Off'", "after 'Fallback'")) {
        fb.name = DecodeString(name->text);
    } else {
        return false;
    }
    fb.range = RangeFrom(kw);
    shader.fallback = fb;
    return true;
}

bool Parser::ParseDependency(Shader& shader) {
    const Token& kw = Next();
    Dependency dep;
    const Token* key = Expect(TokenKind::kString, "a dependency name string", "after 'Dependency'");
    if (key == nullptr || !Expect(TokenKind::kEquals, "'='", "after the dependency name")) {
        return false;
    }
    const Token* value = Expect(TokenKind::kString, "a shader name string", "after '='");
    if (value == nullptr) {
        return false;
    }
    dep.key = DecodeString(key->text);
    dep.value = DecodeString(value->text);
    dep.range = RangeFrom(kw);
    shader.dependencies.push_back(std::move(dep));
    return true;
}

bool Parser::ParseStringArg(std::string& out, std::string_view command) {
    Next();
    const Token* s = Expect(TokenKind::kString, "a string", "after '" + std::string(command) + "'");
    if (s == nullptr) {
        return false;
    }
    out = DecodeString(s->text);
    return true;
}

bool Parser::ParseCategory(std::unique_ptr<Category>& out) {
    const Token& kw = Next();
    out = std::make_unique<Category>();
    Category& cat = *out;
    const bool ok = ParseBlock("'Category'", [&] {
        if (AtWord("SubShader")) {
            SubShader sub;
            const bool sub_ok = ParseSubShader(sub);
            cat.children.emplace_back(std::move(sub));
            return sub_ok;
        }
        if (AtWord("Category")) {
            std::unique_ptr<Category> inner;
            const bool inner_ok = ParseCategory(inner);
            cat.children.emplace_back(std::move(inner));
            return inner_ok;
        }
        if (AtWord("LOD")) {
            return ParseLod(cat.lod);
        }
        bool item_ok = false;
        if (TryCommonCommand(cat.tags, cat.state, cat.fixed, cat.programs, false, item_ok)) {
            return item_ok;
        }
        return ReportMisplacedOrUnknown(Level::kCategory);
    });
    cat.range = RangeFrom(kw);
    return ok;
}

bool Parser::ParseSubShader(SubShader& sub) {
    const Token& kw = Next();
    const bool ok = ParseBlock("'SubShader'", [&] {
        if (AtWord("Pass")) {
            Pass pass;
            const bool pass_ok = ParsePass(pass);
            sub.passes.emplace_back(std::move(pass));
            return pass_ok;
        }
        if (AtWord("UsePass")) {
            return ParseUsePass(sub);
        }
        if (AtWord("GrabPass")) {
            return ParseGrabPass(sub);
        }
        if (AtWord("LOD")) {
            return ParseLod(sub.lod);
        }
        bool item_ok = false;
        if (TryCommonCommand(sub.tags, sub.state, sub.fixed, sub.programs, false, item_ok)) {
            return item_ok;
        }
        return ReportMisplacedOrUnknown(Level::kSubShader);
    });
    sub.range = RangeFrom(kw);
    return ok;
}

bool Parser::ParsePass(Pass& pass) {
    const Token& kw = Next();
    const bool ok = ParseBlock("'Pass'", [&] {
        if (AtWord("Name")) {
            return ParseStringArg(pass.name, "Name");
        }
        if (AtWord("LOD")) {
            return ParseLod(pass.lod);
        }
        bool item_ok = false;
        if (TryCommonCommand(pass.tags, pass.state, pass.fixed, pass.programs, true, item_ok)) {
            return item_ok;
        }
        return ReportMisplacedOrUnknown(Level::kPass);
    });
    pass.range = RangeFrom(kw);
    return ok;
}

bool Parser::ParseUsePass(SubShader& sub) {
    const Token& kw = Next();
    const Token* target =
        Expect(TokenKind::kString, "a \"Shader/PASSNAME\" string", "after 'UsePass'");
    if (target == nullptr) {
        return false;
    }
    sub.passes.emplace_back(UsePass{RangeFrom(kw), DecodeString(target->text)});
    return true;
}

bool Parser::ParseGrabPass(SubShader& sub) {
    const Token& kw = Next();
    GrabPass grab;
    const bool ok = ParseBlock("'GrabPass'", [&] {
        if (At(TokenKind::kString)) {
            grab.texture_name = DecodeString(Next().text);
            return true;
        }
        if (AtWord("Name")) {
            return ParseStringArg(grab.name, "Name");
        }
        if (AtWord("Tags")) {
            return ParseTags(grab.tags);
        }
        return ReportMisplacedOrUnknown(Level::kGrabPass);
    });
    grab.range = RangeFrom(kw);
    sub.passes.emplace_back(std::move(grab));
    return ok;
}

bool Parser::TryCommonCommand(std::vector<Tag>& tags,
                              RenderState& state,
                              FixedFunction& fixed,
                              std::vector<ProgramBlock>& programs,
                              bool in_pass,
                              bool& ok) {
    if (At(TokenKind::kProgram)) {
        ok = ParseProgram(programs);
        return true;
    }
    if (AtWord("Tags")) {
        ok = ParseTags(tags);
        return true;
    }
    if (TryStateCommand(state, ok)) {
        return true;
    }
    if (TryFixedFunctionCommand(fixed, in_pass, ok)) {
        return true;
    }
    if (Peek().kind == TokenKind::kIdentifier && IsLegacyCommand(Peek().text)) {
        Warning(DiagCode::kLegacyCommandIgnored, Peek().range,
                "legacy fixed-function command '" + std::string(Peek().text) +
                    "' is not supported by Kiln and is ignored");
        ok = false;  // skip the rest of the command
        return true;
    }
    return false;
}

bool Parser::ReportMisplacedOrUnknown(Level level) {
    const Token& t = Peek();
    const std::string where = std::string("in a ") + LevelName(static_cast<int>(level)) + " block";
    if (t.kind != TokenKind::kIdentifier) {
        ErrorUnexpected(t, where);
        return false;
    }
    if (t.text == "ENDCG" || t.text == "ENDHLSL" || t.text == "ENDGLSL") {
        Error(DiagCode::kStrayProgramEnd, t.range,
              "'" + std::string(t.text) + "' without a matching program block start");
        return false;
    }
    if (const char* home = HomeOf(t.text)) {
        Error(DiagCode::kMisplacedCommand, t.range,
              "'" + Clip(t.text) + "' is not allowed " + where + "; it belongs in " + home);
        return false;
    }
    // Every command word ShaderLab has, for the "did you mean" of a typo such as ZWirte.
    static const std::vector<std::string> kCommands = {
        "Pass",     "UsePass",      "GrabPass",   "LOD",          "SubShader", "Category",
        "Properties", "Fallback",   "CustomEditor", "Dependency", "Name",      "Tags",
        "Cull",     "ZTest",        "ZWrite",     "ZClip",        "Blend",     "BlendOp",
        "ColorMask", "Offset",      "AlphaToMask", "Stencil",     "Conservative", "Lighting",
        "Material", "SetTexture",   "Fog",        "AlphaTest",    "ColorMaterial",
        "SeparateSpecular", "BindChannels", "CGPROGRAM", "HLSLPROGRAM", "CGINCLUDE",
        "HLSLINCLUDE"};
    Error(DiagCode::kUnknownCommand, t.range,
          "unknown command '" + Clip(t.text) + "' " + where +
              pack::DidYouMean(std::string(t.text), kCommands));
    return false;
}

bool Parser::ParseTags(std::vector<Tag>& tags) {
    Next();
    return ParseBlock("'Tags'", [&] {
        if (Accept(TokenKind::kComma)) {
            return true;
        }
        const Token& first = Peek();
        const Token* key = Expect(TokenKind::kString, "a tag name string", "in a Tags block");
        if (key == nullptr || !Expect(TokenKind::kEquals, "'='", "after the tag name")) {
            return false;
        }
        const Token* value = Expect(TokenKind::kString, "a tag value string", "after '='");
        if (value == nullptr) {
            return false;
        }
        Tag tag{DecodeString(key->text), DecodeString(value->text), RangeFrom(first)};
        for (const Tag& other : tags) {
            if (other.key == tag.key) {
                WarnDuplicate(DiagCode::kDuplicateTag, tag.range, "tag '" + Clip(tag.key) + "'",
                              other.range);
            }
        }
        tags.push_back(std::move(tag));
        return true;
    });
}

bool Parser::ParseLod(std::optional<int>& lod) {
    Next();
    const Token* n = Expect(TokenKind::kNumber, "a level of detail number", "after 'LOD'");
    if (n == nullptr) {
        return false;
    }
    const std::optional<double> v = ParseDouble(n->text);
    if (!v || *v < 0 || *v > 1e9 || *v != static_cast<double>(static_cast<int>(*v))) {
        Error(DiagCode::kInvalidValue, n->range,
              "invalid LOD " + Clip(n->text) + "; expected a non-negative integer");
        return false;
    }
    lod = static_cast<int>(*v);
    return true;
}

bool Parser::ParseProgram(std::vector<ProgramBlock>& programs) {
    const Token& t = Next();
    ProgramBlock block;
    block.kind = t.program_kind;
    block.range = t.range;
    block.body_begin = t.body_begin;
    block.text = std::string(t.text);
    block.pragmas = ScanPragmas(block.text, block.body_begin);
    programs.push_back(std::move(block));
    return true;
}

std::optional<Shader> Parse(const SourceFile& source,
                            DiagnosticList& diags,
                            const ParseOptions& options) {
    Parser parser(source, Lex(source, diags), diags, options);
    return parser.ParseFile();
}

std::optional<Shader> ParseAndCheck(const SourceFile& source,
                                    DiagnosticList& diags,
                                    const ParseOptions& options) {
    std::optional<Shader> shader = Parse(source, diags, options);
    if (shader) {
        Check(*shader, source.path(), diags);
    }
    return shader;
}

}  // namespace kiln::shaderlab
