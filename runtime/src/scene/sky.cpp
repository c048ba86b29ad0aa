// Skies for the ambient light (kiln/runtime/scene.h, AmbientMode::kSky): Kiln's procedural sky or
// an equirectangular HDR image, with the values the renderer reads derived once: the SH
// projection (reference::AddEquirect), the mean radiance, and the means over the caps, the
// horizon band and the cube faces, each weighted by the texels' solid angles.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "kiln/reference/sh.h"
#include "kiln/runtime/image.h"
#include "kiln/runtime/scene.h"

namespace kiln::runtime {
namespace {

// The cube face a direction falls in: +x, -x, +y, -y, +z, -z (the largest component).
int FaceOf(const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) {
        return d.x >= 0 ? 0 : 1;
    }
    if (a.y >= a.z) {
        return d.y >= 0 ? 2 : 3;
    }
    return d.z >= 0 ? 4 : 5;
}

}  // namespace

std::shared_ptr<const Sky> MakeSky(std::string name,
                                   uint32_t width,
                                   uint32_t height,
                                   std::vector<float> rgb) {
    auto sky = std::make_shared<Sky>();
    sky->name = std::move(name);
    sky->width = width;
    sky->height = height;
    sky->rgb = std::move(rgb);
    reference::SH9 sh;
    reference::AddEquirect(sh, width, height, sky->rgb.data());
    sky->sh = sh.L;
    glm::dvec3 total(0.0), up(0.0), band(0.0), down(0.0);
    double w_up = 0, w_band = 0, w_down = 0;
    std::array<glm::dvec3, 6> faces{};
    std::array<double, 6> w_faces{};
    for (uint32_t v = 0; v < height; ++v) {
        const double omega = reference::EquirectSolidAngle(v, width, height);
        for (uint32_t u = 0; u < width; ++u) {
            const float* t = sky->rgb.data() + (size_t(v) * width + u) * 3;
            const glm::dvec3 l = glm::dvec3(t[0], t[1], t[2]) * omega;
            const glm::dvec3 d = reference::EquirectDirection(u, v, width, height);
            total += l;
            if (d.y > 0.5) {
                up += l;
                w_up += omega;
            } else if (d.y < -0.5) {
                down += l;
                w_down += omega;
            } else {
                band += l;
                w_band += omega;
            }
            const int f = FaceOf(d);
            faces[size_t(f)] += l;
            w_faces[size_t(f)] += omega;
        }
    }
    auto mean = [](const glm::dvec3& sum, double w) {
        return w > 0 ? glm::vec3(sum / w) : glm::vec3(0.0f);
    };
    sky->mean = mean(total, 4.0 * M_PI);
    sky->up = mean(up, w_up);
    sky->horizon = mean(band, w_band);
    sky->down = mean(down, w_down);
    for (size_t f = 0; f < 6; ++f) {
        sky->faces[f] = mean(faces[f], w_faces[f]);
    }
    return sky;
}

std::shared_ptr<const Sky> ProceduralSky(const glm::vec3& zenith,
                                         const glm::vec3& horizon,
                                         const glm::vec3& ground) {
    constexpr uint32_t kWidth = 256, kHeight = 128;
    std::vector<float> rgb(size_t{kWidth} * kHeight * 3);
    for (uint32_t v = 0; v < kHeight; ++v) {
        for (uint32_t u = 0; u < kWidth; ++u) {
            const double y = reference::EquirectDirection(u, v, kWidth, kHeight).y;
            const glm::vec3 c = y >= 0 ? glm::mix(horizon, zenith, float(std::sqrt(y)))
                                       : glm::mix(horizon, ground, float(std::sqrt(-y)));
            float* t = rgb.data() + (size_t(v) * kWidth + u) * 3;
            t[0] = c.r;
            t[1] = c.g;
            t[2] = c.b;
        }
    }
    return MakeSky("procedural", kWidth, kHeight, std::move(rgb));
}

Result<std::shared_ptr<const Sky>> LoadSky(const std::string& path, float scale) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return Error{DiagCode::kBadScene, path + ": no such sky image"};
    if (!(scale >= 0) || !std::isfinite(scale)) {
        return Error{DiagCode::kBadScene, path + ": the sky's scale must be a finite number >= 0"};
    }
    Result<LinearRgbImage> image = ReadImageLinearRgb(path);
    if (!image) {
        std::string why = image.error().message;
        if (const std::string named = "'" + path + "': "; why.rfind(named, 0) == 0)
            why.erase(0, named.size());
        return Error{DiagCode::kBadImage, path + ": cannot read the sky image: " + why};
    }
    LinearRgbImage& sky = image.value();
    if (sky.width < 2 || sky.height < 1 || sky.width > 16384 || sky.height > 8192) {
        return Error{DiagCode::kBadScene, path +
                                              ": a sky image must be between 2x1 and 16384x8192 "
                                              "texels (it is " +
                                              std::to_string(sky.width) + "x" +
                                              std::to_string(sky.height) + ")"};
    }
    for (float& c : sky.rgb) {
        // Non-finite or negative radiance (a damaged file) would poison every derived value.
        c = std::isfinite(c) ? std::max(c, 0.0f) * scale : 0.0f;
    }
    return MakeSky(path, sky.width, sky.height, std::move(sky.rgb));
}

}  // namespace kiln::runtime
