#include "render/harness_scene.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace kiln::render {
namespace {

const glm::vec3 kEye(0.0f, 0.6f, 2.4f);
const glm::vec3 kTarget(0.0f, 0.5f, 0.0f);

runtime::MeshVertex Vertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv, glm::vec3 t) {
    runtime::MeshVertex v{};
    for (int i = 0; i < 3; ++i) {
        v.position[i] = p[i];
        v.normal[i] = n[i];
        v.tangent[i] = t[i];
    }
    v.tangent[3] = 1;
    v.uv0[0] = v.uv1[0] = uv.x;
    v.uv0[1] = v.uv1[1] = uv.y;
    for (float& c : v.color) {
        c = 1;
    }
    return v;
}

runtime::Primitive Sphere(uint32_t segments, uint32_t rings) {
    runtime::Primitive p;
    const float pi = 3.14159265f;
    for (uint32_t r = 0; r <= rings; ++r) {
        const float theta = pi * float(r) / float(rings);
        for (uint32_t s = 0; s <= segments; ++s) {
            const float phi = 2 * pi * float(s) / float(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              -std::sin(theta) * std::sin(phi));
            const glm::vec3 t(-std::sin(phi), 0.0f, -std::cos(phi));  // d position / d u
            p.vertices.push_back(Vertex(kTarget + 0.5f * n, n,
                                        {float(s) / float(segments), float(r) / float(rings)}, t));
        }
    }
    for (uint32_t r = 0; r < rings; ++r) {
        for (uint32_t s = 0; s < segments; ++s) {
            const uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
            p.indices.insert(p.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    }
    p.has_tangents = true;
    return p;
}

runtime::Primitive Plane() {
    runtime::Primitive p;
    const glm::vec3 up(0, 1, 0), t(1, 0, 0);
    p.vertices = {Vertex({-2, 0, -2}, up, {0, 0}, t), Vertex({-2, 0, 2}, up, {0, 1}, t),
                  Vertex({2, 0, 2}, up, {1, 1}, t), Vertex({2, 0, -2}, up, {1, 0}, t)};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.has_tangents = true;
    return p;
}

}  // namespace

runtime::Scene HarnessScene() {
    runtime::Scene scene;
    scene.path = "<kiln test harness>";
    scene.meshes.push_back({"sphere", {Sphere(32, 16)}});
    scene.meshes.push_back({"plane", {Plane()}});
    scene.instances.push_back({0, glm::mat4(1.0f), "sphere"});
    scene.instances.push_back({1, glm::mat4(1.0f), "plane"});
    for (runtime::Mesh& mesh : scene.meshes) {
        ComputeBounds(mesh.primitives[0]);
    }
    scene.id = runtime::NewSceneId();
    runtime::Camera camera;
    camera.name = "harness";
    camera.yfov = 0.6f;
    camera.world = glm::inverse(glm::lookAt(kEye, kTarget, glm::vec3(0, 1, 0)));
    scene.cameras.push_back(camera);
    return scene;
}

runtime::Light HarnessLight(runtime::LightType type, float intensity) {
    runtime::Light l;
    l.type = type;
    l.name = type == runtime::LightType::kPoint  ? "harness point light"
             : type == runtime::LightType::kSpot ? "harness spot light"
                                                 : "harness directional light";
    l.intensity = intensity;
    l.position = kEye;
    l.direction = glm::normalize(kTarget - kEye);
    l.inner_cone = 0.3f;
    l.outer_cone = 0.5f;
    return l;
}

}  // namespace kiln::render
