#include "harness/harness_scene.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace kiln::tools {

using runtime::CameraSetup;
using runtime::ComputeBounds;
using runtime::ForwardPlan;
namespace {

const glm::vec3 kEye = kHarnessEye;
const glm::vec3 kTarget = kHarnessSphereCentre;

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

}  // namespace

runtime::Primitive SpherePrimitive(uint32_t segments,
                                   uint32_t rings,
                                   glm::vec3 centre,
                                   float radius) {
    runtime::Primitive p;
    const float pi = 3.14159265f;
    for (uint32_t r = 0; r <= rings; ++r) {
        const float theta = pi * float(r) / float(rings);
        for (uint32_t s = 0; s <= segments; ++s) {
            const float phi = 2 * pi * float(s) / float(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              -std::sin(theta) * std::sin(phi));
            const glm::vec3 t(-std::sin(phi), 0.0f, -std::cos(phi));  // d position / d u
            p.vertices.push_back(Vertex(centre + radius * n, n,
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

runtime::Primitive FloorPrimitive(float h) {
    runtime::Primitive p;
    const glm::vec3 up(0, 1, 0), t(1, 0, 0);
    p.vertices = {Vertex({-h, 0, -h}, up, {0, 0}, t), Vertex({-h, 0, h}, up, {0, 1}, t),
                  Vertex({h, 0, h}, up, {1, 1}, t), Vertex({h, 0, -h}, up, {1, 0}, t)};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.has_tangents = true;
    return p;
}

namespace {

// The plane z = 0, |x|, |y| <= 2, as eight triangles around the origin, facing +z.
runtime::Primitive FacingPlane() {
    runtime::Primitive p;
    const glm::vec3 n(0, 0, 1), t(1, 0, 0);
    p.vertices.push_back(Vertex({0, 0, 0}, n, {0.5f, 0.5f}, t));
    const float ring[8][2] = {{2, 0}, {2, 2}, {0, 2}, {-2, 2}, {-2, 0}, {-2, -2}, {0, -2}, {2, -2}};
    for (const auto& c : ring) {
        p.vertices.push_back(Vertex({c[0], c[1], 0}, n, {c[0] / 4 + 0.5f, c[1] / 4 + 0.5f}, t));
    }
    for (uint32_t i = 0; i < 8; ++i) {
        p.indices.insert(p.indices.end(), {0, 1 + i, 1 + (i + 1) % 8});
    }
    p.has_tangents = true;
    return p;
}

// Bounds, a new id and one camera at `eye` looking at `target`.
void FinishScene(runtime::Scene& scene,
                 const char* camera_name,
                 float yfov,
                 glm::vec3 eye,
                 glm::vec3 target) {
    for (runtime::Mesh& mesh : scene.meshes) {
        ComputeBounds(mesh.primitives[0]);
    }
    scene.id = runtime::NewSceneId();
    runtime::Camera camera;
    camera.name = camera_name;
    camera.yfov = yfov;
    camera.world = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
    scene.cameras.push_back(camera);
}

}  // namespace

runtime::Scene StabilityScene() {
    runtime::Scene scene;
    scene.path = "<kiln stability scene>";
    scene.meshes.push_back({"plane", {FacingPlane()}});
    scene.meshes.push_back(
        {"sphere", {SpherePrimitive(32, 16, kStabilitySphereCentre, kStabilitySphereRadius)}});
    scene.instances.push_back({0, glm::mat4(1.0f), "plane"});
    scene.instances.push_back({1, glm::mat4(1.0f), "sphere"});
    FinishScene(scene, "stability", kStabilityYFov, glm::vec3(0, 0, kStabilityEyeZ), glm::vec3(0));
    return scene;
}

Status DrawHarnessPass(runtime::Renderer& renderer,
                       const runtime::ColorPipeline& color,
                       const runtime::Scene& scene,
                       const runtime::FrameSettings& settings,
                       const CameraSetup& camera,
                       const HarnessPass& draw,
                       runtime::LinearImage& out,
                       std::vector<runtime::tool_access::TargetValues>* targets) {
    ForwardPlan plan;
    plan.list.lights = draw.lights;  // the requests point into it: not resized after this
    const runtime::Light* light =
        draw.pixel_light && !plan.list.lights.empty() ? &plan.list.lights[0] : nullptr;
    std::vector<const runtime::Light*> vertex;
    if (draw.vertex_light && plan.list.lights.size() > 1) {
        vertex.push_back(&plan.list.lights[1]);
    }
    for (const runtime::Instance& inst : scene.instances) {
        plan.draws.push_back({&inst,
                              &scene.meshes[inst.mesh].primitives[0],
                              draw.material,
                              draw.pass,
                              draw.additive,
                              light,
                              vertex,
                              {},
                              draw.keywords,
                              "kiln test"});
        plan.draws.back().mirrored_view = draw.mirrored;
    }
    plan.objects = uint32_t(scene.instances.size());
    plan.list.materials.push_back(draw.material);
    return runtime::tool_access::DrawForwardPlan(renderer, color, scene, settings, camera, plan,
                                                 out, targets);
}

runtime::Scene HarnessScene() {
    runtime::Scene scene;
    scene.path = "<kiln test harness>";
    scene.meshes.push_back({"sphere", {SpherePrimitive(32, 16, kTarget, kHarnessSphereRadius)}});
    scene.meshes.push_back({"plane", {FloorPrimitive(kHarnessPlaneHalf)}});
    scene.instances.push_back({0, glm::mat4(1.0f), "sphere"});
    scene.instances.push_back({1, glm::mat4(1.0f), "plane"});
    FinishScene(scene, "harness", 0.6f, kEye, kTarget);
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

}  // namespace kiln::tools
