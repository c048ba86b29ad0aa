// Material instances as the renderer binds them: the shader's property defaults, then a
// .material file or a glTF material on top, resolved into numbers (linear), textures (with their
// colour space) and keywords; and the writer that fills a uniform block by reflected offsets.
#ifndef KILN_RUNTIME_RENDER_MATERIAL_BINDING_H_
#define KILN_RUNTIME_RENDER_MATERIAL_BINDING_H_

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kiln/material/material.h"
#include "kiln/pack/reader.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/scene.h"
#include "vk/pipeline.h"

namespace kiln::runtime {

struct TextureBinding {
    // kAmbient: the scene's ambient radiance as the environment (the reflection-probe cube
    // unity_SpecCube0/1, prefiltered per roughness mip; render/reflection_probe.h).
    enum class Source { kDefault, kSceneImage, kFile, kAmbient };
    Source source = Source::kDefault;
    std::string default_name = "white";  // "white", "black", "gray", "bump", "red"
    int image = -1;                      // kSceneImage
    std::string file;                    // kFile
    bool srgb = true;
    TextureWrap wrap_u = TextureWrap::kRepeat, wrap_v = TextureWrap::kRepeat;
    bool nearest = false;
};

struct MaterialInstance {
    std::string name;  // for messages: the .material file or "glTF material 'x'"
    uint32_t pack = 0, shader = 0;
    // Color/Vector/Float/Range + _ST vectors (looked up by string_view, without a copy)
    std::map<std::string, std::vector<float>, std::less<>> values;
    std::map<std::string, TextureBinding> textures;
    std::vector<std::string> keywords;
    std::vector<pack::StateOverride> overrides;      // every pass (Blend: not additive passes)
    std::vector<pack::StateOverride> add_overrides;  // additive passes only
    bool transparent = false;                        // drawn after opaque, back to front
};

// The shader's Properties defaults. Colors (and [Gamma] floats/vectors) are sRGB-authored and
// decoded to linear through `color`; [HDR] colours are not clamped to [0, 1] first.
void InstanceFromDefaults(const pack::Pack& pack,
                          uint32_t pack_index,
                          uint32_t shader,
                          const ColorPipeline& color,
                          MaterialInstance& out);

// Reads, validates (against the pack) and applies a .material file on top of the shader's
// defaults; the shader comes from the file. Errors carry file:line:col.
Status InstanceFromMaterialFile(const std::vector<const pack::Pack*>& packs,
                                const std::string& path,
                                const ColorPipeline& color,
                                MaterialInstance& out);

// A glTF metallic-roughness material mapped onto Kiln/StandardMetallic, or a KHR_materials_unlit
// one onto Kiln/Unlit (factors are linear in glTF and written as they are; maps switch on their
// shader_feature keywords; each map's KHR_texture_transform and UV set go to <map>_ST and
// <map>_UV, materials/GltfTexture.cginc).
void ApplyGltfMaterial(const SceneMaterial& m, MaterialInstance& inout);

// Writes a uniform or push-constant block: each member whose name `lookup` knows gets that
// value (clipped to the member's size; floats converted for int members); others stay zero.
using ValueLookup = std::function<const std::vector<float>*(std::string_view name)>;
// Writes one member's value at its offset in `dst` (converted to its base type; at most its
// size and the value's), after zeroing the member's bytes.
void WriteMember(const pack::MemberRec& member,
                 const std::vector<float>& value,
                 uint8_t* dst,
                 size_t dst_size);
void WriteBlock(const pack::Pack& pack,
                const pack::BlockRec& block,
                const ValueLookup& lookup,
                uint8_t* dst,
                size_t dst_size);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_MATERIAL_BINDING_H_
