// The macro table of the inactive-text plan (hlsl/inactive_text.h) and its #if evaluation, as
// glslang's preprocessor evaluates: 32-bit int arithmetic, an undefined name is 0. Every answer
// is exact or "not known" (nullopt, false): a function-like macro, a literal other than a plain
// int, an operator glslang does not evaluate, a name glslang may define itself (GL_*, __*,
// VULKAN) or a macro whose definition is not known all give "not known", and the plan then
// blanks nothing that depends on it.
#ifndef KILN_HLSL_PP_MACROS_H_
#define KILN_HLSL_PP_MACROS_H_

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace kiln::hlsl {

// Whether glslang's preprocessor may define `name` itself (GL_*, __*, VULKAN).
bool GlslangMayDefine(std::string_view name);
// The macro a #define's or #undef's text (after the directive name) names; empty when none.
std::string_view DirectiveMacroName(std::string_view rest);

enum class MacroState { kUndefined, kDefined, kUnknown };

// A word's 64-bit hash, as WordHashSet keeps it.
uint64_t WordHash(std::string_view word);

// A set of words kept as their hashes (for PpMacros::Fingerprint): one probe per word asked,
// and a false "in the set" only where two words' hashes collide.
class WordHashSet {
  public:
    void Insert(std::string_view word);
    bool Has(uint64_t hash) const;
    bool Has(std::string_view word) const { return Has(WordHash(word)); }
    size_t size() const { return size_; }

  private:
    std::vector<uint64_t> slots_;  // 0 is empty; a hash of 0 is kept as 1
    size_t size_ = 0;
};

// What the table holds for one name.
struct MacroValue {
    MacroState state = MacroState::kUndefined;
    bool function_like = false;  // kDefined
    std::string body;            // kDefined: the text after the name (and parameters), trimmed
    std::string params;          // kDefined and function-like: the parameters, "(" to ")"
    bool operator==(const MacroValue& o) const {
        return state == o.state && function_like == o.function_like && body == o.body &&
               params == o.params;
    }
};

// What a stretch of the walk read of the table and wrote to it (hlsl/plan_memo.h): each name
// read before it was written there, with what it read, in order; and each name written.
struct MacroLog {
    std::vector<std::pair<std::string, MacroValue>> reads;
    std::vector<std::string> writes;
    std::unordered_set<std::string> seen;     // read or written
    std::unordered_set<std::string> written;  // of `writes`
};

class PpMacros {
  public:
    // #define's and #undef's text after the directive name. False when the line is not one
    // glslang accepts as written (the plan then stops).
    bool Define(std::string_view rest);
    bool Undef(std::string_view rest);
    // A #define or #undef on a line that may or may not be read: its macro becomes unknown.
    void Forget(std::string_view rest);

    // Takes `name` as unknown from now on, whatever the text defines.
    void Pin(const std::string& name) { pinned_.insert(name); }

    MacroState Lookup(std::string_view name) const;

    // What a lookup of `name` sees (Lookup with the definition), and what the table itself
    // holds for it (pinned names included).
    MacroValue Value(const std::string& name) const;
    MacroValue Held(const std::string& name) const;
    // Makes the table hold `value` for `name`, as a write.
    void Set(const std::string& name, const MacroValue& value);

    // Logs the reads and writes from now on into `log` until CloseLog; logs nest, and closing
    // one adds what it logged to the one it was opened in. Reads of names glslang may define
    // are not logged (Lookup does not read the table for them).
    void OpenLog(MacroLog* log) { logs_.push_back(log); }
    void CloseLog();
    // Logs reads made elsewhere (a stretch replayed from a memo) into the open log, if any.
    void NoteReads(const std::vector<std::pair<std::string, MacroValue>>& reads);

    // A fingerprint of what the table holds for the names in `words` (hlsl/output_memo.h): each
    // one defined there with its definition, closed over the words of those definitions' bodies;
    // the same table restricted to those names gives the same fingerprint, whatever its order.
    // nullopt where one of them is not known (pinned or unknown).
    std::optional<std::pair<uint64_t, uint64_t>> Fingerprint(const WordHashSet& words) const;

    // #if / #elif's expression; #ifdef's operand (#ifndef is its negation).
    std::optional<bool> If(std::string_view expression) const;
    std::optional<bool> Ifdef(std::string_view rest) const;

  private:
    struct Macro {
        bool function_like = false;
        std::string body;
        std::string params;
        uint64_t name_hash = 0;  // WordHash of its name
    };
    void Wrote(std::string_view name);

    std::unordered_map<std::string, Macro> defined_;
    std::unordered_set<std::string> unknown_;
    std::unordered_set<std::string> pinned_;
    // Logging does not change what the table answers.
    mutable std::vector<MacroLog*> logs_;
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_PP_MACROS_H_
