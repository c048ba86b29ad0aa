// Diagnostics: the library never prints. Every stage appends to a DiagnosticList; the CLI formats
// it (text or JSON). Codes are stable: once published a code keeps its meaning
// (docs/diagnostics.md).
#ifndef KILN_DIAGNOSTIC_H_
#define KILN_DIAGNOSTIC_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/source.h"

namespace kiln {

enum class Severity : uint8_t { kNote, kWarning, kError, kInternal };

// Stable diagnostic codes, printed as K<number>. Ranges:
//   K0xxx  input/output          K1xxx  ShaderLab lexer
//   K2xxx  ShaderLab parser      K3xxx  ShaderLab semantic checks
//   K4xxx  pragmas and variants  K5xxx  HLSL compilation, SPIR-V, reflection, bindings
//   K6xxx  material instances (kiln::material::IssueCode, runtime/include/kiln/material)
//   K9xxx  internal compiler errors
enum class DiagCode : uint16_t {
    kCannotReadFile = 1,  // also: larger than kMaxSourceFileBytes
    kCannotWriteFile = 2,
    kBadCommandLine = 3,      // an unknown subcommand or option value the CLI reports itself
    kBadPack = 4,             // a pack that cannot be read (the reader's reason in the message)
    kUnknownPackName = 5,     // a shader or pass name the pack does not hold
    kMissingVariant = 6,      // the pack holds no variant with the requested keywords
    kBadScene = 7,            // a scene that cannot be loaded or rendered as asked
    kRenderFailed = 8,        // the renderer failed (device, pipeline, validation messages)
    kBadColorConfig = 9,      // an OpenColorIO config, display or view that does not exist
    kRenderWarning = 10,      // the runtime's warnings (scene content it skipped or changed)
    kWorkerUnavailable = 11,  // no compile worker process could be found or started

    kUnterminatedString = 1001,
    kUnterminatedComment = 1002,
    kUnterminatedProgramBlock = 1003,
    kUnexpectedCharacter = 1004,
    kStrayProgramEnd = 1005,

    kExpectedShader = 2001,
    kExpectedToken = 2002,
    kUnexpectedToken = 2003,
    kUnknownCommand = 2004,
    kInvalidValue = 2005,
    kUnclosedBlock = 2006,
    kNestingTooDeep = 2007,
    kTooManyErrors = 2008,
    kExpectedNumber = 2010,
    kUnknownPropertyType = 2011,
    kBadPropertyDefault = 2012,
    kBadAttribute = 2013,
    kLegacyCommandIgnored = 2014,
    kDuplicateCommand = 2015,
    kMisplacedCommand = 2016,
    kBadRenderTarget = 2017,

    kDuplicateProperty = 3001,
    kUndeclaredProperty = 3002,
    kPropertyRefType = 3003,
    kBadRange = 3004,
    kDefaultOutOfRange = 3005,
    kMultiplePrograms = 3006,
    kUnsupportedGlsl = 3007,
    kUnsupportedSurfaceShader = 3008,
    kProgramOutsidePass = 3009,
    kDuplicateTag = 3010,
    kUnknownTextureDefault = 3011,
    kDuplicatePassName = 3012,
    kUnknownLightMode = 3013,
    kMisspelledLightMode = 3014,

    kUnknownPragma = 4001,
    kUnsupportedStage = 4002,
    kMissingEntryPoint = 4003,
    kDuplicateEntryPoint = 4004,
    kBadShaderTarget = 4005,
    kBadKeyword = 4006,
    kDuplicateKeyword = 4007,
    kTooManyVariants = 4008,
    kPragmaMissingArgument = 4009,
    kRendererRestricted = 4010,
    kVariantKeyTooWide = 4011,
    kUnknownSkipKeyword = 4012,
    kNoVariantsLeft = 4013,
    kEntryPointNotFound = 4014,
    kUnknownKeyword = 4015,
    kMisspelledPragma = 4016,

    kHlslError = 5001,
    kHlslWarning = 5002,
    kSpirvInvalid = 5003,
    kStageInterfaceMismatch = 5004,
    kPropertyUnused = 5005,
    kGlobalNotAProperty = 5006,
    kBlockLayoutMismatch = 5007,
    kPropertyTypeMismatch = 5008,
    kCompilerCrashed = 5009,         // glslang or SPIRV-Tools crashed in its worker process
    kCompilerTimeLimit = 5010,       // ... did not finish within --program-timeout
    kCompilerMemoryLimit = 5011,     // ... used more than --program-memory
    kProgramNestingTooDeep = 5012,   // parentheses, braces or #if nested past the limit
    kMacroExpansionTooLarge = 5013,  // a macro whose expansion is over the budget
    kExpressionTooLong = 5014,       // one statement or expression with too many terms

    // K6xxx: material instances; the values are kiln::material::IssueCode's (runtime).
    kMaterialFirst = 6001,
    kMaterialLast = 6099,

    kInternalError = 9001,
};

// "K1234".
std::string FormatDiagCode(DiagCode code);
std::string_view SeverityName(Severity severity);

struct DiagnosticNote {
    std::string file;
    SourceRange range;
    std::string message;
};

struct Diagnostic {
    Severity severity = Severity::kError;
    DiagCode code = DiagCode::kInternalError;
    std::string file;
    SourceRange range;
    std::string message;  // lower-case, one sentence, no trailing period
    std::vector<DiagnosticNote> notes;
};

class DiagnosticList {
  public:
    // Errors past this limit are dropped and replaced by one kTooManyErrors error.
    static constexpr size_t kDefaultErrorLimit = 100;

    Diagnostic& Add(Severity severity,
                    DiagCode code,
                    std::string file,
                    SourceRange range,
                    std::string message);
    Diagnostic& Error(DiagCode code, std::string file, SourceRange range, std::string message) {
        return Add(Severity::kError, code, std::move(file), range, std::move(message));
    }
    Diagnostic& Warning(DiagCode code, std::string file, SourceRange range, std::string message) {
        return Add(Severity::kWarning, code, std::move(file), range, std::move(message));
    }

    const std::vector<Diagnostic>& all() const { return diags_; }
    size_t error_count() const { return errors_; }
    bool has_errors() const { return errors_ > 0; }
    bool has_internal_errors() const { return internal_ > 0; }
    // True once the error limit was hit: callers should stop early.
    bool saturated() const { return saturated_; }
    void set_error_limit(size_t limit) { limit_ = limit; }
    void Append(const DiagnosticList& other);

  private:
    std::vector<Diagnostic> diags_;
    size_t errors_ = 0;
    size_t internal_ = 0;
    size_t limit_ = kDefaultErrorLimit;
    bool saturated_ = false;
    Diagnostic overflow_sink_;
};

// Compiler-style text: "file:line:col: error: message [K1234]" followed by the source line and a
// caret/underline when `source` is the file the diagnostic points into, then its notes. `color`
// adds ANSI colours (a terminal's choice: the CLI's --color).
std::string FormatDiagnosticsText(const DiagnosticList& diags,
                                  const std::vector<const SourceFile*>& sources,
                                  bool color = false);
// A JSON array of diagnostics (format in docs/diagnostics.md).
std::string FormatDiagnosticsJson(const DiagnosticList& diags);

}  // namespace kiln

#endif  // KILN_DIAGNOSTIC_H_
