#include "render/reflection_probe.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

#include "kiln/reference/sh.h"
#include "render/frame_values.h"

namespace kiln::runtime {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Texel (x, y) of an n x n face: its centre's face coordinates.
double Coord(uint32_t i, uint32_t n) {
    return (2.0 * (double(i) + 0.5)) / double(n) - 1.0;
}

// The face and texel a unit direction falls in on an n x n cube (Vulkan's face selection).
void CubeTexelOf(const glm::dvec3& d, uint32_t n, uint32_t& face, uint32_t& x, uint32_t& y) {
    const glm::dvec3 a = glm::abs(d);
    double sc, tc, ma;
    if (a.x >= a.y && a.x >= a.z) {
        face = d.x >= 0 ? 0 : 1;
        sc = d.x >= 0 ? -d.z : d.z;
        tc = -d.y;
        ma = a.x;
    } else if (a.y >= a.z) {
        face = d.y >= 0 ? 2 : 3;
        sc = d.x;
        tc = d.y >= 0 ? d.z : -d.z;
        ma = a.y;
    } else {
        face = d.z >= 0 ? 4 : 5;
        sc = d.z >= 0 ? d.x : -d.x;
        tc = -d.y;
        ma = a.z;
    }
    auto texel = [&](double c) {
        const double u = (c / ma + 1.0) * 0.5 * double(n);
        return uint32_t(std::clamp(u, 0.0, double(n) - 1.0));
    };
    x = texel(sc);
    y = texel(tc);
}

// The solid angle of a cube texel at face coordinates (a, b) with side 2/n, to first order.
double TexelSolidAngle(double a, double b, uint32_t n) {
    const double side = 2.0 / double(n);
    return side * side / std::pow(1.0 + a * a + b * b, 1.5);
}

// A sky image sampled bilinearly at direction d (the inverse of reference::EquirectDirection).
glm::dvec3 SampleSky(const Sky& sky, const glm::dvec3& d) {
    const double theta = std::acos(std::clamp(d.y, -1.0, 1.0));
    const double phi = std::atan2(d.x, -d.z);  // sin phi = x / sin theta, cos phi = -z / ...
    const double u = (phi + kPi) / (2.0 * kPi) * double(sky.width) - 0.5;
    const double v = theta / kPi * double(sky.height) - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    glm::dvec3 sum(0.0);
    for (int dv = 0; dv < 2; ++dv) {
        for (int du = 0; du < 2; ++du) {
            const double w = (du ? u - fu : 1.0 - (u - fu)) * (dv ? v - fv : 1.0 - (v - fv));
            const int64_t w_ = int64_t(sky.width);
            const uint32_t x = uint32_t(((int64_t(fu) + du) % w_ + w_) % w_);  // wraps around
            const uint32_t y =
                uint32_t(std::clamp<int64_t>(int64_t(fv) + dv, 0, int64_t(sky.height) - 1));
            const float* t = &sky.rgb[(size_t(y) * sky.width + x) * 3];
            sum += w * glm::dvec3(t[0], t[1], t[2]);
        }
    }
    return sum;
}

using Faces = std::vector<glm::vec3>;  // six n x n faces

// Mip 0: a sky's texels binned by direction (each cube texel the solid-angle-weighted mean of
// the sky texels in it; a texel no sky texel falls in samples the sky at its centre); analytic
// ambients at texel centres.
Faces BaseLevel(const Scene& scene, uint32_t n) {
    Faces out(size_t(6) * n * n, glm::vec3(0.0f));
    const Sky* sky = SkyOf(scene);
    std::vector<double> weight(out.size(), 0.0);
    std::vector<glm::dvec3> sum(out.size(), glm::dvec3(0.0));
    if (sky) {
        for (uint32_t v = 0; v < sky->height; ++v) {
            const double omega = reference::EquirectSolidAngle(v, sky->width, sky->height);
            for (uint32_t u = 0; u < sky->width; ++u) {
                uint32_t face, x, y;
                CubeTexelOf(reference::EquirectDirection(u, v, sky->width, sky->height), n, face, x,
                            y);
                const size_t i = (size_t(face) * n + y) * n + x;
                const float* t = &sky->rgb[(size_t(v) * sky->width + u) * 3];
                sum[i] += omega * glm::dvec3(t[0], t[1], t[2]);
                weight[i] += omega;
            }
        }
    }
    for (uint32_t face = 0; face < 6; ++face) {
        for (uint32_t y = 0; y < n; ++y) {
            for (uint32_t x = 0; x < n; ++x) {
                const size_t i = (size_t(face) * n + y) * n + x;
                out[i] = weight[i] > 0
                             ? glm::vec3(sum[i] / weight[i])
                             : glm::vec3(AmbientRadiance(
                                   scene, CubeTexelDirection(face, Coord(x, n), Coord(y, n))));
            }
        }
    }
    return out;
}

// Halves every face (2x2 box).
Faces Downsample(const Faces& in, uint32_t n) {
    const uint32_t h = n / 2;
    Faces out(size_t(6) * h * h);
    for (uint32_t f = 0; f < 6; ++f) {
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < h; ++x) {
                glm::vec3 s(0.0f);
                for (uint32_t k = 0; k < 4; ++k) {
                    s += in[(size_t(f) * n + y * 2 + k / 2) * n + x * 2 + k % 2];
                }
                out[(size_t(f) * h + y) * h + x] = s * 0.25f;
            }
        }
    }
    return out;
}

// One prefiltered level of n x n faces from `source` (m x m faces) with GGX of `alpha`.
Faces Prefilter(const Faces& source, uint32_t m, uint32_t n, double alpha) {
    struct Texel {
        glm::dvec3 dir, radiance;
        double omega;
    };
    std::vector<Texel> src;
    src.reserve(source.size());
    for (uint32_t f = 0; f < 6; ++f) {
        for (uint32_t y = 0; y < m; ++y) {
            for (uint32_t x = 0; x < m; ++x) {
                const double a = Coord(x, m), b = Coord(y, m);
                src.push_back({CubeTexelDirection(f, a, b),
                               glm::dvec3(source[(size_t(f) * m + y) * m + x]),
                               TexelSolidAngle(a, b, m)});
            }
        }
    }
    const double a2 = alpha * alpha;
    Faces out(size_t(6) * n * n);
    for (uint32_t f = 0; f < 6; ++f) {
        for (uint32_t y = 0; y < n; ++y) {
            for (uint32_t x = 0; x < n; ++x) {
                const glm::dvec3 r = CubeTexelDirection(f, Coord(x, n), Coord(y, n));
                glm::dvec3 sum(0.0);
                double total = 0;
                for (const Texel& t : src) {
                    const double nl = glm::dot(r, t.dir);
                    if (nl <= 0) {
                        continue;
                    }
                    // n = v = r: h halves l and r, and n . h = sqrt((1 + n . l) / 2).
                    const double nh2 = (1.0 + nl) * 0.5;
                    const double q = nh2 * (a2 - 1.0) + 1.0;
                    const double w = a2 / (kPi * q * q) * nl * t.omega;
                    sum += w * t.radiance;
                    total += w;
                }
                out[(size_t(f) * n + y) * n + x] = glm::vec3(total > 0 ? sum / total : sum);
            }
        }
    }
    return out;
}

}  // namespace

glm::dvec3 CubeTexelDirection(uint32_t face, double a, double b) {
    glm::dvec3 d;
    switch (face) {
        case 0:
            d = {1.0, -b, -a};
            break;
        case 1:
            d = {-1.0, -b, a};
            break;
        case 2:
            d = {a, 1.0, b};
            break;
        case 3:
            d = {a, -1.0, -b};
            break;
        case 4:
            d = {a, -b, 1.0};
            break;
        default:
            d = {-a, -b, -1.0};
            break;
    }
    return glm::normalize(d);
}

double ProbeMipRoughness(uint32_t mip) {
    const double m = double(mip) / double(kProbeMips - 1);
    return std::clamp(1.7 / 1.4 - std::sqrt(std::max(2.89 / 1.96 - m / 0.7, 0.0)), 0.0, 1.0);
}

glm::dvec3 AmbientRadiance(const Scene& scene, const glm::dvec3& d) {
    if (const Sky* sky = SkyOf(scene)) {
        return SampleSky(*sky, d);
    }
    if (scene.ambient_mode == AmbientMode::kTrilight) {
        return reference::TrilightRadiance(d, glm::dvec3(scene.ambient),
                                           glm::dvec3(scene.ambient_equator),
                                           glm::dvec3(scene.ambient_ground));
    }
    return glm::dvec3(scene.ambient);
}

ReflectionProbe MakeReflectionProbe(const Scene& scene) {
    ReflectionProbe p;
    p.size = kProbeSize;
    p.mips = kProbeMips;
    const Faces base = BaseLevel(scene, kProbeSize);
    // Box-filtered copies of the base: 32, 16 and 8 texels a side.
    std::vector<std::pair<uint32_t, Faces>> box = {{kProbeSize, base}};
    while (box.back().first > 8) {
        const uint32_t n = box.back().first;
        box.push_back({n / 2, Downsample(box.back().second, n)});
    }
    p.texels.push_back(base);
    // Mip 1's lobe (alpha 0.01, about 4 degrees to its 1% edge) is narrower than two of its
    // texels: the 2x2 box of the base is that lobe to within a texel. Each later mip is
    // prefiltered from the box level of twice its resolution (8 to 32 a side), which puts
    // five or more source texels across its lobe.
    p.texels.push_back(box[1].second);
    for (uint32_t mip = 2; mip < kProbeMips; ++mip) {
        const uint32_t n = std::max(1u, kProbeSize >> mip);
        const uint32_t want = std::clamp(n * 2, 8u, 32u);
        const auto& [m, source] =
            *std::find_if(box.begin(), box.end(), [&](const auto& b) { return b.first == want; });
        const double r = ProbeMipRoughness(mip);
        p.texels.push_back(Prefilter(source, m, n, r * r));
    }
    return p;
}

}  // namespace kiln::runtime
