// The one way material code reports a problem: a diagnostic at one byte of the .material file,
// with its "did you mean" or list of allowed values as a note at the same place.
#ifndef KILN_RUNTIME_MATERIAL_ISSUE_H_
#define KILN_RUNTIME_MATERIAL_ISSUE_H_

#include <string>
#include <utility>

#include "kiln/diagnostic.h"
#include "kiln/material/material.h"

namespace kiln::material {

inline void AddIssue(DiagnosticList& diags,
                     const std::string& file,
                     Severity severity,
                     DiagCode code,
                     TextPos pos,
                     std::string message,
                     std::string note = "") {
    SourceRange range{pos, pos};
    range.end.offset += 1;
    range.end.column += 1;
    Diagnostic& d = diags.Add(severity, code, file, range, std::move(message));
    if (!note.empty()) {
        d.notes.push_back({file, range, std::move(note)});
    }
}

}  // namespace kiln::material

#endif  // KILN_RUNTIME_MATERIAL_ISSUE_H_
