// Recursive-descent ShaderLab parser (private). Split over parser.cpp (structure: Shader,
// Category, SubShader, Pass), parser_properties.cpp and parser_state.cpp (render state).
//
// Recovery: every block body is a loop over commands. A command that fails reports one error and
// the loop skips the rest of it (to the end of its line, or past the block it opens), so one run
// reports many independent errors. Nesting is bounded by ParseOptions::max_nesting; skipping is
// iterative, so no input can exhaust the stack.
#ifndef KILN_SHADERLAB_PARSER_H_
#define KILN_SHADERLAB_PARSER_H_

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/base/text.h"
#include "kiln/diagnostic.h"
#include "kiln/pack/render_state.h"
#include "kiln/shaderlab/ast.h"
#include "kiln/shaderlab/parse.h"
#include "lexer.h"

namespace kiln::shaderlab {

using base::EqualsIgnoreCase;
// A finite number spelled exactly as `text` ("1", "-0.5", "1e3"); nullopt otherwise.
std::optional<double> ParseDouble(std::string_view text);

class Parser {
  public:
    Parser(const SourceFile& source,
           std::vector<Token> tokens,
           DiagnosticList& diags,
           const ParseOptions& options);

    std::optional<Shader> ParseFile();

  private:
    // Where a command appears; decides which commands are allowed.
    enum class Level { kShader, kCategory, kSubShader, kPass, kGrabPass };

    // Tokens.
    const Token& Peek(size_t ahead = 0) const;
    const Token& Next();
    bool At(TokenKind kind) const { return Peek().kind == kind; }
    bool AtWord(std::string_view word) const;
    bool Accept(TokenKind kind);
    // Consumes a token of `kind` or reports "expected <what> <context>, found ..." and returns
    // null.
    const Token* Expect(TokenKind kind, std::string_view what, std::string_view context);
    static std::string Describe(const Token& token);
    SourceRange RangeFrom(const Token& first) const;  // first..last consumed token

    // Diagnostics.
    Diagnostic& Error(DiagCode code, SourceRange range, std::string message);
    Diagnostic& Warning(DiagCode code, SourceRange range, std::string message);
    void ErrorUnexpected(const Token& token, std::string_view context);
    // "duplicate <what>; the last one wins", with a note at the previous one.
    void WarnDuplicate(DiagCode code,
                       SourceRange range,
                       const std::string& what,
                       SourceRange previous);

    // Blocks and recovery. ParseBlock expects '{' next; `item` parses one command starting at the
    // current token and returns false after reporting an error (the command is then skipped).
    bool ParseBlock(std::string_view what, const std::function<bool()>& item);
    void SkipCommand(size_t start, uint32_t line);
    void SkipBalanced();

    // Structure (parser.cpp).
    Shader ParseShader();
    bool ParseShaderItem(Shader& shader);
    bool ParseCategory(std::unique_ptr<Category>& out);
    bool ParseSubShader(SubShader& out);
    bool ParsePass(Pass& out);
    bool ParseFallback(Shader& shader);
    bool ParseDependency(Shader& shader);
    bool ParseUsePass(SubShader& sub);
    bool ParseGrabPass(SubShader& sub);
    bool ParseTags(std::vector<Tag>& tags);
    bool ParseLod(std::optional<int>& lod);
    bool ParseProgram(std::vector<ProgramBlock>& programs);
    bool ParseStringArg(std::string& out, std::string_view command);
    // Shared commands for Category/SubShader/Pass; false when the current token is none of them.
    bool TryCommonCommand(std::vector<Tag>& tags,
                          RenderState& state,
                          FixedFunction& fixed,
                          std::vector<ProgramBlock>& programs,
                          bool in_pass,
                          bool& ok);
    bool ReportMisplacedOrUnknown(Level level);

    // Properties (parser_properties.cpp).
    bool ParseProperties(Shader& shader);
    bool ParseProperty(std::vector<Property>& out);
    bool ParseAttribute(std::vector<Attribute>& out);
    bool ParsePropertyType(Property& prop);
    bool ParsePropertyDefault(Property& prop);
    std::optional<double> ParseSignedNumber(std::string_view context);

    // Legacy fixed-function commands (parser_fixed_function.cpp). TryFixedFunctionCommand: false
    // when the current token is none of them; otherwise parses it and sets `ok`.
    bool TryFixedFunctionCommand(FixedFunction& fixed, bool in_pass, bool& ok);
    bool ParseOnOff(std::optional<bool>& slot, std::string_view command);
    std::optional<FixedValue> ParseFixedValue(std::string_view context, bool colour);
    bool ParseMaterialBlock(FixedFunction& fixed);
    bool ParseAlphaTest(FixedFunction& fixed);
    bool ParseSetTexture(FixedFunction& fixed);
    bool ParseCombine(TextureStage& stage, uint32_t line);
    std::optional<Combiner> ParseCombiner(uint32_t line);
    std::optional<CombineSource> ParseCombineSource(uint32_t line);
    bool ParseBindChannels(FixedFunction& fixed);

    // Render state (parser_state.cpp). TryStateCommand: false when the current token is not a
    // render-state command; otherwise parses it and sets `ok`.
    bool TryStateCommand(RenderState& state, bool& ok);
    bool ParseSimpleState(std::optional<SimpleState>& slot,
                          std::string_view command,
                          pack::StateValues set);
    bool ParseOffset(RenderState& state);
    bool ParseBlend(RenderState& state);
    bool ParseBlendOp(RenderState& state);
    bool ParseColorMask(RenderState& state);
    bool ParseStencil(RenderState& state);
    std::optional<int> ParseRenderTarget(std::string_view command);
    std::optional<StateValue> ParseEnumValue(std::string_view command, pack::StateValues set);
    std::optional<StateValue> ParseNumberValue(std::string_view command,
                                               double min,
                                               double max,
                                               bool integer);
    std::optional<StateValue> ParsePropertyRef();

    const SourceFile& source_;
    std::vector<Token> tokens_;
    DiagnosticList& diags_;
    ParseOptions options_;
    size_t pos_ = 0;
    size_t depth_ = 0;
    bool reported_eof_ = false;
};

}  // namespace kiln::shaderlab

#endif  // KILN_SHADERLAB_PARSER_H_
