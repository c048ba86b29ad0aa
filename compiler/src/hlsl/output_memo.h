// glslang's output for an #include, remembered per worker and given back without glslang reading
// the included code again. A program's included code is nearly all served to glslang exactly as
// it was to an earlier program (the shipped materials: 98% of its bytes), and glslang reads it a
// character at a time each time (docs/performance.md, "The next lever").
//
// The unit is a walk the plan memo remembers (hlsl/plan_memo.h): an #include with the files it
// includes, whose branches are decided alike wherever the memo takes it. glslang's output for
// it, between its prologue's `#line` and its return's, depends on that walk's served lines and
// on the macros its lines name as they are at the #include (closed over their bodies), so it is
// kept under the walk and a fingerprint of those definitions (PpMacros::Fingerprint). A program
// whose walk and fingerprint match serves the walk's root as its #define, #undef and #pragma
// lines only (glslang's macro table after it is the same), does not serve the files it
// includes, and is given the kept output in place of what glslang printed for it. glslang
// stays the judge of every output: Kiln expands nothing.
//
// Not remembered: a walk with a branch the plan did not decide, a #line, #error or other
// directive that is not #define, #undef, #include, #pragma or a decided conditional's, a use of
// __FILE__, or a name the table does not know at the #include.
#ifndef KILN_HLSL_OUTPUT_MEMO_H_
#define KILN_HLSL_OUTPUT_MEMO_H_

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hlsl/pp_macros.h"
#include "kiln/source.h"

namespace kiln::hlsl {

struct IncludeWalk;
struct WalkWords;

using OutputKey = std::pair<uint64_t, uint64_t>;

// glslang's output for a walk, between its prologue's #line and its return's. glslang spaces the
// first token after a #line by the token before it (DoPreprocessing: one space, none after any
// of `;()[]` or at the start), so an output is kept only where its first token follows an empty
// line, and `last` says how its last token spaces the token after its return: ';' for one of
// `;()[]`, '0' for any other, 0 where it has none. A replay serves that token last, so glslang
// spaces the token after the return as it did.
struct KeptOutput {
    std::string text;
    char last = 0;
};

// A walk whose output the plan remembers: `inclusion` is its root in the plan's inclusions, and
// `count` the inclusions it makes (the root's own first). With `output`, the kept output is
// replayed (served as `words` says); without, glslang's output is kept after it runs.
struct OutputMark {
    size_t inclusion = 0;
    size_t count = 0;
    std::shared_ptr<const IncludeWalk> walk;
    OutputKey key;
    std::shared_ptr<const KeptOutput> output;
    std::shared_ptr<const WalkWords> words;  // with `output`
};

// What a walk's output depends on besides the macros, made once per walk.
struct WalkWords {
    bool usable = false;
    WordHashSet words;        // of its read lines
    bool names_file = false;  // __FILE__ is one
    std::string directives;   // its #define, #undef and #pragma lines, in the order read
    // The files its root includes, in the order glslang reads them (a replay's dependencies).
    std::vector<std::shared_ptr<const SourceFile>> nested;
};

class OutputMemo {
  public:
    // The key of `walk`'s output where the macro table at its #include is `macros`; nullopt
    // where it is not remembered. Thread-safe.
    std::optional<OutputKey> Key(const std::shared_ptr<const IncludeWalk>& walk,
                                 const PpMacros& macros);
    // The output kept for `walk` and `key`, or null. Thread-safe.
    std::shared_ptr<const KeptOutput> Find(const IncludeWalk* walk, const OutputKey& key);
    // The text a replayed `walk` is served as (Key was asked for it). Thread-safe.
    std::shared_ptr<const WalkWords> Words(const IncludeWalk* walk);
    // Keeps `output` (the text between the prologue and the return) for `mark`'s walk and key,
    // where it does not depend on the token before the walk's #include. Thread-safe.
    void Add(const OutputMark& mark, std::string output);

    static constexpr size_t kMaxOutputsPerWalk = 16;
    static constexpr size_t kMaxBytes = size_t{64} << 20;

  private:
    struct Entry {
        std::shared_ptr<const IncludeWalk> walk;  // kept, so its address is not reused
        std::shared_ptr<const WalkWords> words;
        std::vector<std::pair<OutputKey, std::shared_ptr<const KeptOutput>>> outputs;
    };
    std::mutex mu_;
    std::unordered_map<const IncludeWalk*, Entry> walks_;
    size_t bytes_ = 0;
};

// The text a replayed walk is served as: `words`' directives, then a token spaced as `output`'s
// last.
std::string ReplayedText(const WalkWords& words, const KeptOutput& output);

// The name a marked root is served under: `path` marked with its inclusion index (the splice
// marker's prefix, which no text of a spliced program spells).
std::string OutputMarkName(size_t inclusion, std::string_view path);

// glslang's output for a plan with `marks` (sorted by inclusion), after its blank inclusions and
// splices were given back: each replayed walk's output put in, each marked name given back, and
// each recorded walk's output kept in `memo` when given. False, `text` unchanged, where the
// output is not as the marks expect.
bool RestoreOutputs(std::string& text, const std::vector<OutputMark>& marks, OutputMemo* memo);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_OUTPUT_MEMO_H_
