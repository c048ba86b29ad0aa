// The one name of a pass, used by the compiler's messages and `kiln variants`, by `kiln info`, the
// runtime's messages, the usage log and the variant selector, so that a pass named in one can be
// looked up in the other (scene-driven stripping joins the usage log with the pack on it).
//
// A pass is called by its Name; an unnamed pass by its LightMode tag; a pass with neither by its
// position, "#2" (1-based among the SubShader's compiled passes). When the shader's passes come
// from more than one SubShader, "SubShader 2/" goes before it. Examples: "FORWARD",
// "ForwardBase", "#1", "SubShader 2/ShadowCaster".
#ifndef KILN_PACK_PASS_ID_H_
#define KILN_PACK_PASS_ID_H_

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace kiln::pack {

class Pack;

struct PassIdParts {
    std::string_view name;            // Name "..." (empty when unnamed)
    std::string_view light_mode;      // the LightMode tag (empty when untagged)
    uint32_t subshader = 0;           // 0-based SubShader of the pass
    uint32_t index = 0;               // 0-based among its SubShader's compiled passes
    bool several_subshaders = false;  // the shader's passes come from more than one SubShader
};

std::string PassId(const PassIdParts& parts);

// The parts and PassId of a pack's pass; "" for an index out of range.
PassIdParts PassIdPartsOf(const Pack& pack, uint32_t pass);
std::string PassLabel(const Pack& pack, uint32_t pass);

// The LightMode tag of a pack's pass, or "".
std::string_view LightModeOf(const Pack& pack, uint32_t pass);

// Unity's render queue of a "Queue" tag value (kiln/pack/engine_names.h: a name with an optional
// +N or -N, or a number); nullopt when unreadable.
std::optional<int> RenderQueue(std::string_view queue_tag);
// The render queue of a pack's pass (its own or its SubShader's Queue tag), nullopt when it has
// none; Unity's default for a shader without one is Geometry (2000).
std::optional<int> RenderQueueOf(const Pack& pack, uint32_t pass);
// Whether `shader` draws in a transparent queue (above kRenderQueueTransparentAbove, as Unity
// sorts and draws them: after the opaque ones, back to front, and forward on the deferred path),
// by its first pass's Queue tag.
bool IsTransparentShader(const Pack& pack, uint32_t shader);

}  // namespace kiln::pack

#endif  // KILN_PACK_PASS_ID_H_
