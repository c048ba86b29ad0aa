#include "harness/shadow_map_check.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "harness/variant_harness.h"

namespace kiln::tools {
namespace {

enum class Cover { kIn, kOut, kEdge };

// A ray against the harness's scene: covered, missed, or too near an outline to judge; for a
// clear hit, where (the ray's parameter) and the surface's normal, unless the sphere's outline
// passes in front of the plane there.
struct Trace {
    Cover cover = Cover::kOut;
    bool depth_known = false;
    float t = 0;
    glm::vec3 normal{0.0f};
};

Trace TraceScene(const glm::vec3& o, const glm::vec3& d, float tmax, float margin) {
    const float inf = std::numeric_limits<float>::infinity();
    // The sphere: the ray's closest approach to its centre.
    const glm::vec3 oc = kHarnessSphereCentre - o;
    const float tc = glm::dot(oc, d);
    const float dist2 = std::max(glm::dot(oc, oc) - tc * tc, 0.0f);
    const float dist = std::sqrt(dist2), r = kHarnessSphereRadius;
    Cover sphere = Cover::kOut;
    float ts = inf;
    if (tc > 0 && dist < r - margin) {
        sphere = Cover::kIn;
        ts = tc - std::sqrt(r * r - dist2);
    } else if (tc > 0 && dist <= r + margin) {
        sphere = Cover::kEdge;
    }
    // The plane y = 0, |x|, |z| <= kHarnessPlaneHalf, seen from above.
    Cover plane = Cover::kOut;
    float tp = inf;
    if (o.y > 0 && d.y < 0) {
        tp = -o.y / d.y;
        const glm::vec3 p = o + d * tp;
        const float e = std::max(std::abs(p.x), std::abs(p.z));
        if (tp <= tmax && e < kHarnessPlaneHalf - margin) {
            plane = Cover::kIn;
        } else if (tp <= tmax + margin && e <= kHarnessPlaneHalf + margin) {
            plane = Cover::kEdge;
        }
    }
    Trace out;
    if (sphere == Cover::kIn) {  // above the plane: hit before it
        out.cover = Cover::kIn;
        out.depth_known = true;
        out.t = ts;
        out.normal = glm::normalize(o + d * ts - kHarnessSphereCentre);
    } else if (plane == Cover::kIn) {
        out.cover = Cover::kIn;
        out.depth_known = sphere == Cover::kOut;
        out.t = tp;
        out.normal = glm::vec3(0, 1, 0);
    } else if (sphere == Cover::kEdge || plane == Cover::kEdge) {
        out.cover = Cover::kEdge;
    }
    return out;
}

glm::vec3 Unproject(const glm::mat4& inverse, float x, float y, float z) {
    const glm::vec4 p = inverse * glm::vec4(x, y, z, 1);
    return glm::vec3(p) / p.w;
}

// Texels within `radius` of a texel of the other value in `covered` (w x h): near the outline.
std::vector<uint8_t> NearOutline(const std::vector<uint8_t>& covered,
                                 uint32_t w,
                                 uint32_t h,
                                 int radius) {
    // The window's minimum and maximum, separably: rows, then columns.
    std::vector<uint8_t> lo(covered.size()), hi(covered.size());
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            uint8_t a = 1, b = 0;
            for (int d = -radius; d <= radius; ++d) {
                const int64_t xx = std::clamp<int64_t>(int64_t(x) + d, 0, w - 1);
                a = std::min(a, covered[size_t(y) * w + size_t(xx)]);
                b = std::max(b, covered[size_t(y) * w + size_t(xx)]);
            }
            lo[size_t(y) * w + x] = a;
            hi[size_t(y) * w + x] = b;
        }
    }
    std::vector<uint8_t> out(covered.size());
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            uint8_t a = 1, b = 0;
            for (int d = -radius; d <= radius; ++d) {
                const int64_t yy = std::clamp<int64_t>(int64_t(y) + d, 0, h - 1);
                a = std::min(a, lo[size_t(yy) * w + x]);
                b = std::max(b, hi[size_t(yy) * w + x]);
            }
            out[size_t(y) * w + x] = a != b;
        }
    }
    return out;
}

std::string Texel(size_t i, uint32_t width) {
    return std::to_string(i % width) + ", " + std::to_string(i / width);
}

}  // namespace

ShadowMapCheck CheckShadowMap(const runtime::tool_access::TargetValues& map,
                              const glm::mat4& view_projection,
                              float depth_bias,
                              const ShadowReference* reference) {
    ShadowMapCheck out;
    const glm::mat4 inverse = glm::inverse(view_projection);
    const float margin = 4 * depth_bias, tolerance = 5 * depth_bias + 0.02f;
    if (reference && (reference->covered.size() != map.values.size() ||
                      reference->depth.size() != map.values.size())) {
        reference = nullptr;
    }
    const std::vector<uint8_t> outline =
        reference ? NearOutline(reference->covered, map.width, map.height, 8)
                  : std::vector<uint8_t>();
    size_t missing = 0, extra = 0, wrong = 0, first_coverage = 0, first_depth = 0;
    float worst = 0;
    for (size_t i = 0; i < map.values.size(); ++i) {
        const uint32_t x = uint32_t(i % map.width), y = uint32_t(i / map.width);
        // Texel centres in clip space: +y is the top row (the viewport is flipped).
        const float cx = 2 * (float(x) + 0.5f) / float(map.width) - 1;
        const float cy = 1 - 2 * (float(y) + 0.5f) / float(map.height);
        const glm::vec3 near = Unproject(inverse, cx, cy, 0), far = Unproject(inverse, cx, cy, 1);
        const glm::vec3 d = glm::normalize(far - near);
        const Trace hit = TraceScene(near, d, glm::length(far - near), margin);
        const float z = map.values[i];
        const bool covered = z < 1.0f;
        out.covered += covered;
        const bool judged = reference ? !outline[i] : hit.cover != Cover::kEdge;
        const bool expected = reference ? reference->covered[i] != 0 : hit.cover == Cover::kIn;
        if (!judged) {
            continue;
        }
        if (covered != expected) {
            first_coverage = missing + extra == 0 ? i : first_coverage;
            (covered ? extra : missing) += 1;
            continue;
        }
        // Surfaces facing the light within 72 degrees (cos 0.3), where the biases are bounded,
        // and where the object is where the traced scene is.
        if (!covered || hit.cover != Cover::kIn || !hit.depth_known ||
            glm::dot(hit.normal, -d) < 0.3f) {
            continue;
        }
        if (reference) {
            const float t = glm::dot(Unproject(inverse, cx, cy, reference->depth[i]) - near, d);
            if (!(std::abs(t - hit.t) <= 0.02f)) {
                continue;
            }
        }
        ++out.checked;
        const float t = glm::dot(Unproject(inverse, cx, cy, z) - near, d);
        const float error = std::abs(t - hit.t);
        if (!(error <= tolerance)) {
            first_depth = wrong == 0 ? i : first_depth;
            ++wrong;
            worst = std::max(worst, std::isfinite(error) ? error : worst);
        }
    }
    const std::string face =
        map.name + (map.layer ? " (face " + std::to_string(map.layer) + ")" : "");
    if (missing + extra > 0) {
        out.coverage = face + ": " + std::to_string(missing) +
                       " texels that see the object hold no depth and " + std::to_string(extra) +
                       " that see nothing hold one (the object as " +
                       (reference ? "its forward pass draws it" : "the traced scene has it") +
                       "; the first at texel " + Texel(first_coverage, map.width) + ")";
    }
    if (wrong > 0) {
        out.depth = face + ": " + std::to_string(wrong) + " of " + std::to_string(out.checked) +
                    " texels' depths do not unproject onto the surface (the first at texel " +
                    Texel(first_depth, map.width) + "; the largest distance " + Describe(worst) +
                    " against a tolerance of " + Describe(tolerance) + ")";
    }
    return out;
}

}  // namespace kiln::tools
