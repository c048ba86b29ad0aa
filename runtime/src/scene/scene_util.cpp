// GenerateTangents and the material sidecar reader.
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "kiln/runtime/scene.h"

#include "kiln/base/files.h"
#include "scene/gltf_input.h"

namespace kiln::runtime {

// Lengyel, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh" (2001): per triangle
// T = (dP1 dv2 - dP2 dv1) / det, B = (dP2 du1 - dP1 du2) / det, summed per vertex, then
// orthogonalized against N; w = -sign(dot(cross(N, T), B)) because glTF's v axis points down
// the image (MikkTSpace as glTF viewers run it, on 1 - v). Degenerate UVs fall back to any
// unit vector perpendicular to N.
void GenerateTangents(Primitive& p) {
    std::vector<glm::vec3> tan(p.vertices.size(), glm::vec3(0)),
        bit(p.vertices.size(), glm::vec3(0));
    for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        const uint32_t i[3] = {p.indices[t], p.indices[t + 1], p.indices[t + 2]};
        const MeshVertex& a = p.vertices[i[0]];
        const MeshVertex& b = p.vertices[i[1]];
        const MeshVertex& c = p.vertices[i[2]];
        const glm::vec3 e1 = glm::make_vec3(b.position) - glm::make_vec3(a.position);
        const glm::vec3 e2 = glm::make_vec3(c.position) - glm::make_vec3(a.position);
        const float du1 = b.uv0[0] - a.uv0[0], dv1 = b.uv0[1] - a.uv0[1];
        const float du2 = c.uv0[0] - a.uv0[0], dv2 = c.uv0[1] - a.uv0[1];
        const float det = du1 * dv2 - du2 * dv1;
        if (std::fabs(det) < 1e-20f) {
            continue;
        }
        const float r = 1.0f / det;
        const glm::vec3 sdir = (e1 * dv2 - e2 * dv1) * r;
        const glm::vec3 tdir = (e2 * du1 - e1 * du2) * r;
        for (uint32_t k : i) {
            tan[k] += sdir;
            bit[k] += tdir;
        }
    }
    for (size_t k = 0; k < p.vertices.size(); ++k) {
        MeshVertex& v = p.vertices[k];
        const glm::vec3 n = glm::make_vec3(v.normal);
        glm::vec3 t = tan[k] - n * glm::dot(n, tan[k]);
        float len = glm::length(t);
        if (!(len > 1e-12f)) {
            t = std::fabs(n.x) < 0.9f ? glm::cross(n, glm::vec3(1, 0, 0))
                                      : glm::cross(n, glm::vec3(0, 1, 0));
            len = glm::length(t);
            if (!(len > 1e-12f)) {
                t = glm::vec3(1, 0, 0);
                len = 1;
            }
        }
        t /= len;
        // glTF's v runs down the image while a normal map's +y (green) points up it, so the
        // bitangent must point towards decreasing v: the opposite of the accumulated dP/dv.
        const float w = glm::dot(glm::cross(n, t), bit[k]) > 0.0f ? -1.0f : 1.0f;
        v.tangent[0] = t.x;
        v.tangent[1] = t.y;
        v.tangent[2] = t.z;
        v.tangent[3] = w;
    }
    p.has_tangents = true;
}

Status LoadMaterialSidecar(const std::string& path, Scene& scene) {
    Result<std::string> text = base::ReadRegularFile(path, kMaxSidecarBytes);
    if (!text) {
        return text.error();
    }
    if (JsonDepth(text.value(), kMaxJsonDepth) > kMaxJsonDepth) {
        return Error{DiagCode::kBadScene,
                     path + ": JSON nested more than " + std::to_string(kMaxJsonDepth) + " deep"};
    }
    nlohmann::json doc = nlohmann::json::parse(text.value(), nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !doc.is_object()) {
        return Error{DiagCode::kBadScene, path + ": not a JSON object"};
    }
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    for (const auto& [key, value] : doc.items()) {
        if (key == "kiln_materials") {
            if (!value.is_number_integer() || value.get<int>() != 1) {
                return Error{DiagCode::kBadScene, path + ": kiln_materials must be 1"};
            }
        } else if (key == "materials") {
            if (!value.is_object()) {
                return Error{
                    DiagCode::kBadScene,
                    path + ": 'materials' must map glTF material names to .material files"};
            }
            for (const auto& [name, file] : value.items()) {
                if (!file.is_string()) {
                    return Error{DiagCode::kBadScene,
                                 path + ": material '" + name + "' must name a .material file"};
                }
                scene.material_files[name] = (dir / file.get<std::string>()).lexically_normal();
            }
        } else if (key == "ambient") {
            if (!value.is_array() || value.size() != 3 || !value[0].is_number() ||
                !value[1].is_number() || !value[2].is_number()) {
                return Error{DiagCode::kBadScene,
                             path + ": 'ambient' must be three numbers (linear RGB)"};
            }
            scene.ambient =
                glm::vec3(value[0].get<float>(), value[1].get<float>(), value[2].get<float>());
        } else if (key != "description") {
            return Error{DiagCode::kBadScene,
                         path + ": unknown field '" + key +
                             "' (expected kiln_materials, materials, ambient, description)"};
        }
    }
    return {};
}

}  // namespace kiln::runtime
