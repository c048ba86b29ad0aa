// glTF materials and their texture references -> SceneMaterial: metallic-roughness factors and
// maps, each map's sampler (wrapS and wrapT apart, mirrored repeat), UV set and
// KHR_texture_transform, KHR_materials_emissive_strength and KHR_materials_unlit.
#ifndef KILN_RUNTIME_SCENE_GLTF_MATERIAL_H_
#define KILN_RUNTIME_SCENE_GLTF_MATERIAL_H_

#include <string>

#include "kiln/diagnostic.h"
#include "kiln/runtime/scene.h"

namespace tinygltf {
class Model;
struct Material;
}  // namespace tinygltf

namespace kiln::runtime {

// Material `index` of `m`. A map reading a UV set past TEXCOORD_1 (Kiln's vertex has two) reads
// TEXCOORD_0 with a K0016 warning naming the material and the map; `path` is the scene.
SceneMaterial ReadGltfMaterial(const tinygltf::Model& m,
                               size_t index,
                               const std::string& path,
                               DiagnosticList& diags);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_SCENE_GLTF_MATERIAL_H_
