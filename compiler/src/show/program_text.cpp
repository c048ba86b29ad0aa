// kiln show --hlsl and kiln compile -E: the text glslang compiled, without the blank lines that
// preprocessing and reduction leave (a 7,800-line fragment program has about 7,200).
#include "kiln/show.h"

#include <regex>
#include <sstream>

namespace kiln {

std::string CompactProgramText(const std::string& text) {
    static const std::regex kLine(R"(^\s*#\s*line\s+(\d+)(?:\s+\"([^\"]*)\")?\s*$)");
    std::string out;
    std::string cur_file, out_file;
    long cur_line = 1, out_line = -1;
    std::istringstream in(text);
    std::string line;
    std::smatch m;
    while (std::getline(in, line)) {
        if (std::regex_match(line, m, kLine)) {
            cur_line = std::stol(m[1].str());
            if (m[2].matched)
                cur_file = m[2].str();
            continue;
        }
        if (line.find_first_not_of(" \t\r") == std::string::npos) {
            ++cur_line;
            continue;
        }
        if (cur_file != out_file || cur_line != out_line) {
            const long gap = cur_line - out_line;
            if (cur_file == out_file && gap > 0 && gap <= 2) {
                out.append(size_t(gap), '\n');  // a short gap stays as it was
            } else {
                out += "#line " + std::to_string(cur_line) + " \"" + cur_file + "\"\n";
            }
            out_file = cur_file;
            out_line = cur_line;
        }
        out += line;
        out += '\n';
        ++out_line;
        ++cur_line;
    }
    return out;
}

std::string ProgramView(const ProgramText& p) {
    std::string header = "// " + p.shader + ", pass " + p.pass + ", keywords " +
                         (p.keywords.empty() ? "(none)" : pack::JoinKeywords(p.keywords));
    if (p.variants > 1)
        header += " (and " + std::to_string(p.variants - 1) + " more variants)";
    header += std::string(", ") + pack::StageName(p.stage) + " stage, entry " + p.entry + "\n";
    return header + CompactProgramText(p.text);
}

}  // namespace kiln
