// A glTF file and everything it refers to, read within limits before tinygltf sees any of it:
// regular files only (a buffer uri naming a directory or a device is an error, not an allocation
// of its "size"), bounded sizes, JSON nested no deeper than kMaxJsonDepth (tinygltf's parser
// recurses once per level). Images are decoded by Kiln's image reader (kiln/runtime/image.h), not
// tinygltf's: bounded, and a truncated image is an error, not rows of zeros.
#ifndef KILN_RUNTIME_SCENE_GLTF_INPUT_H_
#define KILN_RUNTIME_SCENE_GLTF_INPUT_H_

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/result.h"

namespace tinygltf {
class Model;
}

namespace kiln::runtime {

inline constexpr uint64_t kMaxSceneFileBytes = uint64_t{1} << 30;  // .gltf, .glb, .bin, images
inline constexpr size_t kMaxJsonDepth = 128;

// Deepest nesting of arrays and objects in JSON text (strings skipped); stops counting once past
// `limit`, so the scan is linear whatever the input.
size_t JsonDepth(std::string_view json, size_t limit);

// tinygltf's messages, which end with newlines, one per line.
std::vector<std::string> MessageLines(const std::string& text);

// Loads `path` (.gltf, or .glb by extension) into `model`; tinygltf's warnings go to `warn`. A
// required extension Kiln does not support is an error (K0030, scene/gltf_extensions.h), also
// where tinygltf itself fails on the file. An image that cannot be decoded is left empty and
// `image_errors` says why, by image index.
Status LoadGltfModel(const std::string& path,
                     tinygltf::Model& model,
                     std::string& warn,
                     std::map<int, std::string>& image_errors);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_SCENE_GLTF_INPUT_H_
