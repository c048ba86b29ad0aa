// Diagnostics: the library never prints. Every stage appends to a DiagnosticList; the CLI formats
// it (text or JSON). Codes are stable: once published a code keeps its meaning
// (docs/diagnostics.md).
#ifndef KILN_DIAGNOSTIC_H_
#define KILN_DIAGNOSTIC_H_

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
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

// Every code of kiln/diag_code_list.h, in its order.
const std::vector<DiagCode>& AllDiagCodes();

// A named group of warnings for the -W options (-Wno-lint): codes in the inclusive ranges.
struct WarningGroup {
    std::string_view name;
    std::vector<std::pair<uint16_t, uint16_t>> ranges;
    std::string_view summary;
};
const std::vector<WarningGroup>& WarningGroups();

// Compiler-style warning options in clang's and GCC's spelling, where X is a code (K7001) or a
// group (lint, all): -Wno-X silences X's warnings, -WX shows them again, -Werror=X makes them
// errors, -Wno-error=X keeps them warnings, -Werror makes every other warning an error and
// -Wno-error undoes that. Options apply in order: of two naming one code, the later wins.
// Errors are never silenced or demoted (docs/diagnostics.md, "Warning options").
class WarningPolicy {
  public:
    enum class Action : uint8_t { kWarn, kIgnore, kError };
    // One option ("-Wno-K7001"); a K0003 error naming what was expected and the closest valid
    // code or group when it is not one of the spellings above.
    Status Add(std::string_view option);
    Action For(DiagCode code) const;
    bool empty() const { return codes_.empty() && !werror_; }

  private:
    struct Entry {
        int8_t shown = -1;  // -1: not named; 0: -Wno-X; 1: -WX or -Werror=X
        int8_t error = -1;  // -1: not named (-Werror decides); 0: -Wno-error=X; 1: -Werror=X
    };
    std::map<uint16_t, Entry> codes_;
    bool werror_ = false;
};

class DiagnosticList {
  public:
    DiagnosticList() = default;
    // Every warning added is passed through `policy` (silenced, kept or made an error).
    explicit DiagnosticList(WarningPolicy policy) : policy_(std::move(policy)) {}

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
    WarningPolicy policy_;
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
