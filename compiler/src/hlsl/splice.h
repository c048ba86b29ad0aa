// Lines of plain code given to glslang's preprocessor short, and given back whole after it. Most
// tokens of the code glslang reads in Unity's includes are no macro: their output is their own
// spelling, with glslang's spacing between two tokens of a line: one space, none where either is
// one of `;()[]` or the second is `,` (glslang's DoPreprocessing). In such a line of three or
// more tokens, each run of two or more tokens between the first, the last and the macros is
// served as one marker word naming the run; after preprocessing, the marker and the spaces
// glslang put around it are replaced by the run's tokens, spaced from the tokens glslang printed
// around it. The first and last tokens and the macros stay, so that glslang places and spaces
// the line's ends itself (where a line follows a #line of its output, its first token's spacing
// depends on the token before it) and expands the macros.
//
// A line is served so only where none of its words is a macro whose expansion may be empty or
// may leave a macro's name last (nor one glslang may define), no macro call may still be
// collecting arguments over it (a line after one that names such a macro and leaves a bracket
// open, or ends with its name), and it holds nothing glslang reads otherwise than as plain tokens
// (comments, strings, backslashes, '#', other characters than code's, numbers of other forms
// than plain ones).
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

#include "kiln/source.h"

namespace kiln::hlsl {

class FileCache;
struct LeanText;
struct PpSkeleton;

// What one served file's lines hold, scanned once per file.
struct SpliceFile {
    enum class Kind : uint8_t { kEmpty, kDirective, kCode, kPlain };
    struct Tok {
        uint32_t begin = 0, end = 0;  // offsets in the text
        int32_t word = -1;            // its id, when a word
    };
    struct Line {
        Kind kind = Kind::kEmpty;
        int32_t last_word = -1;  // the id of the line's last token, when it is a word
        uint32_t events_begin = 0, events_end = 0;  // in `events`
        uint32_t toks_begin = 0, toks_end = 0;      // kPlain: its tokens, in `toks`
    };
    static constexpr int32_t kOpen = -1, kClose = -2;

    std::shared_ptr<const LeanText> text;  // what the offsets are of
    // False where a line of code is continued by a backslash, or the text spells the marker's
    // prefix: such a file is served without splicing.
    bool usable = false;
    std::vector<Line> lines;  // one per physical line
    // Per line of code: its words (ids) and brackets ( and ) in order, outside comments.
    std::vector<int32_t> events;
    std::vector<Tok> toks;
    std::vector<std::string_view> words;  // of code lines, by id: views into `text`
    std::unordered_map<std::string_view, uint32_t> word_ids;
};

// Scans `text` (a file's served text, lean) with `skeleton` = ScanSkeleton of the file.
std::shared_ptr<const SpliceFile> ScanSpliceFile(std::shared_ptr<const LeanText> text,
                                                 const PpSkeleton& skeleton);

// What a #define (its text after "define") may leave last where it is expanded, so that a
// bracket on a later line may open a macro's arguments: `calls` for a function-like macro, a
// body that pastes (its pasted name may be one) or leaves a bracket open, else the body's last
// word (empty when none): a macro whose last word may itself be such a macro is one too.
// `body` is the text after the name, and `words_only` says it holds nothing but words and
// blanks (none at all included).
struct DefineEnd {
    bool calls = false;
    std::string_view last_word;
    std::string_view body;
    bool words_only = false;
};
DefineEnd EndOfDefine(std::string_view rest);

// What a word may be where a line names it, as far as splicing goes, in rising order: no macro;
// a macro whose expansion glslang prints (it stays in the served line); one whose expansion may
// be empty; one that may leave a macro's name last (EndOfDefine).
enum : char { kNoMacro = 0, kMacro = 1, kEmptyMacro = 2, kCallMacro = 3 };

// By word id of `file`, for a program whose #define names are `defined`: `callable` (those that
// may leave a macro's name last) and `empty` (those whose expansion may be empty) as named; and
// kCallMacro for any name glslang may define itself.
std::vector<char> MacroWords(const SpliceFile& file,
                             const std::unordered_set<std::string_view>& defined,
                             const std::unordered_set<std::string_view>& callable,
                             const std::unordered_set<std::string_view>& empty);

// The lines of `file` that may be served short, given `macro` (MacroWords, with the program's
// own names added): plain lines of three or more tokens that name no macro of kEmptyMacro or
// kCallMacro, outside any macro call's arguments. `poisoned` is set where a macro call may
// collect arguments over a directive or past the file's end: no line of the program may then be
// served short.
std::vector<uint32_t> SpliceableLines(const SpliceFile& file,
                                      const std::vector<char>& macro,
                                      bool& poisoned);

// A run of tokens served as a marker: in a spliceable line, two or more tokens that are not the
// line's first or last and name no macro. The first and last tokens and each macro stay for
// glslang, which places and expands them.
struct SpliceRun {
    uint32_t line = 0;
    uint32_t begin = 0, end = 0;                // the run's bytes in the text
    uint32_t render_begin = 0, render_end = 0;  // in SpliceChoice::renders
    bool first_tight = false;  // the first token is one of ;()[] or a comma (no space before)
    bool last_tight = false;   // the last token is one of ;()[] (no space after)
};

// The runs of one file for one set of #define names (made once per file and set, or per program
// where its own names are words of the file).
struct SpliceChoice {
    std::vector<char> macro;
    std::vector<SpliceRun> runs;  // by line, ascending
    std::string renders;          // each run's tokens as glslang prints them
    bool poisoned = false;
};
SpliceChoice ChooseSpliceRuns(const SpliceFile& file, std::vector<char> macro);

// One inclusion of a plan (hlsl/inactive_text.h), and the lines the plan blanked in it (sorted).
struct SpliceInclusion {
    std::shared_ptr<const SourceFile> file;
    std::shared_ptr<const PpSkeleton> skeleton;
    const std::vector<std::pair<uint32_t, uint32_t>>* blank = nullptr;
};
// What one inclusion serves as markers: its file's runs, and those to serve.
struct InclusionSplice {
    std::shared_ptr<const SpliceFile> file;
    std::shared_ptr<const SpliceChoice> choice;
    std::vector<uint32_t> runs;  // indices into choice->runs, none on a blanked line
};
// Per inclusion of a plan that reached the end of `main` (whose skeleton is `main_skeleton`,
// with the plan's PlanOptions::unknown), what it serves as markers; empty where nothing may be
// (a file not modelled, a macro call that may run over a directive or a file's end, the marker's
// prefix in the main text).
std::vector<InclusionSplice> ChooseSplices(FileCache& cache,
                                           const std::vector<std::string>& unknown,
                                           const PpSkeleton& main_skeleton,
                                           std::string_view main,
                                           const std::vector<SpliceInclusion>& inclusions);

// The marker word's prefix; a program whose texts spell it is not spliced.
inline constexpr std::string_view kSpliceMarker = "qKsP";
// The letter after the prefix of a remembered output's marked name (hlsl/output_memo.h), which
// Unsplice leaves to RestoreOutputs.
inline constexpr char kOutputMarkTag = 'o';

// `file`'s text served: the physical lines of `blank` (inclusive, ascending) blanked as
// BlankLines does, and each of `runs` (indices into choice.runs, ascending, none on a blanked
// line) served as a marker that names `inclusion` (the file's index in the plan's inclusions)
// and the run.
std::string ServeSpliced(const SpliceFile& file,
                         const SpliceChoice& choice,
                         size_t inclusion,
                         const std::vector<std::pair<uint32_t, uint32_t>>& blank,
                         const std::vector<uint32_t>& runs,
                         size_t& blanked_lines);

// glslang's output for a program served with spliced files (by inclusion index; null where a
// file was served whole) made whole: each marker, with the spaces glslang put around it, replaced
// by its run's tokens spaced as glslang spaces them from the tokens around. False, with `text`
// unchanged, where a marker is not where a run puts it (first or last of an output line, a
// marker twice, spaces other than glslang's).
bool Unsplice(std::string& text, const std::vector<std::shared_ptr<const SpliceChoice>>& files);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_SPLICE_H_
