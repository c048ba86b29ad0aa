// Frames that allocate nothing after the first (render/frame_cache.h): a frame of a shape drawn
// before (one path at one size, with its shadows and samples) creates no Vulkan object, and
// draws exactly what its first frame drew; the last four shapes are kept, so configurations
// interleaved as kiln report interleaves them allocate nothing either; a fifth shape gives back
// the least recently used one.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <vector>

#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

runtime::Scene ShadowedScene() {
    runtime::Scene scene = SphereOnFloor(RuntimeData("deferred_metallic.material"));
    scene.id = runtime::NewSceneId();  // its buffers and images stay uploaded between frames
    runtime::Light sun;
    sun.type = runtime::LightType::kDirectional;
    sun.intensity = 2;
    sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    runtime::Light lamp;
    lamp.type = runtime::LightType::kPoint;
    lamp.position = glm::vec3(1.5f, 1.2f, 1.5f);
    lamp.intensity = 6;
    lamp.range = 4;
    scene.lights = {sun, lamp};
    return scene;
}

struct Config {
    const char* name;
    runtime::FrameSettings settings;
};

std::vector<Config> Configs() {
    runtime::FrameSettings base;
    base.width = 96;
    base.height = 64;
    base.shadow_resolution = 256;
    std::vector<Config> out;
    runtime::FrameSettings s = base;
    out.push_back({"forward", s});
    s.path = runtime::RenderPath::kDeferred;
    out.push_back({"deferred", s});
    s = base;
    s.shadows = runtime::Shadows::kSoft;
    s.msaa = 4;
    out.push_back({"forward, soft shadows, 4x MSAA", s});
    s = base;
    s.path = runtime::RenderPath::kDeferred;
    s.shadows = runtime::Shadows::kHard;
    out.push_back({"deferred, shadows", s});
    return out;
}

TEST_F(RuntimeTest, SteadyStateFramesCreateNoVulkanObject) {
    const runtime::Scene scene = ShadowedScene();
    const std::vector<Config> configs = Configs();
    std::vector<runtime::LinearImage> first;
    for (const Config& c : configs) {
        runtime::FrameStats a, b, d;
        first.push_back(Render(scene, c.settings, &a));
        EXPECT_GT(a.allocations, 0u) << c.name;  // its shape's targets, at least
        const runtime::LinearImage second = Render(scene, c.settings, &b);
        Render(scene, c.settings, &d);
        EXPECT_EQ(b.allocations, 0u) << c.name;
        EXPECT_EQ(d.allocations, 0u) << c.name;
        EXPECT_EQ(second.rgba, first.back().rgba) << c.name;
        EXPECT_GT(b.cpu_ms, 0.0) << c.name;
    }
    // Interleaved, A B C D A B C D: every shape is kept.
    for (int round = 0; round < 2; ++round) {
        for (size_t i = 0; i < configs.size(); ++i) {
            runtime::FrameStats stats;
            const runtime::LinearImage image = Render(scene, configs[i].settings, &stats);
            EXPECT_EQ(stats.allocations, 0u) << configs[i].name;
            EXPECT_EQ(image.rgba, first[i].rgba) << configs[i].name;
        }
    }
    // A fifth shape: its targets are made, and the least recently used shape's are given back.
    runtime::FrameSettings larger = configs[0].settings;
    larger.width = 128;
    runtime::FrameStats fifth, again;
    Render(scene, larger, &fifth);
    EXPECT_GT(fifth.allocations, 0u);
    Render(scene, configs[0].settings, &again);  // the least recently used: made again
    EXPECT_GT(again.allocations, 0u);
}

}  // namespace
}  // namespace kiln::test
