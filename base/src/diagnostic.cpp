#include "kiln/diagnostic.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "kiln/base/text.h"

namespace kiln {

std::string FormatDiagCode(DiagCode code) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "K%04u", static_cast<unsigned>(code));
    return buf;
}

std::string_view SeverityName(Severity severity) {
    switch (severity) {
        case Severity::kNote:
            return "note";
        case Severity::kWarning:
            return "warning";
        case Severity::kError:
            return "error";
        case Severity::kInternal:
            return "internal compiler error";
    }
    return "error";
}

Diagnostic& DiagnosticList::Add(Severity severity,
                                DiagCode code,
                                std::string file,
                                SourceRange range,
                                std::string message) {
    if (severity == Severity::kWarning && !policy_.empty()) {
        switch (policy_.For(code)) {
            case WarningPolicy::Action::kIgnore:
                overflow_sink_ = Diagnostic{};
                return overflow_sink_;
            case WarningPolicy::Action::kError:
                severity = Severity::kError;
                break;
            case WarningPolicy::Action::kWarn:
                break;
        }
    }
    const bool is_error = severity == Severity::kError || severity == Severity::kInternal;
    if (saturated_ || (is_error && severity != Severity::kInternal && errors_ >= limit_)) {
        if (!saturated_) {
            saturated_ = true;
            ++errors_;
            diags_.push_back(Diagnostic{Severity::kError,
                                        DiagCode::kTooManyErrors,
                                        file,
                                        range,
                                        "too many errors; stopping after " + std::to_string(limit_),
                                        {}});
        }
        overflow_sink_ = Diagnostic{};
        return overflow_sink_;
    }
    errors_ += is_error ? 1 : 0;
    internal_ += severity == Severity::kInternal ? 1 : 0;
    diags_.push_back(Diagnostic{severity, code, std::move(file), range, std::move(message), {}});
    return diags_.back();
}

void DiagnosticList::Append(const DiagnosticList& other) {
    for (const Diagnostic& d : other.diags_) {
        Diagnostic& added = Add(d.severity, d.code, d.file, d.range, d.message);
        added.notes = d.notes;
    }
}

void DiagnosticList::SortByPosition() {
    std::stable_sort(diags_.begin(), diags_.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return a.file != b.file ? a.file < b.file : a.range.begin.offset < b.range.begin.offset;
    });
}

namespace {

const SourceFile* FindSource(const std::vector<const SourceFile*>& sources,
                             const std::string& file) {
    for (const SourceFile* s : sources) {
        if (s != nullptr && s->path() == file) {
            return s;
        }
    }
    return nullptr;
}

// Appends " 12 | text\n    |   ^~~~\n" for a range that starts on a known line. Control bytes and
// invalid UTF-8 are shown as '?', and long lines are cut to a window around the caret, so that
// binary input never reaches the terminal and the caret stays aligned.
void AppendSnippet(std::string& out,
                   const SourceFile* source,
                   const SourceRange& range,
                   bool color) {
    if (source == nullptr || range.begin.line == 0 || range.begin.line > source->line_count()) {
        return;
    }
    constexpr size_t kWindow = 120;
    std::string_view line = source->Line(range.begin.line);
    size_t col = std::min<size_t>(range.begin.column - 1, line.size());
    size_t width = 1;
    if (range.end.line == range.begin.line && range.end.column > range.begin.column) {
        width = range.end.column - range.begin.column;
    } else if (range.end.line > range.begin.line) {
        width = line.size() > col ? line.size() - col : 1;
    }
    std::string text;
    std::string caret;
    size_t first = 0;
    if (line.size() > kWindow) {
        first = col > kWindow / 2 ? col - kWindow / 2 : 0;
        line = line.substr(first, kWindow);
        text = first > 0 ? "..." : "";
        caret = first > 0 ? "   " : "";
        col -= first;
    }
    width = std::min(width, line.size() > col ? line.size() - col : 1);
    for (size_t i = 0; i < line.size();) {
        const size_t n = base::Utf8SequenceLength(line, i);
        const auto c = static_cast<unsigned char>(line[i]);
        const bool printable = n > 1 || c == '\t' || (c >= 0x20 && c < 0x7f);
        const size_t step = n > 1 ? n : 1;
        text += printable ? std::string(line.substr(i, step)) : std::string("?");
        if (i < col) {
            caret += c == '\t' ? '\t' : ' ';
        } else if (i < col + width) {
            caret += i == col ? '^' : '~';
        }
        i += step;
    }
    if (caret.find('^') == std::string::npos) {
        caret += '^';
    }
    const std::string number = std::to_string(range.begin.line);
    out += " " + number + " | " + text + "\n";
    out += " " + std::string(number.size(), ' ') + " | " + (color ? "\033[1;32m" : "") + caret +
           (color ? "\033[0m" : "") + "\n";
}

// clang's colours: bold position and message, red errors, magenta warnings, cyan notes.
const char* SeverityColor(std::string_view severity) {
    if (severity == "warning")
        return "\033[1;35m";
    if (severity == "note")
        return "\033[1;36m";
    return "\033[1;31m";
}

void AppendHeader(std::string& out,
                  const std::string& file,
                  const SourceRange& range,
                  std::string_view severity,
                  const std::string& message,
                  bool color) {
    if (color)
        out += "\033[1m";
    out += file.empty() ? "kiln" : base::EscapeForTerminal(file);
    if (range.begin.line > 0) {
        out += ":" + std::to_string(range.begin.line) + ":" + std::to_string(range.begin.column);
    }
    out += ": ";
    if (color)
        out += SeverityColor(severity);
    out += severity;
    out += color ? ":\033[0m\033[1m " : ": ";
    out += base::EscapeForTerminal(message);
    if (color)
        out += "\033[0m";
}

nlohmann::ordered_json RangeJson(const SourceRange& r) {
    return {{"begin", {{"line", r.begin.line}, {"column", r.begin.column}}},
            {"end", {{"line", r.end.line}, {"column", r.end.column}}}};
}

}  // namespace

std::string FormatDiagnosticsText(const DiagnosticList& diags,
                                  const std::vector<const SourceFile*>& sources,
                                  bool color) {
    std::string out;
    for (const Diagnostic& d : diags.all()) {
        AppendHeader(out, d.file, d.range, SeverityName(d.severity), d.message, color);
        out += " [" + FormatDiagCode(d.code) + "]\n";
        AppendSnippet(out, FindSource(sources, d.file), d.range, color);
        for (const DiagnosticNote& n : d.notes) {
            AppendHeader(out, n.file, n.range, "note", n.message, color);
            out += '\n';
            AppendSnippet(out, FindSource(sources, n.file), n.range, color);
        }
    }
    return out;
}

std::string FormatDiagnosticsJson(const DiagnosticList& diags) {
    nlohmann::ordered_json arr = nlohmann::ordered_json::array();
    for (const Diagnostic& d : diags.all()) {
        nlohmann::ordered_json notes = nlohmann::ordered_json::array();
        for (const DiagnosticNote& n : d.notes) {
            notes.push_back({{"file", base::EscapeForTerminal(n.file)},
                             {"range", RangeJson(n.range)},
                             {"message", base::EscapeForTerminal(n.message)}});
        }
        // Files and messages escaped as the text form escapes them (invalid UTF-8 and control
        // bytes from inputs or packs as \xNN), so both forms show the same string.
        arr.push_back({{"severity", SeverityName(d.severity)},
                       {"code", FormatDiagCode(d.code)},
                       {"file", base::EscapeForTerminal(d.file)},
                       {"range", RangeJson(d.range)},
                       {"message", base::EscapeForTerminal(d.message)},
                       {"notes", notes}});
    }
    // Nothing left to replace, and never thrown on.
    return arr.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

namespace {

bool ReadRange(const nlohmann::json& j, SourceRange& r) {
    auto pos = [](const nlohmann::json& p, SourceLoc& out) {
        if (!p.is_object() || !p.contains("line") || !p["line"].is_number_unsigned() ||
            !p.contains("column") || !p["column"].is_number_unsigned()) {
            return false;
        }
        out.line = p["line"].get<uint32_t>();
        out.column = p["column"].get<uint32_t>();
        return true;
    };
    return j.is_object() && j.contains("begin") && j.contains("end") && pos(j["begin"], r.begin) &&
           pos(j["end"], r.end);
}

bool ReadStringField(const nlohmann::json& j, const char* key, std::string& out) {
    if (!j.contains(key) || !j[key].is_string()) {
        return false;
    }
    out = j[key].get<std::string>();
    return true;
}

}  // namespace

Result<DiagnosticList> ParseDiagnosticsJson(std::string_view text) {
    const nlohmann::json doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    const Error bad{DiagCode::kInternalError, "not a JSON array of Kiln diagnostics"};
    if (doc.is_discarded() || !doc.is_array()) {
        return bad;
    }
    DiagnosticList out;
    out.set_error_limit(SIZE_MAX);
    for (const nlohmann::json& j : doc) {
        std::string severity, code, file, message;
        SourceRange range;
        if (!j.is_object() || !ReadStringField(j, "severity", severity) ||
            !ReadStringField(j, "code", code) || !ReadStringField(j, "file", file) ||
            !ReadStringField(j, "message", message) || !j.contains("range") ||
            !ReadRange(j["range"], range) || code.size() != 5 || code[0] != 'K' ||
            code.find_first_not_of("0123456789", 1) != std::string::npos) {
            return bad;
        }
        Severity sev = Severity::kError;
        for (Severity s :
             {Severity::kNote, Severity::kWarning, Severity::kError, Severity::kInternal}) {
            if (SeverityName(s) == severity) {
                sev = s;
            }
        }
        Diagnostic& d =
            out.Add(sev, static_cast<DiagCode>(std::stoi(code.substr(1))), file, range, message);
        if (j.contains("notes") && j["notes"].is_array()) {
            for (const nlohmann::json& n : j["notes"]) {
                DiagnosticNote note;
                if (n.is_object() && ReadStringField(n, "file", note.file) &&
                    ReadStringField(n, "message", note.message) && n.contains("range") &&
                    ReadRange(n["range"], note.range)) {
                    d.notes.push_back(std::move(note));
                }
            }
        }
    }
    return out;
}

}  // namespace kiln
