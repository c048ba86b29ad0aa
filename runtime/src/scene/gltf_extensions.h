// The glTF extensions Kiln reads, and what it does with the others: one table. A file that
// requires (extensionsRequired) an extension Kiln does not support cannot be drawn as its author
// meant, so loading it is an error that names the extension and what it is (K0030); an
// unsupported extension the file only uses, and the core features Kiln does not draw (skins,
// animations, morph targets), are one warning each (K0016).
#ifndef KILN_RUNTIME_SCENE_GLTF_EXTENSIONS_H_
#define KILN_RUNTIME_SCENE_GLTF_EXTENSIONS_H_

#include <string>
#include <string_view>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/result.h"

namespace tinygltf {
class Model;
}

namespace kiln::runtime {

// True for the extensions the loader and renderer implement: KHR_lights_punctual,
// KHR_materials_emissive_strength, KHR_materials_unlit, KHR_mesh_quantization,
// KHR_texture_transform.
bool IsSupportedExtension(std::string_view name);

// What an unsupported extension is, for messages ("Draco mesh compression"); empty when the
// table does not know it.
std::string_view ExtensionDescription(std::string_view name);

// An error (K0030) for the first of `required` that Kiln does not support; `path` is the file.
Status CheckRequiredExtensions(const std::string& path, const std::vector<std::string>& required);

// extensionsRequired of glTF JSON text, read without tinygltf (which fails on some of them,
// Draco's accessors without a bufferView, before saying why); empty when the text is not JSON.
std::vector<std::string> RequiredExtensionsOf(std::string_view json);

// One K0016 warning per optional feature of `model` that is not drawn: each unsupported
// extension in extensionsUsed, skins, animations, morph targets.
void WarnIgnoredFeatures(const tinygltf::Model& model,
                         const std::string& path,
                         DiagnosticList& diags);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_SCENE_GLTF_EXTENSIONS_H_
