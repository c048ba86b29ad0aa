// Reading glTF accessors with every element checked against its buffer view and buffer.
#ifndef KILN_RUNTIME_SCENE_ACCESSORS_H_
#define KILN_RUNTIME_SCENE_ACCESSORS_H_

#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "kiln/result.h"

namespace kiln::runtime {

// Accessor `index` as floats, `want` components per element (missing components 0), integer
// types normalized when the accessor says so. An error (K0007) on any inconsistency.
Status ReadAccessor(const tinygltf::Model& m, int index, int want, std::vector<float>& out);

// An index accessor, exact for 32-bit indices.
Status ReadIndices(const tinygltf::Model& m, int index, std::vector<uint32_t>& out);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_SCENE_ACCESSORS_H_
