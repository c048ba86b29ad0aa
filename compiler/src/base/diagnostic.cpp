#include "kiln/diagnostic.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

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

Diagnostic& DiagnosticList::Add(Severity severity, DiagCode code, std::string file,
                                SourceRange range, std::string message) {
    const bool is_error = severity == Severity::kError || severity == Severity::kInternal;
    if (saturated_ || (is_error && severity != Severity::kInternal && errors_ >= limit_)) {
        if (!saturated_) {
            saturated_ = true;
            ++errors_;
            diags_.push_back(Diagnostic{Severity::kError, DiagCode::kTooManyErrors, file, range,
                                        "too many errors; stopping after " +
                                            std::to_string(limit_),
                                        {}});
        }
        overflow_sink_ = Diagnostic{};
        return overflow_sink_;
    }
    errors_ += is_error ? 1 : 0;
    internal_ += severity == Severity::kInternal ? 1 : 0;
    diags_.push_back(
        Diagnostic{severity, code, std::move(file), range, std::move(message), {}});
    return diags_.back();
}

void DiagnosticList::Append(const DiagnosticList& other) {
    for (const Diagnostic& d : other.diags_) {
        Diagnostic& added = Add(d.severity, d.code, d.file, d.range, d.message);
        added.notes = d.notes;
    }
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

// Appends "  12 | text\n     |   ^~~~\n" for a range that starts on a known line.
void AppendSnippet(std::string& out, const SourceFile* source, const SourceRange& range) {
    if (source == nullptr || range.begin.line == 0 || range.begin.line > source->line_count()) {
        return;
    }
    const std::string_view line = source->Line(range.begin.line);
    const std::string number = std::to_string(range.begin.line);
    std::string gutter(number.size(), ' ');
    out += " " + number + " | ";
    // Tabs are kept so the caret line can mirror them and stay aligned.
    for (char c : line) {
        out += (static_cast<unsigned char>(c) < 0x20 && c != '\t') ? ' ' : c;
    }
    out += "\n " + gutter + " | ";
    const size_t col = std::min<size_t>(range.begin.column - 1, line.size());
    for (size_t i = 0; i < col; ++i) {
        out += line[i] == '\t' ? '\t' : ' ';
    }
    size_t width = 1;
    if (range.end.line == range.begin.line && range.end.column > range.begin.column) {
        width = range.end.column - range.begin.column;
    } else if (range.end.line > range.begin.line) {
        width = line.size() > col ? line.size() - col : 1;
    }
    out += '^';
    out.append(width > 1 ? width - 1 : 0, '~');
    out += '\n';
}

void AppendHeader(std::string& out, const std::string& file, const SourceRange& range,
                  std::string_view severity, const std::string& message) {
    out += file.empty() ? "kiln" : file;
    if (range.begin.line > 0) {
        out += ":" + std::to_string(range.begin.line) + ":" + std::to_string(range.begin.column);
    }
    out += ": ";
    out += severity;
    out += ": " + message;
}

nlohmann::ordered_json RangeJson(const SourceRange& r) {
    return {{"begin", {{"line", r.begin.line}, {"column", r.begin.column}}},
            {"end", {{"line", r.end.line}, {"column", r.end.column}}}};
}

}  // namespace

std::string FormatDiagnosticsText(const DiagnosticList& diags,
                                  const std::vector<const SourceFile*>& sources) {
    std::string out;
    for (const Diagnostic& d : diags.all()) {
        AppendHeader(out, d.file, d.range, SeverityName(d.severity), d.message);
        out += " [" + FormatDiagCode(d.code) + "]\n";
        AppendSnippet(out, FindSource(sources, d.file), d.range);
        for (const DiagnosticNote& n : d.notes) {
            AppendHeader(out, n.file, n.range, "note", n.message);
            out += '\n';
            AppendSnippet(out, FindSource(sources, n.file), n.range);
        }
    }
    return out;
}

std::string FormatDiagnosticsJson(const DiagnosticList& diags) {
    nlohmann::ordered_json arr = nlohmann::ordered_json::array();
    for (const Diagnostic& d : diags.all()) {
        nlohmann::ordered_json notes = nlohmann::ordered_json::array();
        for (const DiagnosticNote& n : d.notes) {
            notes.push_back({{"file", n.file}, {"range", RangeJson(n.range)}, {"message", n.message}});
        }
        arr.push_back({{"severity", SeverityName(d.severity)},
                       {"code", FormatDiagCode(d.code)},
                       {"file", d.file},
                       {"range", RangeJson(d.range)},
                       {"message", d.message},
                       {"notes", notes}});
    }
    // Invalid UTF-8 in a message (echoed from bad input) is replaced, never thrown on.
    return arr.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace kiln
