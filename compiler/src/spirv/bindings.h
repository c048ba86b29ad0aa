// Descriptor bindings per docs/binding-model.md. glslang leaves every resource at set 0,
// binding 0 unless told otherwise; Kiln assigns them itself, by name, the same way for every
// variant of a pass, by rewriting the DescriptorSet/Binding decorations.
//
//   set 0  built-ins the runtime fills per frame/camera/light (table kBuiltinBindings)
//   set 1  the material: binding 0 is `$Global` (properties and other loose globals), then the
//          pass's other cbuffers by name, then textures (Properties order first, then by name),
//          each followed by its `sampler<Name>` SamplerState when there is one, then the
//          remaining samplers by name
//   push constants are not descriptors and are left alone
#ifndef KILN_SPIRV_BINDINGS_H_
#define KILN_SPIRV_BINDINGS_H_

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "kiln/result.h"

namespace kiln::spirv {

inline constexpr uint32_t kFrameSet = 0;
inline constexpr uint32_t kMaterialSet = 1;

enum class DescriptorClass { kBlock, kTexture, kSampler, kCombined, kStorage };

struct DescriptorVar {
    std::string name;  // variable name, or the block type's name for cbuffers ("$Global")
    DescriptorClass cls = DescriptorClass::kBlock;

    friend auto operator<=>(const DescriptorVar&, const DescriptorVar&) = default;
};

struct Binding {
    uint32_t set = 0, binding = 0;
};

// The set-0 binding of a built-in name, if it is one.
std::optional<Binding> BuiltinBinding(const std::string& name);

// Variables of the module that carry DescriptorSet/Binding decorations.
std::vector<DescriptorVar> ListDescriptorVars(const std::vector<uint32_t>& words);

// Assigns bindings to every name used by any variant of a pass.
std::map<std::string, Binding> AssignBindings(const std::set<DescriptorVar>& used,
                                              const std::vector<std::string>& texture_properties);

// Rewrites the decorations; an internal error when a variable has no binding in `table` or
// lacks the decorations.
Status ApplyBindings(std::vector<uint32_t>& words, const std::map<std::string, Binding>& table);

}  // namespace kiln::spirv

#endif  // KILN_SPIRV_BINDINGS_H_
