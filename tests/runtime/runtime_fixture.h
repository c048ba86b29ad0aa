// Shared set-up of the runtime tests: a renderer on the default device (lavapipe without a GPU)
// with the validation layer on, the shipped and test packs, and scenes built in code.
#ifndef KILN_TESTS_RUNTIME_RUNTIME_FIXTURE_H_
#define KILN_TESTS_RUNTIME_RUNTIME_FIXTURE_H_

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "runtime/runtime_asserts.h"

namespace kiln::test {

// IEC 61966-2-1 decoding, written out independently of OpenColorIO.
inline double SrgbToLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
inline double LinearToSrgb(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// A UV sphere (counter-clockwise from outside) and a square floor facing +y.
inline runtime::Primitive SpherePrimitive(float radius, int segments, int rings) {
    runtime::Primitive p;
    for (int r = 0; r <= rings; ++r) {
        const float theta = float(M_PI) * float(r) / float(rings);
        for (int s = 0; s <= segments; ++s) {
            const float phi = 2 * float(M_PI) * float(s) / float(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              -std::sin(theta) * std::sin(phi));
            runtime::MeshVertex v{};
            for (int k = 0; k < 3; ++k) {
                v.position[k] = n[k] * radius;
                v.normal[k] = n[k];
            }
            v.uv0[0] = float(s) / float(segments);
            v.uv0[1] = float(r) / float(rings);
            v.tangent[0] = v.tangent[3] = 1;
            v.color[0] = v.color[1] = v.color[2] = v.color[3] = 1;
            p.vertices.push_back(v);
        }
    }
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = uint32_t(r * (segments + 1) + s), b = a + uint32_t(segments) + 1;
            p.indices.insert(p.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    }
    p.material = 0;
    return p;
}

inline runtime::Primitive FloorPrimitive(float half) {
    runtime::Primitive p;
    const float xz[4][2] = {{-half, -half}, {-half, half}, {half, half}, {half, -half}};
    for (const auto& c : xz) {
        runtime::MeshVertex v{};
        v.position[0] = c[0];
        v.position[2] = c[1];
        v.normal[1] = 1;
        v.tangent[0] = v.tangent[3] = 1;
        v.color[0] = v.color[1] = v.color[2] = v.color[3] = 1;
        p.vertices.push_back(v);
    }
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = 0;
    return p;
}

// A sphere of radius 1 resting on a 6 m floor, one material "m" for both, a camera looking at
// it; the caller adds lights and assigns the material file.
inline runtime::Scene SphereOnFloor(const std::string& material_file) {
    runtime::Scene scene;
    runtime::Mesh sphere, floor;
    sphere.primitives.push_back(SpherePrimitive(1.0f, 96, 48));
    floor.primitives.push_back(FloorPrimitive(3.0f));
    scene.meshes = {sphere, floor};
    runtime::SceneMaterial m;
    m.name = "m";
    scene.materials.push_back(m);
    scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 0)), "sphere"});
    scene.instances.push_back({1, glm::mat4(1.0f), "floor"});
    runtime::Camera cam;
    cam.name = "test";
    cam.yfov = 0.8f;
    cam.znear = 0.1f;
    cam.zfar = 50.0f;
    cam.world = glm::inverse(
        glm::lookAtRH(glm::vec3(0.5f, 2.8f, 5.0f), glm::vec3(0, 0.7f, 0), glm::vec3(0, 1, 0)));
    scene.cameras.push_back(cam);
    scene.ambient = glm::vec3(0.05f, 0.06f, 0.08f);
    scene.material_files["m"] = material_file;
    return scene;
}

// Keeps the Vulkan driver and layer mapped after the loader closes them, so that LeakSanitizer
// can name them in stacks (tests/runtime/lsan.supp suppresses Mesa's process-lifetime
// allocations by module). Harmless outside sanitizer builds; a missing library is ignored.
inline void PinVulkanLibraries() {
    static const bool pinned = [] {
        for (const char* lib :
             {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so", "libLLVM-15.so.1"}) {
            dlopen(lib, RTLD_NOW | RTLD_NODELETE);
        }
        return true;
    }();
    (void)pinned;
}

class RuntimeTest : public ::testing::Test {
  protected:
    void SetUp() override {
        PinVulkanLibraries();
        runtime::RendererOptions options;
        options.validation = true;
        options.float32_target = true;
        ASSERT_TRUE(CreateInto(options, renderer_)) << "no Vulkan device";
        for (const char* pack : {KILN_MATERIALS_PACK, KILN_PROBE_PACK}) {
            Status e = renderer_.AddPack(pack);
            ASSERT_TRUE(Ok(e));
        }
        ASSERT_TRUE(CreateColorInto({}, color_));
    }
    void TearDown() override {
        // Every test fails on any message from VK_LAYER_KHRONOS_validation.
        for (const std::string& m : renderer_.ValidationMessages()) {
            ADD_FAILURE() << "validation: " << m;
        }
    }

    runtime::LinearImage Render(const runtime::Scene& scene,
                                runtime::FrameSettings settings = {},
                                runtime::FrameStats* stats_out = nullptr) {
        runtime::LinearImage image;
        runtime::FrameStats stats;
        Status e = renderer_.Render(scene, settings, color_, image, stats);
        EXPECT_TRUE(Ok(e));
        if (stats_out) {
            *stats_out = stats;
        }
        return image;
    }

    // KILN_TEST_IMAGES=<folder>: keeps `image` as <test>-<n>.png there, to look at.
    void KeepImage(const runtime::LinearImage& image) {
        if (const char* dir = std::getenv("KILN_TEST_IMAGES")) {
            static int n = 0;
            const std::string name =
                ::testing::UnitTest::GetInstance()->current_test_info()->name();
            EXPECT_TRUE(Ok(runtime::WriteDisplayPng(
                std::string(dir) + "/" + name + "-" + std::to_string(n++) + ".png", image,
                color_)));
        }
    }

    runtime::Renderer renderer_;
    runtime::ColorPipeline color_;
};

}  // namespace kiln::test

#endif  // KILN_TESTS_RUNTIME_RUNTIME_FIXTURE_H_
