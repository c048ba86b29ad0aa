// Kiln's mesh vertex, the one layout the runtime fills from glTF and every pipeline reads, and
// the HLSL input semantic that reads each stream: an engine feeding Kiln's shaders from its own
// meshes matches VertexStreamFor().
#ifndef KILN_PACK_VERTEX_H_
#define KILN_PACK_VERTEX_H_

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace kiln::pack {

// Interleaved, 72 bytes.
struct MeshVertex {
    float position[3];
    float normal[3];
    float uv0[2];
    float uv1[2];
    float tangent[4];  // xyz + handedness w (bitangent = w * cross(normal, tangent))
    float color[4];    // linear RGBA; white when the mesh has none
};
static_assert(sizeof(MeshVertex) == 72);

struct VertexStream {
    uint32_t offset;      // bytes into MeshVertex
    uint32_t components;  // 32-bit floats
};

// The stream a vertex input with `semantic` (upper-case, as reflection stores it: POSITION,
// NORMAL, TEXCOORD0, TEXCOORD1, TANGENT, COLOR; a missing index means 0) reads; nullopt for one
// Kiln's meshes do not carry.
constexpr std::optional<VertexStream> VertexStreamFor(std::string_view semantic) {
    if (semantic == "POSITION" || semantic == "POSITION0") {
        return VertexStream{offsetof(MeshVertex, position), 3};
    }
    if (semantic == "NORMAL" || semantic == "NORMAL0") {
        return VertexStream{offsetof(MeshVertex, normal), 3};
    }
    if (semantic == "TEXCOORD" || semantic == "TEXCOORD0") {
        return VertexStream{offsetof(MeshVertex, uv0), 2};
    }
    if (semantic == "TEXCOORD1") {
        return VertexStream{offsetof(MeshVertex, uv1), 2};
    }
    if (semantic == "TANGENT" || semantic == "TANGENT0") {
        return VertexStream{offsetof(MeshVertex, tangent), 4};
    }
    if (semantic == "COLOR" || semantic == "COLOR0") {
        return VertexStream{offsetof(MeshVertex, color), 4};
    }
    return std::nullopt;
}

}  // namespace kiln::pack

#endif  // KILN_PACK_VERTEX_H_
