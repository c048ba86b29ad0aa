// The macro table of the inactive-text plan (hlsl/inactive_text.h) and its #if evaluation, as
// glslang's preprocessor evaluates: 32-bit int arithmetic, an undefined name is 0. Every answer
// is exact or "not known" (nullopt, false): a function-like macro, a literal other than a plain
// int, an operator glslang does not evaluate, a name glslang may define itself (GL_*, __*,
// VULKAN) or a macro whose definition is not known all give "not known", and the plan then
// blanks nothing that depends on it.
#ifndef KILN_HLSL_PP_MACROS_H_
#define KILN_HLSL_PP_MACROS_H_

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

namespace kiln::hlsl {

// Whether glslang's preprocessor may define `name` itself (GL_*, __*, VULKAN).
bool GlslangMayDefine(std::string_view name);
// The macro a #define's or #undef's text (after the directive name) names; empty when none.
std::string_view DirectiveMacroName(std::string_view rest);

enum class MacroState { kUndefined, kDefined, kUnknown };

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

    // #if / #elif's expression; #ifdef's operand (#ifndef is its negation).
    std::optional<bool> If(std::string_view expression) const;
    std::optional<bool> Ifdef(std::string_view rest) const;

  private:
    struct Macro {
        bool function_like = false;
        std::string body;
    };
    std::unordered_map<std::string, Macro> defined_;
    std::unordered_set<std::string> unknown_;
    std::unordered_set<std::string> pinned_;
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_PP_MACROS_H_
