#include "hlsl/splice.h"

#include <algorithm>

#include "hlsl/lean_text.h"
#include "hlsl/pp_skeleton.h"

// The scan of one file's lines for splicing (hlsl/splice.h): which are plain, their words and
// brackets, and each plain line's tokens.

namespace kiln::hlsl {
namespace {

using Line = SpliceFile::Line;
using Kind = SpliceFile::Kind;

// ASCII only: glslang's scanner reads any other byte as a character it does not know.
bool Alpha(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool Digit(char c) {
    return c >= '0' && c <= '9';
}
bool WordChar(char c) {
    return Alpha(c) || Digit(c);
}
bool HexDigit(char c) {
    return Digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

constexpr size_t kMaxWord = 200;  // well under glslang's token length limit

// The length of the number at s[i] where glslang reads it as the token it spells: a decimal int
// (no octal), a hex int, a float with an optional f; 0 for any other form (a suffix glslang reads
// otherwise, a number run into a word or a dot, an int glslang may find too big).
size_t Number(std::string_view s, size_t i) {
    const size_t n = s.size();
    size_t j = i;
    if (s[j] == '0' && j + 1 < n && (s[j + 1] == 'x' || s[j + 1] == 'X')) {
        j += 2;
        const size_t digits = j;
        while (j < n && HexDigit(s[j]))
            ++j;
        if (j == digits || j - digits > 8)
            return 0;
        if (j < n && (s[j] == 'u' || s[j] == 'U'))
            ++j;
    } else {
        while (j < n && Digit(s[j]))
            ++j;
        const size_t int_digits = j - i;
        bool is_float = false;
        if (j < n && s[j] == '.') {
            is_float = true;
            const size_t fraction = ++j;
            while (j < n && Digit(s[j]))
                ++j;
            if (int_digits == 0 && j == fraction)
                return 0;
        }
        if (int_digits == 0 && !is_float)
            return 0;
        if (j < n && (s[j] == 'e' || s[j] == 'E')) {
            size_t k = j + 1;
            if (k < n && (s[k] == '+' || s[k] == '-'))
                ++k;
            const size_t exponent = k;
            while (k < n && Digit(s[k]))
                ++k;
            if (k == exponent)
                return 0;
            j = k;
            is_float = true;
        }
        if (is_float) {
            if (j < n && (s[j] == 'f' || s[j] == 'F'))
                ++j;
        } else {
            if (int_digits > 9 || (int_digits > 1 && s[i] == '0'))
                return 0;
            if (j < n && (s[j] == 'u' || s[j] == 'U'))
                ++j;
        }
    }
    if (j < n && (WordChar(s[j]) || s[j] == '.'))
        return 0;
    return j - i;
}

// The length of glslang's operator token at s[i] (its longest), 0 for a character it does not
// read as one.
size_t Operator(std::string_view s, size_t i) {
    const char c = s[i];
    const char n = i + 1 < s.size() ? s[i + 1] : '\0';
    const char n2 = i + 2 < s.size() ? s[i + 2] : '\0';
    switch (c) {
        case '+':
        case '-':
        case '&':
        case '|':
        case '^':
            return n == c || n == '=' ? 2 : 1;
        case '*':
        case '/':
        case '%':
        case '=':
        case '!':
            return n == '=' ? 2 : 1;
        case '<':
        case '>':
            if (n == c)
                return n2 == '=' ? 3 : 2;
            return n == '=' ? 2 : 1;
        case ':':
            return n == ':' ? 2 : 1;
        case '~':
        case '?':
        case '{':
        case '}':
        case '(':
        case ')':
        case '[':
        case ']':
        case ';':
        case ',':
        case '.':
            return 1;
        default:
            return 0;
    }
}

struct Scan {
    SpliceFile& f;
    std::string_view text;
    bool in_comment = false;              // a block comment open at the line's start
    std::vector<SpliceFile::Tok> tokens;  // of the line being scanned
};

uint32_t WordId(SpliceFile& f, std::string_view word) {
    const auto [it, added] = f.word_ids.emplace(word, static_cast<uint32_t>(f.words.size()));
    if (added)
        f.words.push_back(word);
    return it->second;
}

// Skips a "..." or '...' literal starting at `i`, to its closing quote or the line's end.
size_t SkipQuoted(std::string_view s, size_t i, size_t end) {
    const char quote = s[i++];
    while (i < end && s[i] != quote)
        i += s[i] == '\\' ? 2 : 1;
    return std::min(i + 1, end);
}

// Scans the physical line [begin, end): its tokens into `scan.tokens`, and for a line of code its
// words and brackets into the file's events; false where it holds anything but plain tokens.
bool ScanCode(Scan& scan, Line& line, size_t begin, size_t end) {
    SpliceFile& f = scan.f;
    const std::string_view s = scan.text.substr(0, end);
    bool plain = !scan.in_comment;
    size_t i = begin;
    while (i < end) {
        const char c = s[i];
        const char next = i + 1 < end ? s[i + 1] : '\0';
        if (scan.in_comment) {
            const size_t close = s.find("*/", i);
            scan.in_comment = close == std::string_view::npos;
            i = scan.in_comment ? end : close + 2;
            continue;
        }
        if (c == ' ' || c == '\t' || (c == '\r' && i + 1 == end)) {
            ++i;
            continue;
        }
        if (c == '/' && (next == '/' || next == '*')) {
            plain = false;
            if (next == '/')
                break;
            scan.in_comment = true;
            i += 2;
            continue;
        }
        if (c == '"' || c == '\'') {
            plain = false;
            i = SkipQuoted(s, i, end);
            line.last_word = -1;
            continue;
        }
        size_t len = 0;
        int32_t word = -1;
        if (Alpha(c)) {
            while (i + len < end && WordChar(s[i + len]))
                ++len;
            if (line.kind != Kind::kDirective) {  // a directive's words are not code's
                word = static_cast<int32_t>(WordId(f, s.substr(i, len)));
                f.events.push_back(word);
                line.last_word = word;
            }
            plain = plain && len <= kMaxWord;
        } else {
            line.last_word = -1;
            if (Digit(c) || (c == '.' && Digit(next))) {
                len = Number(s, i);
                if (len == 0) {
                    plain = false;
                    while (i + len < end && (WordChar(s[i + len]) || s[i + len] == '.'))
                        ++len;
                }
            } else {
                len = Operator(s, i);
                if (len == 0) {
                    plain = false;
                    len = 1;
                } else if ((c == '(' || c == ')') && line.kind != Kind::kDirective) {
                    f.events.push_back(c == '(' ? SpliceFile::kOpen : SpliceFile::kClose);
                }
            }
        }
        scan.tokens.push_back({static_cast<uint32_t>(i), static_cast<uint32_t>(i + len), word});
        i += len;
    }
    return plain;
}

}  // namespace

std::shared_ptr<const SpliceFile> ScanSpliceFile(std::shared_ptr<const LeanText> text,
                                                 const PpSkeleton& skeleton) {
    auto out = std::make_shared<SpliceFile>();
    SpliceFile& f = *out;
    f.text = std::move(text);
    const std::string_view s = f.text->text;
    const std::vector<uint32_t>& starts = f.text->line_starts;
    f.usable = skeleton.safe && s.find(kSpliceMarker) == std::string_view::npos;
    if (!f.usable)
        return out;
    f.lines.resize(starts.size());
    for (const PpDirective& d : skeleton.directives) {
        for (uint32_t l = d.first_line; l <= d.last_line && l < f.lines.size(); ++l)
            f.lines[l].kind = Kind::kDirective;
    }
    Scan scan{f, s, false, {}};
    for (size_t l = 0; l < starts.size(); ++l) {
        Line& line = f.lines[l];
        const size_t begin = starts[l];
        const size_t end = l + 1 < starts.size() ? starts[l + 1] - 1 : s.size();
        scan.tokens.clear();
        line.events_begin = static_cast<uint32_t>(f.events.size());
        const bool plain = ScanCode(scan, line, begin, end);
        if (line.kind != Kind::kDirective) {
            size_t e = end;
            if (e > begin && s[e - 1] == '\r')
                --e;
            if (e > begin && s[e - 1] == '\\' && !scan.in_comment) {
                f.usable = false;  // a line of code continued: tokens may span the lines
                return out;
            }
            if (plain && scan.tokens.size() >= 3) {
                line.kind = Kind::kPlain;
                line.toks_begin = static_cast<uint32_t>(f.toks.size());
                f.toks.insert(f.toks.end(), scan.tokens.begin(), scan.tokens.end());
                line.toks_end = static_cast<uint32_t>(f.toks.size());
            } else if (!scan.tokens.empty()) {
                line.kind = Kind::kCode;
            }
        }
        line.events_end = static_cast<uint32_t>(f.events.size());
    }
    return out;
}

}  // namespace kiln::hlsl
