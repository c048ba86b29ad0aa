// The inactive-text plan's walk of an #include, remembered (hlsl/inactive_text.h). What walking a
// file does to the plan depends only on the file and the files it includes, on how includes
// resolve, on the plan's options and on the macros it reads: Unity's includes read a few
// keywords among hundreds of names, so most variants of a pass walk most files alike. Each
// walk is kept with the names it read before writing them and what it read (a decision tree per
// file: the walk is deterministic, so walks that read the same values up to a point read the
// same next name), and a later walk that would read the same values takes the remembered one:
// its inclusions, and the names it wrote with their values, instead of reading its directives.
// The tree answers "would read the same" with one table lookup per name read.
#ifndef KILN_HLSL_PLAN_MEMO_H_
#define KILN_HLSL_PLAN_MEMO_H_

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hlsl/pp_macros.h"
#include "kiln/source.h"

namespace kiln::hlsl {

struct PpSkeleton;
struct LeanText;

using LineRanges = std::vector<std::pair<uint32_t, uint32_t>>;  // inclusive

// A #define glslang reads, which is needless when nothing else it reads names it.
struct DefineLine {
    uint32_t first_line = 0, last_line = 0;
    std::string_view name;  // in the file's skeleton
    bool maybe = false;     // in a branch it may or may not read: kept, but counted as a read
};

// An inclusion whose text is made when the walk ends, once it is known which #define lines no
// other line names.
struct Pending {
    size_t index = 0;  // in InactiveTextPlan::inclusions
    std::shared_ptr<const SourceFile> file;
    std::shared_ptr<const PpSkeleton> skeleton;
    std::shared_ptr<const LeanText> lean;
    LineRanges blank;
    std::vector<DefineLine> defines;
};

// What walking one #include did to the plan.
struct IncludeWalk {
    std::vector<std::string> paths;  // the inclusions it added, in order (the file's own first)
    std::vector<Pending> pending;    // as they were added; `index` counts from its first inclusion
    size_t maybe_branches = 0;
    bool names_unknown = false;  // it found PlanOptions::unknown named outside conditions
    bool stopped = false;
    std::vector<std::pair<std::string, MacroValue>> reads;   // as MacroLog::reads
    std::vector<std::pair<std::string, MacroValue>> writes;  // each name written, as it was left
    size_t bytes = 0;                                        // about what it holds
};

class PlanMemo {
  public:
    // The walks of `file` with `context` (the include paths, the depth and the plan's options):
    // the one that read what `macros` holds now, or null. Thread-safe.
    std::shared_ptr<const IncludeWalk> Find(const std::shared_ptr<const SourceFile>& file,
                                            const std::string& context,
                                            const PpMacros& macros);
    // Whether a walk of `file` with `context` is still worth logging: each file keeps a bounded
    // number of walks, and the memo a bounded number of bytes, and a file whose walks are seldom
    // taken again (one that reads what differs in every variant) is no longer logged, since
    // logging costs about as much as the walk.
    bool Open(const std::shared_ptr<const SourceFile>& file, const std::string& context);
    // Keeps `walk`, made from what `walk.reads` held.
    void Add(const std::shared_ptr<const SourceFile>& file,
             const std::string& context,
             std::shared_ptr<const IncludeWalk> walk);

    static constexpr size_t kMaxWalksPerFile = 48;
    // Walks of a file kept before its hits are counted, and the hits per walk it needs then.
    static constexpr size_t kTrialWalks = 8;
    static constexpr size_t kHitsPerWalk = 1;
    static constexpr size_t kMaxBytes = size_t{48} << 20;

  private:
    // Reads `name` and goes to the child that read the same; a leaf holds a walk.
    struct Node {
        std::string name;
        std::vector<std::pair<MacroValue, std::unique_ptr<Node>>> next;
        std::shared_ptr<const IncludeWalk> walk;
        // The child for what `name` read, or null.
        Node* Child(const MacroValue& value) const;
    };
    struct Tree {
        std::shared_ptr<const SourceFile> file;  // kept, so its address is not reused
        Node root;
        size_t walks = 0;
        size_t hits = 0;
    };
    using Key = std::pair<const SourceFile*, std::string>;

    std::mutex mu_;
    std::map<Key, Tree> trees_;
    size_t bytes_ = 0;
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_PLAN_MEMO_H_
