// GenerateTangents, local bounds, scene ids, and the material sidecar applied to a scene.
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "kiln/runtime/scene.h"

#include "kiln/material/sidecar.h"
#include "kiln/pack/names.h"

namespace kiln::runtime {

void ComputeBounds(Primitive& p) {
    p.bounds_min = glm::vec3(std::numeric_limits<float>::max());
    p.bounds_max = -p.bounds_min;
    for (const MeshVertex& v : p.vertices) {
        const glm::vec3 position = glm::make_vec3(v.position);
        p.bounds_min = glm::min(p.bounds_min, position);
        p.bounds_max = glm::max(p.bounds_max, position);
    }
}

uint64_t NewSceneId() {
    static std::atomic<uint64_t> next{1};
    return next.fetch_add(1, std::memory_order_relaxed);
}

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
    Result<material::MaterialSidecar> read = material::ReadMaterialSidecar(path);
    if (!read) {
        return read.error();
    }
    for (const auto& [name, file] : read.value().materials) {
        scene.material_files[name] = file;
    }
    const material::MaterialSidecar& sidecar = read.value();
    std::vector<std::string> names;
    for (const Light& l : scene.lights) {
        names.push_back(l.name);
    }
    for (const auto& [name, mode] : sidecar.light_modes) {
        if (std::find(names.begin(), names.end(), name) == names.end()) {
            return Error{DiagCode::kBadScene, path + ":" + mode.second +
                                                  ": the scene has no light named '" + name + "'" +
                                                  pack::DidYouMean(name, names)};
        }
    }
    for (Light& l : scene.lights) {
        if (auto it = sidecar.light_modes.find(l.name); it != sidecar.light_modes.end()) {
            l.importance = it->second.first == "important"       ? LightImportance::kImportant
                           : it->second.first == "not-important" ? LightImportance::kNotImportant
                                                                 : LightImportance::kAuto;
        }
    }
    if (sidecar.has_ambient) {
        const auto vec = [](const std::array<float, 3>& a) { return glm::vec3(a[0], a[1], a[2]); };
        scene.ambient_mode = sidecar.trilight ? AmbientMode::kTrilight : AmbientMode::kFlat;
        scene.ambient_given = true;
        scene.ambient = vec(sidecar.ambient);
        scene.ambient_equator = vec(sidecar.equator);
        scene.ambient_ground = vec(sidecar.ground);
        if (!sidecar.trilight) {
            scene.ambient_equator = scene.ambient_ground = scene.ambient;
        }
    }
    return {};
}

}  // namespace kiln::runtime
