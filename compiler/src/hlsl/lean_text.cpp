#include "hlsl/lean_text.h"

#include "hlsl/pp_skeleton.h"

namespace kiln::hlsl {
namespace {

bool Space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// What the text's physical lines hold, as glslang's scanner reads them.
struct Lines {
    std::vector<char> directive;          // a line of a directive
    std::vector<char> starts_in_comment;  // line_count + 1 entries: the last is the end's
    std::vector<char> continued;          // ends with a backslash before its line break
    std::vector<size_t> last_code_at;     // offset of the last character of code, or npos
};

Lines ScanLines(std::string_view text, const PpSkeleton& skeleton) {
    const auto count = static_cast<uint32_t>(skeleton.line_starts.size());
    Lines f;
    f.directive.assign(count, 0);
    f.starts_in_comment.assign(count + 1, 0);
    f.continued.assign(count, 0);
    f.last_code_at.assign(count, std::string_view::npos);
    for (const PpDirective& d : skeleton.directives) {
        for (uint32_t l = d.first_line; l <= d.last_line && l < count; ++l)
            f.directive[l] = 1;
    }
    enum class St { kCode, kLineComment, kBlockComment, kString, kChar };
    St st = St::kCode;
    uint32_t line = 0;
    const size_t n = text.size();
    for (size_t i = 0; i < n && line < count; ++i) {
        const char c = text[i];
        const char next = i + 1 < n ? text[i + 1] : '\0';
        if (c == '\n') {
            const bool cont = (i > 0 && text[i - 1] == '\\') ||
                              (i > 1 && text[i - 1] == '\r' && text[i - 2] == '\\');
            f.continued[line] = cont;
            if (!cont && st != St::kBlockComment)
                st = St::kCode;
            ++line;
            f.starts_in_comment[line] = st == St::kBlockComment || st == St::kLineComment;
            continue;
        }
        switch (st) {
            case St::kCode:
                if (c == '/' && next == '/') {
                    st = St::kLineComment;
                    ++i;
                } else if (c == '/' && next == '*') {
                    st = St::kBlockComment;
                    ++i;
                } else if (!Space(c)) {
                    if (c == '"')
                        st = St::kString;
                    else if (c == '\'')
                        st = St::kChar;
                    f.last_code_at[line] = i;
                }
                break;
            case St::kLineComment:
                break;
            case St::kBlockComment:
                if (c == '*' && next == '/') {
                    st = St::kCode;
                    ++i;
                }
                break;
            case St::kString:
            case St::kChar:
                if (c == '\\' && next != '\n')
                    ++i;
                else if (c == (st == St::kString ? '"' : '\''))
                    st = St::kCode;
                f.last_code_at[line] = i;
                break;
        }
    }
    return f;
}

}  // namespace

LeanText MakeLeanText(std::string_view text, const PpSkeleton& skeleton) {
    LeanText out;
    const auto count = static_cast<uint32_t>(skeleton.line_starts.size());
    if (!skeleton.safe) {
        out.text = std::string(text);
        out.line_starts = skeleton.line_starts;
        return out;
    }
    const Lines f = ScanLines(text, skeleton);
    out.text.reserve(text.size());
    out.line_starts.reserve(count);
    for (uint32_t l = 0; l < count; ++l) {
        const size_t begin = skeleton.line_starts[l];
        const size_t end = l + 1 < count ? skeleton.line_starts[l + 1] - 1 : text.size();
        out.line_starts.push_back(static_cast<uint32_t>(out.text.size()));
        const bool code = f.last_code_at[l] != std::string_view::npos;
        // Whether the next line starts as it would have: nothing of this one reaches past it.
        const bool closed = !f.continued[l] &&
                            f.starts_in_comment[l + 1] == f.starts_in_comment[l] &&
                            !(code && f.starts_in_comment[l + 1]);
        if (f.directive[l] || !closed)
            out.text.append(text, begin, end - begin);
        else if (code)
            out.text.append(text, begin, f.last_code_at[l] + 1 - begin);
        if (end < text.size())
            out.text += '\n';
        else if (!code && !text.empty() && text.back() != '\n' && (f.directive[l] == 0 && closed))
            out.text += ' ';  // the file's last character stays a line break or not (BlankLines)
    }
    return out;
}

}  // namespace kiln::hlsl
