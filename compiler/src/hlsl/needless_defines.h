// The #define lines glslang's preprocessor does not need: a macro that no line of the program
// names, other than its #define, never changes glslang's output, so the inactive-text plan
// (hlsl/inactive_text.h) blanks its #define, read once (two would be checked against each other).
// Names are counted over whole files, blanked branches included: a name is needless where the
// files read spell it only in its own #define lines and the program's own text not at all. A
// paste (##) may make a name no file spells; its first piece is a word the #define spells (as
// `sampler` in `sampler##tex`) or an argument, which may be any word: a name is kept where a
// proper prefix of it may be such a piece.
#ifndef KILN_HLSL_NEEDLESS_DEFINES_H_
#define KILN_HLSL_NEEDLESS_DEFINES_H_

#include <memory>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace kiln::hlsl {

struct PpSkeleton;

// What a set of included files alone says about their #define names: made once per set
// (FileCache::Defines) and shared by every program that reads the same files.
struct IncludedDefines {
    // Every name the files #define (but those glslang may define itself).
    std::unordered_set<std::string_view> defined;
    // Those of them whose expansion may end with a macro's name (hlsl/splice.h, MayEndInCall).
    std::unordered_set<std::string_view> callable;
    // Those whose expansion may be empty (not callable: a body of none but such words).
    std::unordered_set<std::string_view> empty;
    // Macros that the files spell only in their own #define lines or in those of other such
    // macros, and that no paste of the files can make.
    std::unordered_set<std::string_view> unnamed;
    // The words of each one's #define lines: needed when it is kept.
    std::unordered_map<std::string_view, std::vector<std::string_view>> bodies;
    // The first piece of each paste of the files, when each is a word the #define spells (as
    // `sampler` in `sampler##tex`); `pieces_known` is false where one is a parameter, whose
    // argument may be any word: a name is then kept where a proper prefix of it is a word of the
    // files, or of the program's own text (`prefixes`).
    std::unordered_set<std::string> pieces;
    bool pieces_known = true;
    std::unordered_map<std::string_view, std::vector<std::string_view>> prefixes;
    std::vector<std::shared_ptr<const PpSkeleton>> skeletons;  // the names are views into these
};

// `files` holds each file once.
IncludedDefines MakeIncludedDefines(std::vector<std::shared_ptr<const PpSkeleton>> files);

// The names of `included.unnamed` that one program leaves needless: those its own text does not
// spell, and that no word of it begins.
class NeedlessDefines {
  public:
    NeedlessDefines(const IncludedDefines& included, const PpSkeleton& main);
    // Takes `name` as needed, and what its #define names (a macro read twice is kept, as
    // glslang compares the two).
    void Keep(std::string_view name);
    // A #define of `name` read once by the program is needless.
    bool Needless(std::string_view name) const {
        return !all_kept_ && included_.unnamed.count(name) != 0 && kept_.count(name) == 0;
    }

  private:
    const IncludedDefines& included_;
    std::unordered_set<std::string_view> kept_;
    bool all_kept_ = false;
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_NEEDLESS_DEFINES_H_
