#include "render/frame_values.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include "kiln/pack/engine_names.h"
#include "kiln/reference/attenuation.h"
#include "kiln/reference/sh.h"

namespace kiln::runtime {
namespace {

std::vector<float> Vec(const glm::vec4& v) {
    return {v.x, v.y, v.z, v.w};
}
std::vector<float> Mat(const glm::mat4& m) {  // column-major, as HLSL's default column_major
    const float* p = glm::value_ptr(m);
    return std::vector<float>(p, p + 16);
}

// Right-handed, depth 0..1, y up in clip space (the viewport flips it).
glm::mat4 Perspective(float yfov, float aspect, float znear, float zfar) {
    if (zfar > znear) {
        return glm::perspectiveRH_ZO(yfov, aspect, znear, zfar);
    }
    const float f = 1.0f / std::tan(yfov / 2);
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[2][2] = -1.0f;
    p[2][3] = -1.0f;
    p[3][2] = -znear;
    return p;
}

// UnityPerCamera's depth and projection helpers and UnityPerCameraRare.
Values CameraValues(const CameraSetup& camera) {
    Values v;
    const glm::mat4& p = camera.projection;
    const bool ortho = p[2][3] == 0.0f;
    const float n = camera.znear;
    // Unity's definitions, also for orthographic cameras (whose shaders test unity_OrthoParams.w).
    if (camera.zfar > 0) {
        // Perspective: z = f (d - n) / (d (f - n)), so 1/d = (1 - f/n)/f * z + (f/n)/f.
        const float f = camera.zfar;
        v[pack::kGlobalZBufferParams] = {1 - f / n, f / n, (1 - f / n) / f, 1 / n};
    } else {
        // Infinite far plane: z = 1 - n/d, 1/d = (1 - z)/n.
        v[pack::kGlobalZBufferParams] = {-1e30f, 1e30f, -1 / n, 1 / n};
    }
    v["unity_OrthoParams"] = {ortho ? 1 / p[0][0] : 0, ortho ? 1 / p[1][1] : 0, 0,
                              ortho ? 1.0f : 0};
    v["unity_CameraProjection"] = Mat(p);
    v["unity_CameraInvProjection"] = Mat(glm::inverse(p));
    // Unity's camera space looks down +z (view space looks down -z).
    const glm::mat4 world_to_camera =
        glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, -1)) * camera.view;
    v["unity_WorldToCamera"] = Mat(world_to_camera);
    v["unity_CameraToWorld"] = Mat(glm::inverse(world_to_camera));
    // Frustum planes (a, b, c, d), normals pointing inwards, from the rows of the
    // view-projection matrix (Gribb and Hartmann 2001); depth runs 0..1.
    const glm::mat4 vp = glm::transpose(p * camera.view);  // vp[i]: row i
    const glm::vec4 planes[6] = {vp[3] + vp[0], vp[3] - vp[0], vp[3] + vp[1],
                                 vp[3] - vp[1], vp[2],         vp[3] - vp[2]};
    std::vector<float> packed;
    for (const glm::vec4& plane : planes) {
        const float length = glm::length(glm::vec3(plane));
        const glm::vec4 unit = length > 0 ? plane / length : plane;
        packed.insert(packed.end(), {unit.x, unit.y, unit.z, unit.w});
    }
    v["unity_CameraWorldClipPlanes"] = packed;
    return v;
}

}  // namespace

float Luminance(const glm::vec3& c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

Status ChooseCamera(const Scene& scene,
                    const FrameSettings& settings,
                    CameraSetup& out,
                    const std::pair<glm::vec3, glm::vec3>* bounds) {
    const float aspect = float(settings.width) / float(settings.height);
    using Settings = FrameSettings;
    if (settings.camera < Settings::kCameraAuto ||
        (settings.camera >= 0 && size_t(settings.camera) >= scene.cameras.size())) {
        return Error{DiagCode::kBadScene, "camera " + std::to_string(settings.camera) +
                                              " does not exist (the scene has " +
                                              std::to_string(scene.cameras.size()) +
                                              "; use an index from 0, or the automatic camera)"};
    }
    if (!scene.cameras.empty() && settings.camera != Settings::kCameraAuto) {
        const Camera& c = scene.cameras[size_t(std::max(settings.camera, 0))];
        out.name =
            c.name.empty() ? "camera " + std::to_string(std::max(settings.camera, 0)) : c.name;
        out.view = glm::inverse(c.world);
        out.position = glm::vec3(c.world[3]);
        out.znear = c.znear > 0 ? c.znear : 0.05f;
        out.zfar = c.zfar;
        if (c.perspective) {
            // glTF: the viewport's aspect ratio is used; the file's only says what was intended.
            out.projection = Perspective(c.yfov, aspect, out.znear, out.zfar);
        } else {
            const float far = c.zfar > out.znear ? c.zfar : out.znear + 1000.0f;
            out.projection = glm::orthoRH_ZO(-c.xmag, c.xmag, -c.ymag, c.ymag, c.znear, far);
            out.zfar = far;
        }
        return {};
    }
    // No camera: frame the scene's bounds from the front, above and to the right.
    const auto [lo, hi] = bounds ? *bounds : SceneBounds(scene);
    const glm::vec3 center = (lo + hi) * 0.5f;
    const float radius = std::max(glm::length(hi - lo) * 0.5f, 1e-3f);
    const float yfov = 0.8f;
    const float fit = std::min(yfov, 2 * std::atan(std::tan(yfov / 2) * aspect));
    const float distance = radius / std::sin(fit / 2) * 1.05f;
    out.name = "automatic";
    out.position = center + glm::normalize(glm::vec3(0.45f, 0.35f, 1.0f)) * distance;
    out.view = glm::lookAtRH(out.position, center, glm::vec3(0, 1, 0));
    out.znear = std::max(distance - radius * 1.5f, distance * 0.01f);
    out.zfar = distance + radius * 2;
    out.projection = Perspective(yfov, aspect, out.znear, out.zfar);
    return {};
}

Values FrameValues(const Scene& scene, const FrameSettings& settings, const CameraSetup& camera) {
    const float t = settings.time;
    const float w = float(settings.width), h = float(settings.height);
    Values v;
    v[pack::kGlobalTime] = {t / 20, t, 2 * t, 3 * t};
    v[pack::kGlobalSinTime] = {std::sin(t / 8), std::sin(t / 4), std::sin(t / 2), std::sin(t)};
    v[pack::kGlobalCosTime] = {std::cos(t / 8), std::cos(t / 4), std::cos(t / 2), std::cos(t)};
    v["unity_DeltaTime"] = {1.0f / 60, 60.0f, 1.0f / 60, 60.0f};
    v[pack::kGlobalWorldSpaceCameraPos] = {camera.position.x, camera.position.y, camera.position.z};
    const float far = camera.zfar > 0 ? camera.zfar : 1e30f;
    // x = -1: the viewport flips clip space (+y is the top row, texture row 0), so
    // ComputeScreenPos must flip y to give texture coordinates of the frame's targets (Unity's
    // convention for a flipped projection).
    v[pack::kGlobalProjectionParams] = {-1, camera.znear, far, camera.zfar > 0 ? 1 / far : 0};
    v[pack::kGlobalScreenParams] = {w, h, 1 + 1 / w, 1 + 1 / h};
    // Shadow receivers drawn without their light's map (kiln test) read these: depth 0 against
    // the renderer's default map at depth 1, lit (render/shadow_plan.h sets the real ones).
    v[pack::kGlobalLightProjectionParams] = {0, 0, 0, 1};
    v["unity_MatrixV"] = Mat(camera.view);
    v["unity_MatrixInvV"] = Mat(glm::inverse(camera.view));
    v["unity_MatrixVP"] = Mat(camera.projection * camera.view);
    v[pack::kGlobalMatrixProjection] = Mat(camera.projection);
    v[pack::kGlobalLightSplitsNear] = {0, 1e30f, 1e30f, 1e30f};
    v[pack::kGlobalLightSplitsFar] = {1e30f, 1e30f, 1e30f, 1e30f};
    for (const auto& [name, value] : CameraValues(camera)) {
        v[name] = value;
    }
    // Flat: every ambient colour is the same radiance; trilight: the three.
    // UNITY_LIGHTMODEL_AMBIENT is glstate_lightmodel_ambient * 2, the sky colour (Unity's
    // RenderSettings.ambientLight); unity_IndirectSpecColor is the mean radiance over the sphere.
    // A sky: its mean radiance over the upper cap, the horizon band and the lower cap.
    const bool trilight = scene.ambient_mode == AmbientMode::kTrilight;
    const Sky* image = SkyOf(scene);
    const glm::vec4 sky(image ? image->up : scene.ambient, 1);
    v["unity_AmbientSky"] = Vec(sky);
    v["unity_AmbientEquator"] = Vec(image      ? glm::vec4(image->horizon, 1)
                                    : trilight ? glm::vec4(scene.ambient_equator, 1)
                                               : sky);
    v["unity_AmbientGround"] = Vec(image      ? glm::vec4(image->down, 1)
                                   : trilight ? glm::vec4(scene.ambient_ground, 1)
                                              : sky);
    v["unity_IndirectSpecColor"] = Vec(glm::vec4(MeanAmbient(scene), 1));
    v[pack::kGlobalLightModelAmbient] = Vec(sky * 0.5f);
    // The reflection probe is the ambient itself (render/reflection_probe.h): a linear float
    // cube (DecodeHDR multiplier 1, exponent 1), one probe (blend weight BoxMin.w = 1), no box
    // projection (ProbePosition.w = 0).
    for (const char* probe : {"unity_SpecCube0", "unity_SpecCube1"}) {
        v[std::string(probe) + "_HDR"] = {1, 1, 0, 0};
        v[std::string(probe) + "_BoxMin"] = {-1e30f, -1e30f, -1e30f, 1};
        v[std::string(probe) + "_BoxMax"] = {1e30f, 1e30f, 1e30f, 1};
        v[std::string(probe) + "_ProbePosition"] = {0, 0, 0, 0};
    }
    v.merge(ProbeValues(scene, {}, glm::vec3(0.0f)));
    return v;
}

const Sky* SkyOf(const Scene& scene) {
    return scene.ambient_mode == AmbientMode::kSky ? scene.sky.get() : nullptr;
}

glm::vec3 MeanAmbient(const Scene& scene) {
    if (const Sky* sky = SkyOf(scene)) {
        return sky->mean;
    }
    if (scene.ambient_mode != AmbientMode::kTrilight) {
        return scene.ambient;
    }
    // The mean of the trilight gradient over the sphere: y is uniform on [-1, 1].
    return scene.ambient_equator * 0.5f + (scene.ambient + scene.ambient_ground) * 0.25f;
}

std::pair<glm::vec3, glm::vec3> IlluminanceAt(const Light& light, const glm::vec3& point) {
    const glm::vec3 lux = light.color * light.intensity;
    if (light.type == LightType::kDirectional) {
        return {lux, -light.direction};
    }
    const glm::vec3 to_light = light.position - point;
    const float d = glm::length(to_light);
    const glm::vec3 l = d > 0 ? to_light / d : glm::vec3(0, 1, 0);
    double falloff = reference::DistanceAttenuation(d, light.range);
    if (light.type == LightType::kSpot) {
        falloff *=
            reference::SpotCone(glm::dot(-l, light.direction), light.outer_cone, light.inner_cone);
    }
    return {lux * float(falloff), l};
}

Values ProbeValues(const Scene& scene,
                   const std::vector<const Light*>& lights,
                   const glm::vec3& center) {
    // A constant sky of radiance `ambient`: ShadeSH9 then returns E / pi = ambient (a trilight
    // gradient: its projection, reference::AddTrilight). A light of
    // illuminance E0 from l adds E0 * Y_lm(l) (radiance times solid angle), so ShadeSH9 gives
    // about E0 / pi * max(n . l, 0) = _LightColor0 * (n . l), what a pixel light's diffuse
    // term would (the order-2 approximation of the clamped cosine, Ramamoorthi and Hanrahan
    // 2001).
    reference::SH9 sh;
    if (const Sky* sky = SkyOf(scene)) {
        sh.L = sky->sh;  // projected once, when the sky was made
    } else if (scene.ambient_mode == AmbientMode::kTrilight) {
        reference::AddTrilight(sh, glm::dvec3(scene.ambient), glm::dvec3(scene.ambient_equator),
                               glm::dvec3(scene.ambient_ground));
    } else {
        reference::AddConstantRadiance(sh, glm::dvec3(scene.ambient));
    }
    for (const Light* light : lights) {
        const auto [lux, l] = IlluminanceAt(*light, center);
        reference::AddDirectionalLight(sh, glm::dvec3(l), glm::dvec3(lux));
    }
    const reference::PackedSH packed = reference::PackSH9(sh);
    const char* names[7] = {"unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr",
                            "unity_SHBg", "unity_SHBb", "unity_SHC"};
    Values v;
    for (int i = 0; i < 7; ++i) {
        v[names[i]] = std::vector<float>(packed[size_t(i)].begin(), packed[size_t(i)].end());
    }
    return v;
}

Values LightValues(const Light* light, const std::vector<const Light*>& vertex) {
    Values v;
    if (light) {
        const glm::vec3 c = ShaderLightColor(*light);
        v[pack::kGlobalLightColor0] = {c.r, c.g, c.b, 1};
        if (light->type == LightType::kDirectional) {
            const glm::vec3 d = -light->direction;  // towards the light
            v[pack::kGlobalWorldSpaceLightPos0] = {d.x, d.y, d.z, 0};
        } else {
            v[pack::kGlobalWorldSpaceLightPos0] = {light->position.x, light->position.y,
                                                   light->position.z, 1};
            // Unity: w = 1 / range (the shadow-cube distance scale); unlimited lights 0.
            v[pack::kGlobalLightPositionRange] = {light->position.x, light->position.y,
                                                  light->position.z,
                                                  light->range > 0 ? 1 / light->range : 0};
        }
        v["kiln_SpotDirection0"] = {light->direction.x, light->direction.y, light->direction.z, 0};
        const float inv_range2 = light->range > 0 ? 1 / (light->range * light->range) : 0;
        v["kiln_LightParams0"] = {inv_range2, std::cos(light->outer_cone),
                                  std::cos(light->inner_cone), 0};
    } else {
        v[pack::kGlobalLightColor0] = {0, 0, 0, 0};
        v[pack::kGlobalWorldSpaceLightPos0] = {0, 1, 0, 0};
        v["kiln_SpotDirection0"] = {0, -1, 0, 0};
        v["kiln_LightParams0"] = {0, -1, -1, 0};
    }
    // No baked shadow mask: a light's baked occlusion is 1 (Unity's UnitySampleBakedOcclusion
    // multiplies the main light by dot(occlusion, selector) wherever light probe proxy volumes are
    // on, as on desktop; a zero selector would leave the main light dark).
    v["unity_OcclusionMaskSelector"] = {1, 0, 0, 0};
    v["unity_ProbesOcclusion"] = {1, 1, 1, 1};
    std::vector<float> x(4, 0), y(4, 0), z(4, 0), atten(4, 0), colors(32, 0);
    for (size_t i = 0; i < vertex.size() && i < 4; ++i) {
        const Light& l = *vertex[i];
        x[i] = l.position.x;
        y[i] = l.position.y;
        z[i] = l.position.z;
        atten[i] = l.range > 0 ? 1 / (l.range * l.range) : 0;
        const glm::vec3 c = ShaderLightColor(l);
        colors[i * 4 + 0] = c.r;
        colors[i * 4 + 1] = c.g;
        colors[i * 4 + 2] = c.b;
        colors[i * 4 + 3] = 1;
    }
    v["unity_4LightPosX0"] = x;
    v["unity_4LightPosY0"] = y;
    v["unity_4LightPosZ0"] = z;
    v["unity_4LightAtten0"] = atten;
    v["unity_LightColor"] = colors;
    return v;
}

Values ObjectValues(const glm::mat4& world, const glm::mat4& view) {
    // w: -1 for a mirroring transform, so tangent-space bitangents keep their handedness.
    const float mirror = glm::determinant(glm::mat3(world)) < 0 ? -1.0f : 1.0f;
    return {{"unity_ObjectToWorld", Mat(world)},
            {"unity_WorldToObject", Mat(glm::inverse(world))},
            {"unity_WorldTransformParams", {0, 0, 0, mirror}},
            {pack::kGlobalMatrixTransposeModelView0, Mat(glm::transpose(view * world))}};
}

const Light* MainLight(const std::vector<Light>& lights) {
    const Light* main = nullptr;
    for (const Light& l : lights) {
        if (l.type == LightType::kDirectional && l.importance != LightImportance::kNotImportant &&
            (!main ||
             l.intensity * Luminance(l.color) > main->intensity * Luminance(main->color))) {
            main = &l;
        }
    }
    return main;
}

ObjectLights LightsFor(const std::vector<Light>& lights,
                       const Light* main,
                       const glm::vec3& center,
                       float radius,
                       uint32_t pixel_lights,
                       LightMode mode) {
    ObjectLights out;
    out.main = main;
    struct Ranked {
        bool directional;
        float importance;
        const Light* light;
    };
    std::vector<Ranked> ranked;
    for (const Light& l : lights) {
        if (&l == main) {
            continue;
        }
        const float power = l.intensity * Luminance(l.color);
        if (l.type == LightType::kDirectional) {
            ranked.push_back({true, power, &l});
            continue;
        }
        const float d = std::max(glm::length(l.position - center) - radius, 0.0f);
        if (l.range > 0 && d >= l.range) {
            continue;
        }
        ranked.push_back({false, power / std::max(d * d, 1e-4f), &l});
    }
    std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
        return a.directional != b.directional ? a.directional : a.importance > b.importance;
    });
    const size_t pixel = mode == LightMode::kAuto    ? pixel_lights
                         : mode == LightMode::kPixel ? ranked.size()
                                                     : 0;
    const bool vertex = mode == LightMode::kAuto || mode == LightMode::kVertex;
    // Unity's Render Mode (auto mode only): important lights are per pixel whatever the count,
    // not-important ones never; auto lights fill what is left of the count.
    const bool by_importance = mode == LightMode::kAuto;
    if (by_importance) {
        for (const Ranked& r : ranked) {
            if (r.light->importance == LightImportance::kImportant) {
                out.pixel.push_back(r.light);
            }
        }
    }
    for (const auto& [directional, importance, light] : ranked) {
        const LightImportance li = by_importance ? light->importance : LightImportance::kAuto;
        if (li == LightImportance::kImportant) {
            continue;  // already per pixel
        }
        if (li == LightImportance::kAuto && out.pixel.size() < pixel) {
            out.pixel.push_back(light);
        } else if (vertex && light->type == LightType::kPoint && out.vertex.size() < 4) {
            out.vertex.push_back(light);
        } else {
            out.sh.push_back(light);
        }
    }
    return out;
}

}  // namespace kiln::runtime
