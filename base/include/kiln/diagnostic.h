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

#include "kiln/diag_code.h"
#include "kiln/result.h"
#include "kiln/source.h"

namespace kiln {

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
    // Orders the diagnostics by file, then by where they start (stable: ties keep their order).
    void SortByPosition();

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
// Reads FormatDiagnosticsJson's text back (a Kiln tool reporting another's diagnostics as its
// own, as kiln compile --scene does with kiln-render's); an error when it is not such an array.
Result<DiagnosticList> ParseDiagnosticsJson(std::string_view text);

}  // namespace kiln

#endif  // KILN_DIAGNOSTIC_H_
