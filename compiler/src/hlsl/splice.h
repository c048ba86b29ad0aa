// Lines of plain code given to glslang's preprocessor short, and given back whole after it. Most
// lines of code glslang reads in Unity's includes name no macro: their output is their own tokens
// (hlsl/lean_text.h keeps each line's first-token column), with glslang's spacing between two
// tokens of a line: one space, none where either is one of `;()[]` or the second is `,`
// (glslang's DoPreprocessing). Such a line of three or more tokens is served as its first token,
// a marker word naming the line, and its last token; after preprocessing, the marker and the
// spaces glslang put around it are replaced by the tokens between, as glslang would have printed
// them. The first and last tokens stay so that glslang places and spaces the line's ends itself
// (where a line follows a #line of its output, its first token's spacing depends on the token
// before it).
//
// A line is served so only where no word of it can be a macro (no word any #define of the
// program names, nor one glslang may define), no macro call may still be collecting arguments
// over it (a line after one that names a macro and leaves a bracket open, or ends with a macro's
// name), and it holds nothing glslang reads otherwise than as plain tokens (comments, strings,
// backslashes, '#', other characters than code's, numbers of other forms than plain ones).
#ifndef KILN_HLSL_SPLICE_H_
#define KILN_HLSL_SPLICE_H_

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace kiln::hlsl {

struct LeanText;
struct PpSkeleton;

// What one served file's lines hold, scanned once per file.
struct SpliceFile {
    enum class Kind : uint8_t { kEmpty, kDirective, kCode, kPlain };
    struct Line {
        Kind kind = Kind::kEmpty;
        int32_t last_word = -1;  // the id of the line's last token, when it is a word
        uint32_t events_begin = 0, events_end = 0;  // in `events`
        // kPlain: the first token's end and the last token's start (offsets in the text), the
        // tokens between as glslang prints them (in `middles`, with the spaces at both ends), and
        // whether glslang puts a space after the first token and before the last.
        uint32_t first_end = 0, last_begin = 0;
        uint32_t middle_begin = 0, middle_end = 0;
        bool space_after_first = false, space_before_last = false;
    };
    static constexpr int32_t kOpen = -1, kClose = -2;

    std::shared_ptr<const LeanText> text;  // what the offsets are of
    // False where a line of code is continued by a backslash, or the text spells the marker's
    // prefix: such a file is served without splicing.
    bool usable = false;
    std::vector<Line> lines;  // one per physical line
    // Per line of code: its words (ids) and brackets ( and ) in order, outside comments.
    std::vector<int32_t> events;
    std::vector<std::string_view> words;  // of code lines, by id: views into `text`
    std::unordered_map<std::string_view, uint32_t> word_ids;
    std::string middles;
};

// Scans `text` (a file's served text, lean) with `skeleton` = ScanSkeleton of the file.
std::shared_ptr<const SpliceFile> ScanSpliceFile(std::shared_ptr<const LeanText> text,
                                                 const PpSkeleton& skeleton);

// What a #define (its text after "define") may leave last where it is expanded, so that a
// bracket on a later line may open a macro's arguments: `calls` for a function-like macro, a
// body that pastes (its pasted name may be one) or leaves a bracket open, else the body's last
// word (empty when none): a macro whose last word may itself be such a macro is one too.
struct DefineEnd {
    bool calls = false;
    std::string_view last_word;
};
DefineEnd EndOfDefine(std::string_view rest);

// By word id of `file`: 0 where the word is no macro of a program whose #define names are
// `defined` (nor one glslang may define itself), 1 where it may be, 2 where it may also leave a
// macro's name last (`callable`, EndOfDefine).
std::vector<char> MacroWords(const SpliceFile& file,
                             const std::unordered_set<std::string_view>& defined,
                             const std::unordered_set<std::string_view>& callable);

// The lines of `file` that may be served short, given `macro` (MacroWords, with the program's
// own names added). `poisoned` is set where a macro call may collect arguments over a directive
// or past the file's end: no line of the program may then be served short.
std::vector<uint32_t> SpliceableLines(const SpliceFile& file,
                                      const std::vector<char>& macro,
                                      bool& poisoned);

// MacroWords and SpliceableLines of one file for one set of #define names, made once.
struct SpliceChoice {
    std::vector<char> macro;
    std::vector<uint32_t> lines;
    bool poisoned = false;
};
SpliceChoice ChooseSpliceLines(const SpliceFile& file,
                               const std::unordered_set<std::string_view>& defined,
                               const std::unordered_set<std::string_view>& callable);

// The marker word's prefix; a program whose texts spell it is not spliced.
inline constexpr std::string_view kSpliceMarker = "qKsP";

// `file`'s text served: the physical lines of `blank` (inclusive, ascending) blanked as
// BlankLines does, and each of `lines` (ascending, none blanked) served short with its marker,
// which names `inclusion` (the file's index in the plan's inclusions).
std::string ServeSpliced(const SpliceFile& file,
                         size_t inclusion,
                         const std::vector<std::pair<uint32_t, uint32_t>>& blank,
                         const std::vector<uint32_t>& lines,
                         size_t& blanked_lines);

// glslang's output for a program served with spliced files (by inclusion index; null where a
// file was served whole) made whole: each marker replaced by its line's tokens. False, with
// `text` unchanged, where a marker is not where a spliced line puts it.
bool Unsplice(std::string& text, const std::vector<std::shared_ptr<const SpliceFile>>& files);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_SPLICE_H_
