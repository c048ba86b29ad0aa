#include "program_scan.h"

#include <string>

namespace kiln::shaderlab {

std::string BlankComments(std::string_view body) {
    std::string out(body);
    size_t i = 0;
    while (i < out.size()) {
        if (out[i] == '/' && i + 1 < out.size() && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n') {
                out[i++] = ' ';
            }
        } else if (out[i] == '/' && i + 1 < out.size() && out[i + 1] == '*') {
            out[i++] = ' ';
            out[i++] = ' ';
            while (i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/')) {
                if (out[i] != '\n') {
                    out[i] = ' ';
                }
                ++i;
            }
            for (size_t k = 0; k < 2 && i < out.size(); ++k) {
                out[i++] = ' ';
            }
        } else if (out[i] == '"') {
            ++i;
            while (i < out.size() && out[i] != '"' && out[i] != '\n') {
                out[i++] = ' ';
            }
            ++i;
        } else {
            ++i;
        }
    }
    return out;
}

namespace {

bool IsBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

}  // namespace

std::vector<Pragma> ScanPragmas(std::string_view body, SourceLoc body_begin) {
    const std::string text = BlankComments(body);
    std::vector<Pragma> pragmas;
    uint32_t line = body_begin.line;
    size_t line_start = 0;
    while (line_start <= text.size()) {
        size_t line_end = text.find('\n', line_start);
        if (line_end == std::string::npos) {
            line_end = text.size();
        }
        // Column of body offset `at`, which lies on the current line.
        auto loc = [&](size_t at) {
            const uint32_t base = line == body_begin.line ? body_begin.column : 1;
            return SourceLoc{body_begin.offset + static_cast<uint32_t>(at), line,
                             base + static_cast<uint32_t>(at - line_start)};
        };
        size_t i = line_start;
        while (i < line_end && IsBlank(text[i])) {
            ++i;
        }
        if (i < line_end && text[i] == '#') {
            const size_t hash = i++;
            while (i < line_end && IsBlank(text[i])) {
                ++i;
            }
            if (text.compare(i, 6, "pragma") == 0 && (i + 6 == line_end || IsBlank(text[i + 6]))) {
                i += 6;
                Pragma pragma;
                std::vector<PragmaArg> words;
                while (true) {
                    while (i < line_end && IsBlank(text[i])) {
                        ++i;
                    }
                    if (i >= line_end) {
                        break;
                    }
                    const size_t start = i;
                    while (i < line_end && !IsBlank(text[i])) {
                        ++i;
                    }
                    words.push_back({text.substr(start, i - start), {loc(start), loc(i)}});
                }
                if (!words.empty()) {
                    pragma.name = words.front().text;
                    pragma.args.assign(words.begin() + 1, words.end());
                    pragma.range = {loc(hash), words.back().range.end};
                    pragmas.push_back(std::move(pragma));
                }
            }
        }
        if (line_end == text.size()) {
            break;
        }
        line_start = line_end + 1;
        ++line;
    }
    return pragmas;
}

}  // namespace kiln::shaderlab
