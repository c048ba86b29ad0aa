#include "kiln/tools/scaling.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "harness/harness_scene.h"

namespace kiln::tools {
namespace {

// splitmix64: a fixed, portable sequence (std::uniform_*_distribution differ between libraries).
struct Sequence {
    uint64_t state;
    double Next() {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return double((z ^ (z >> 31)) >> 11) / double(uint64_t{1} << 53);  // [0, 1)
    }
};

constexpr float kSpacing = 2.0f, kRadius = 0.5f, kRange = 3.0f;

// The draws of a frame: every pass's.
uint32_t Draws(const runtime::FrameStats& s) {
    return s.base_passes + s.add_passes + s.gbuffer_draws + s.light_passes + s.shadow_draws;
}

}  // namespace

runtime::Scene ScalingScene(uint32_t objects, uint32_t lights, uint64_t seed) {
    runtime::Scene scene;
    scene.path = "<scaling scene: " + std::to_string(objects) + " spheres, " +
                 std::to_string(lights) + " lights>";
    const uint32_t columns = std::max(1u, uint32_t(std::ceil(std::sqrt(double(objects)))));
    const uint32_t rows = std::max(1u, (objects + columns - 1) / columns);
    const float width = float(columns) * kSpacing, depth = float(rows) * kSpacing;
    scene.meshes.push_back({"sphere", {SpherePrimitive(16, 8, glm::vec3(0.0f), kRadius)}});
    scene.meshes.push_back({"floor", {FloorPrimitive(0.5f)}});
    for (runtime::Mesh& m : scene.meshes) {
        runtime::ComputeBounds(m.primitives[0]);
    }
    scene.materials.push_back(runtime::SceneMaterial{});
    scene.materials.back().name = "grey";
    scene.materials.back().base_color = glm::vec4(0.7f, 0.7f, 0.7f, 1.0f);
    scene.materials.back().metallic = 0;
    scene.materials.back().roughness = 0.5f;
    for (runtime::Mesh& m : scene.meshes) {
        m.primitives[0].material = 0;
    }
    // Row-major from the far left corner; the grid is centred on the origin.
    for (uint32_t i = 0; i < objects; ++i) {
        const float x = (float(i % columns) + 0.5f) * kSpacing - width / 2;
        const float z = (float(i / columns) + 0.5f) * kSpacing - depth / 2;
        scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(x, kRadius, z)),
                                   "sphere " + std::to_string(i)});
    }
    scene.instances.push_back(
        {1, glm::scale(glm::mat4(1.0f), glm::vec3(width + 2, 1, depth + 2)), "floor"});
    Sequence random{seed};
    for (uint32_t i = 0; i < lights; ++i) {
        runtime::Light l;
        l.name = "light " + std::to_string(i);
        l.type = runtime::LightType::kPoint;
        l.position =
            glm::vec3((float(random.Next()) - 0.5f) * width, 0.8f + 1.6f * float(random.Next()),
                      (float(random.Next()) - 0.5f) * depth);
        l.color = glm::vec3(0.5f) + 0.5f * glm::vec3(float(random.Next()), float(random.Next()),
                                                     float(random.Next()));
        l.intensity = 3;
        l.range = kRange;
        l.importance = runtime::LightImportance::kImportant;  // always per pixel, as the lecture
        scene.lights.push_back(l);
    }
    scene.ambient = glm::vec3(0.03f);
    scene.ambient_given = true;
    runtime::Camera camera;
    camera.name = "scaling";
    camera.yfov = 0.9f;
    camera.znear = 0.1f;
    const float extent = std::max(width, depth);
    const glm::vec3 eye(0.0f, 0.45f * extent + 2, 0.75f * extent + 2);
    camera.world =
        glm::inverse(glm::lookAt(eye, glm::vec3(0, 0, -0.1f * extent), glm::vec3(0, 1, 0)));
    scene.cameras.push_back(camera);
    scene.id = runtime::NewSceneId();
    return scene;
}

Result<ScalingReport> RunScalingReport(runtime::Renderer& renderer,
                                       const runtime::ColorPipeline& color,
                                       const ScalingOptions& options) {
    if (options.width == 0 || options.height == 0 || options.width > 16384 ||
        options.height > 16384 || options.objects.empty() || options.lights.empty()) {
        return Error{DiagCode::kBadCommandLine,
                     "the scaling sweep needs object and light counts and an image size"};
    }
    ScalingReport report;
    report.device = renderer.DeviceName();
    report.width = options.width;
    report.height = options.height;
    report.frames = std::max(options.frames, 1u);
    report.warmup = options.warmup;
    using Clock = std::chrono::steady_clock;
    for (uint32_t objects : options.objects) {
        for (uint32_t lights : options.lights) {
            const runtime::Scene scene = ScalingScene(objects, lights);
            runtime::FrameSettings settings[2];
            for (int p = 0; p < 2; ++p) {
                settings[p].width = options.width;
                settings[p].height = options.height;
                settings[p].path =
                    p ? runtime::RenderPath::kDeferred : runtime::RenderPath::kForward;
                settings[p].light_mode = runtime::LightMode::kPixel;
                settings[p].pixel_lights = lights;
            }
            ScalingRow row[2];
            std::vector<double> gpu[2], cpu[2];
            runtime::LinearImage image;
            for (uint32_t round = 0; round < 1 + options.warmup + report.frames; ++round) {
                for (int p = 0; p < 2; ++p) {
                    runtime::FrameStats stats;
                    const Clock::time_point start = Clock::now();
                    if (Status e = renderer.Render(scene, settings[p], color, image, stats);
                        !e.ok()) {
                        return e.error();
                    }
                    if (round == 0) {
                        row[p].first_frame_ms =
                            std::chrono::duration<double, std::milli>(Clock::now() - start).count();
                        row[p].draws = Draws(stats);
                    } else if (round > options.warmup) {
                        cpu[p].push_back(stats.cpu_ms);
                        if (stats.gpu_ms >= 0) {
                            gpu[p].push_back(stats.gpu_ms);
                        }
                    }
                }
            }
            for (int p = 0; p < 2; ++p) {
                row[p].objects = objects;
                row[p].lights = lights;
                row[p].path = p ? "deferred" : "forward";
                row[p].gpu_ms = SpreadOf(gpu[p]);
                row[p].cpu_ms = SpreadOf(cpu[p]);
                report.rows.push_back(row[p]);
            }
        }
    }
    return report;
}

std::optional<uint32_t> Crossover(const ScalingReport& report, uint32_t objects) {
    auto time = [](const ScalingRow& r) {
        return r.gpu_ms.median >= 0 ? r.gpu_ms.median : r.cpu_ms.median;
    };
    std::optional<uint32_t> from;
    for (size_t i = 0; i + 1 < report.rows.size(); i += 2) {
        const ScalingRow& forward = report.rows[i];
        const ScalingRow& deferred = report.rows[i + 1];
        if (forward.objects != objects) {
            continue;
        }
        if (time(deferred) < time(forward)) {
            from = from ? from : std::optional(forward.lights);
        } else {
            from.reset();  // forward is faster again: the crossover is later
        }
    }
    return from;
}

}  // namespace kiln::tools
