#include "render/shadow_plan.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include "kiln/pack/engine_names.h"

namespace kiln::runtime {
namespace {

// Depth bias in shadow-map texels (world units: texels x the texel's world size at the scene):
// enough for the 2x2 comparison filter's footprint and a surface's slope within a texel.
constexpr float kBiasTexels = 2.0f;

std::vector<float> Flat(const glm::mat4& m) {
    const float* p = glm::value_ptr(m);
    return std::vector<float>(p, p + 16);
}

// Clip space (x, y in -1..1, +y the top row: the viewport flips it) to the map's texture
// coordinates (u, v in 0..1, v = 0 the top row); depth unchanged.
glm::mat4 ClipToTexture() {
    glm::mat4 m(1.0f);
    m[0][0] = 0.5f;
    m[1][1] = -0.5f;
    m[3][0] = 0.5f;
    m[3][1] = 0.5f;
    return m;
}

// A view looking along `dir` from `eye`, with any up vector not parallel to it.
glm::mat4 LookAlong(const glm::vec3& eye, const glm::vec3& dir) {
    const glm::vec3 up = std::abs(dir.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    return glm::lookAtRH(eye, eye + dir, up);
}

// The six faces' views as Vulkan samples a cube (the face's major axis down -z, its s and t
// along view x and -y, since the viewport flips y): rows (s, -t, -major) of each face.
glm::mat4 CubeFaceView(int face, const glm::vec3& eye) {
    static const glm::vec3 kRows[6][3] = {
        {{0, 0, -1}, {0, 1, 0}, {-1, 0, 0}},  // +X: s = -z, t = -y
        {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}},    // -X: s = +z, t = -y
        {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},  // +Y: s = +x, t = +z
        {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},    // -Y: s = +x, t = -z
        {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}},   // +Z: s = +x, t = -y
        {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   // -Z: s = -x, t = -y
    };
    glm::mat4 v(1.0f);
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            v[c][r] = kRows[face][r][c];
        }
        v[3][r] = -glm::dot(kRows[face][r], eye);
    }
    return v;
}

// The farthest corner of the bounds from `p`.
float FarthestCorner(const std::pair<glm::vec3, glm::vec3>& b, const glm::vec3& p) {
    float far = 0;
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 c((k & 1) ? b.second.x : b.first.x, (k & 2) ? b.second.y : b.first.y,
                          (k & 4) ? b.second.z : b.first.z);
        far = std::max(far, glm::length(c - p));
    }
    return far;
}

}  // namespace

uint32_t ShadowMapSize(const FrameSettings& settings, const Light& light) {
    const uint32_t resolution = std::clamp(settings.shadow_resolution, 16u, 8192u);
    return light.type == LightType::kPoint ? std::max(resolution / 2, 16u) : resolution;
}

const char* ReceiverKeyword(const Light& light) {
    return light.type == LightType::kPoint  ? pack::kKeywordShadowsCube
           : light.type == LightType::kSpot ? pack::kKeywordShadowsDepth
                                            : pack::kKeywordShadowsScreen;
}

LightShadow ShadowOf(const Light& light,
                     const std::pair<glm::vec3, glm::vec3>& bounds,
                     uint32_t resolution) {
    LightShadow out;
    out.light = &light;
    const float res = float(std::max(resolution, 1u));
    const glm::vec3 center = (bounds.first + bounds.second) * 0.5f;
    // guard: a scene of one point still needs a non-empty volume
    const float radius = std::max(glm::length(bounds.second - bounds.first) * 0.5f, 1e-3f);
    glm::vec4 bias(0.0f);  // unity_LightShadowBias: depth (clip), pancaking, normal (world)
    glm::vec4 projection_params(0.0f, 0.0f, 0.0f, 1.0f);
    if (light.type == LightType::kDirectional) {
        // Orthographic around the bounds' sphere, from outside it: depth 0 at the sphere's near
        // side, 1 at its far side; casters nearer than that are clamped onto it (pancaking).
        const glm::vec3 dir = glm::normalize(light.direction);
        const float near = radius, far = 3 * radius;
        const glm::mat4 view = LookAlong(center - dir * (2 * radius), dir);
        const glm::mat4 proj = glm::orthoRH_ZO(-radius, radius, -radius, radius, near, far);
        out.view_projection = {proj * view};
        out.depth_bias = kBiasTexels * 2 * radius / res;
        bias = glm::vec4(out.depth_bias / (far - near), 1.0f, out.depth_bias, 0.0f);
    } else {
        // Perspective from the light as far as its range or the scene's farthest corner.
        const float far =
            light.range > 0 ? light.range : std::max(FarthestCorner(bounds, light.position), 1e-2f);
        const float near = std::max(far / 1000.0f, 1e-3f);
        const float d = std::max(glm::length(center - light.position), near);
        float fov = glm::radians(90.0f);
        if (light.type == LightType::kSpot) {
            // The cone and a margin of a few texels for the filters, at most 170 degrees.
            fov = std::min(2 * light.outer_cone * 1.02f + 8 / res, glm::radians(170.0f));
            out.view_projection = {glm::perspectiveRH_ZO(fov, 1.0f, near, far) *
                                   LookAlong(light.position, glm::normalize(light.direction))};
        } else {
            const glm::mat4 proj = glm::perspectiveRH_ZO(fov, 1.0f, near, far);
            for (int face = 0; face < 6; ++face) {
                out.view_projection.push_back(proj * CubeFaceView(face, light.position));
            }
        }
        // A texel's world size at the scene's centre; the clip-space depth bias b moves every
        // caster by the same world distance: perspective depth is z = f/(f-n) - f n/((f-n) w)
        // and the shader adds b / w to clip z, b / w^2 to z.
        out.depth_bias = kBiasTexels * 2 * d * std::tan(fov / 2) / res;
        const float b = far * near * out.depth_bias / (far - near);
        bias = glm::vec4(light.type == LightType::kPoint ? 0.0f : b, 0.0f, out.depth_bias, 0.0f);
        projection_params =
            glm::vec4(-far / (far - near), -far * near / (far - near), out.depth_bias, 1.0f);
    }
    for (const glm::mat4& vp : out.view_projection) {
        Values v;
        v["unity_MatrixVP"] = Flat(vp);
        v["unity_LightShadowBias"] = {bias.x, bias.y, bias.z, bias.w};
        out.caster.push_back(std::move(v));
    }
    std::vector<float> world_to_shadow(64, 0.0f);
    const glm::mat4 first = ClipToTexture() * out.view_projection[0];
    std::copy_n(glm::value_ptr(first), 16, world_to_shadow.begin());
    out.receiver["unity_WorldToShadow"] = std::move(world_to_shadow);
    // Full strength, no fade with distance (the map covers the whole scene).
    out.receiver[pack::kGlobalLightShadowData] = {0, 0, 0, 0};
    out.receiver["unity_ShadowFadeCenterAndType"] = {0, 0, 0, 0};
    out.receiver[pack::kGlobalLightProjectionParams] = {projection_params.x, projection_params.y,
                                                        projection_params.z, projection_params.w};
    out.receiver[std::string(pack::kTextureShadowMap) + "_TexelSize"] = {1 / res, 1 / res, res,
                                                                         res};
    return out;
}

Status PlanShadows(const std::vector<const pack::Pack*>& packs,
                   const Scene& scene,
                   const FrameSettings& settings,
                   const ColorPipeline& color,
                   const DrawList& list,
                   const std::vector<DrawRequest*>& receivers,
                   ShadowPlan& out,
                   DiagnosticList& warnings) {
    const bool soft = settings.shadows == Shadows::kSoft;
    for (const DrawItem& item : list.items) {
        const MaterialInstance& m = *item.material;
        const ShaderPasses passes = PassesOf(*packs[m.pack], m.shader);
        if (m.transparent || !passes.shadow_caster) {
            continue;
        }
        DrawRequest r = ObjectRequest(item, *passes.shadow_caster);
        r.keywords.emplace_back(pack::kKeywordShadowsDepth);
        r.reason = Requester(scene, item) + "shadow caster";
        out.casters.push_back(r);
        r.keywords.back() = pack::kKeywordShadowsCube;
        r.reason += " (point light)";
        out.cube_casters.push_back(std::move(r));
    }
    if (out.casters.empty()) {
        WarnOnce(warnings, scene, DiagCode::kRenderWarning,
                 "no opaque object's shader has a ShadowCaster pass: nothing casts a shadow");
        return {};
    }
    bool point = false, directional = false;
    for (DrawRequest* r : receivers) {
        if (!r->light) {
            continue;
        }
        if (std::find(out.lights.begin(), out.lights.end(), r->light) == out.lights.end()) {
            out.lights.push_back(r->light);
        }
        r->keywords.emplace_back(ReceiverKeyword(*r->light));
        if (soft && r->light->type != LightType::kDirectional) {
            r->keywords.emplace_back(pack::kKeywordShadowsSoft);
        }
        point |= r->light->type == LightType::kPoint;
        directional |= r->light->type == LightType::kDirectional;
    }
    if (!point) {
        out.cube_casters.clear();
    }
    if (!directional) {
        return {};
    }
    for (uint32_t p = 0; p < packs.size(); ++p) {
        const std::optional<uint32_t> shader =
            packs[p]->FindShader(pack::kShaderScreenSpaceShadows);
        if (!shader || packs[p]->Shader(*shader).value().pass_count == 0) {
            continue;
        }
        MaterialInstance& collector = out.collector.emplace();
        InstanceFromDefaults(*packs[p], p, *shader, color, collector);
        collector.name =
            std::string("the screen-space shadows (") + pack::kShaderScreenSpaceShadows + ")";
        DrawRequest& r = out.collect.emplace();
        r.material = &collector;
        r.pass = packs[p]->Shader(*shader).value().first_pass;
        if (soft) {
            r.keywords.emplace_back(pack::kKeywordShadowsSoft);
        }
        r.reason = "screen-space shadows";
        return {};
    }
    return Error{DiagCode::kRenderFailed,
                 std::string("shadows of directional lights need shader '") +
                     pack::kShaderScreenSpaceShadows +
                     "', which is in none of the loaded packs (add the shipped materials.kpack, "
                     "built from materials/internal/ScreenSpaceShadows.shader)"};
}

void ShadowRequests(const ShadowPlan& plan, std::vector<const DrawRequest*>& out) {
    if (plan.lights.empty()) {
        return;  // no shadow pass
    }
    for (const auto* casters : {&plan.casters, &plan.cube_casters}) {
        for (const DrawRequest& r : *casters) {
            out.push_back(&r);
        }
    }
    if (plan.collect) {
        out.push_back(&*plan.collect);
    }
}

}  // namespace kiln::runtime
