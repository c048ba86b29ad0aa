// TestMaterialStability (kiln/tools/stability.h): a material's fragment variants under extreme
// light set-ups and at the ends of its Ranges, in the stability scene (harness/harness_scene.h).
#include "kiln/tools/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include <glm/geometric.hpp>

#include "harness/harness_scene.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"

namespace kiln::tools {

using runtime::ColorPipeline;
using runtime::FrameSettings;
using runtime::Light;
using runtime::LightType;
using runtime::LinearImage;
using runtime::Renderer;
using runtime::Scene;
namespace {

using glm::vec3;

struct LightSetup {
    std::string name;
    Light light;   // per pixel (its type is the variant's)
    Light vertex;  // the point light for VERTEXLIGHT_ON
};

Light Make(LightType type, vec3 position, vec3 direction, float intensity) {
    Light l;
    l.type = type;
    l.name = "stability light";
    l.position = position;
    l.direction = direction;
    l.intensity = intensity;
    l.inner_cone = 0.3f;
    l.outer_cone = 0.5f;
    return l;
}

// The set-ups for a light of `type`. The eye is at (0, 0, kStabilityEyeZ) looking at the origin.
std::vector<LightSetup> Setups(LightType type) {
    const float e = kStabilityEyeZ;
    const vec3 eye(0, 0, e), behind(0, 0, -e), toward(0, 0, -1), away(0, 0, 1);
    auto point = [](vec3 p, float i) { return Make(LightType::kPoint, p, {0, 0, -1}, i); };
    std::vector<LightSetup> out;
    auto add = [&](std::string name, vec3 pos, vec3 dir, float intensity, vec3 vertex_pos) {
        out.push_back(
            {std::move(name), Make(type, pos, dir, intensity), point(vertex_pos, intensity)});
    };
    // The first set-up (the light at the camera) changed by `change`.
    auto at_camera = [&](std::string name, const std::function<void(LightSetup&)>& change) {
        LightSetup l = out[0];
        l.name = std::move(name);
        change(l);
        out.push_back(std::move(l));
    };
    const bool directional = type == LightType::kDirectional;
    add(directional ? "directional light from the camera (l = v at the centre)"
                    : "light at the camera (l = v)",
        eye, toward, 1, eye);
    add(directional ? "directional light from behind the surface (n . l = -1)"
                    : "light mirrored behind the surface (l = -v at the centre)",
        behind, away, 1, behind);
    if (directional) {
        add("directional light grazing the surface (n . l = 0)", eye, {1, 0, 0}, 1, vec3(0));
    } else {
        add("light on the surface (distance 0 at the centre)", vec3(0), toward, 1, vec3(0));
        add("light 1e-6 from the surface", vec3(0, 0, 1e-6f), toward, 1, vec3(0, 0, 1e-6f));
        add("light 1e6 away", vec3(0, 0, 1e6f), toward, 1, vec3(0, 0, 1e6f));
        at_camera("light at the camera with range 1e-6",
                  [](LightSetup& l) { l.light.range = l.vertex.range = 1e-6f; });
        at_camera("light at the camera with range -1 (none)",
                  [](LightSetup& l) { l.light.range = l.vertex.range = -1.0f; });
    }
    if (type == LightType::kSpot) {
        at_camera("spot light with inner cone = outer cone",
                  [](LightSetup& l) { l.light.inner_cone = l.light.outer_cone = 0.5f; });
        at_camera("spot light with inner cone > outer cone", [](LightSetup& l) {
            l.light.inner_cone = 0.6f;
            l.light.outer_cone = 0.3f;
        });
    }
    for (float intensity : {6.6e4f, 1e9f, 3.4e38f}) {
        char name[64];
        std::snprintf(name, sizeof name, "intensity %g at the camera", double(intensity));
        add(name, eye, toward, intensity, eye);
    }
    return out;
}

// What the pixel (x, y) of the stability scene sees: the point, its normal, and the set-up's l.
std::string Inputs(const LightSetup& setup, uint32_t x, uint32_t y, uint32_t size) {
    const float t = std::tan(kStabilityYFov / 2);
    const vec3 eye(0, 0, kStabilityEyeZ);
    const vec3 d = glm::normalize(vec3((2 * (float(x) + 0.5f) / float(size) - 1) * t,
                                       (1 - 2 * (float(y) + 0.5f) / float(size)) * t, -1));
    vec3 p, n(0, 0, 1);
    const vec3 c = kStabilitySphereCentre;
    const float r = kStabilitySphereRadius;
    const float b = glm::dot(d, eye - c), q = glm::dot(eye - c, eye - c) - r * r;
    if (b * b - q >= 0 && -b - std::sqrt(b * b - q) > 0) {
        p = eye + d * (-b - std::sqrt(b * b - q));
        n = glm::normalize(p - c);
    } else {
        p = eye + d * (eye.z / -d.z);
    }
    const vec3 v = glm::normalize(eye - p);
    const Light& L = setup.light;
    const vec3 to = L.position - p;
    const float distance = glm::length(to);
    char buf[192];
    if (L.type != LightType::kDirectional && distance < 1e-6f) {
        std::snprintf(buf, sizeof buf,
                      "the light is at the shaded point (distance %g), n . v = %.3g",
                      double(distance), double(glm::dot(n, v)));
        return buf;
    }
    const vec3 l = L.type == LightType::kDirectional ? -L.direction : to / distance;
    const float lv = glm::dot(l, v);
    std::snprintf(buf, sizeof buf, "n . l = %.3g, n . v = %.3g, l . v = %.3g%s, distance %.3g",
                  double(glm::dot(n, l)), double(glm::dot(n, v)), double(lv),
                  lv <= -1 + 1e-6f ? " (l = -v)" : "", double(distance));
    return buf;
}

bool IsLightKeyword(const std::string& k) {
    return k == pack::kKeywordDirectional || k == pack::kKeywordPoint || k == pack::kKeywordSpot ||
           k == pack::kKeywordVertexLight;
}

// The variant keywords the material selects: its own, plus only the light keywords the forward
// path sets.
bool MaterialSelects(const std::vector<std::string>& variant,
                     const std::vector<std::string>& mine) {
    for (const std::string& k : mine) {
        if (std::find(variant.begin(), variant.end(), k) == variant.end()) {
            return false;
        }
    }
    for (const std::string& k : variant) {
        if (!IsLightKeyword(k) && std::find(mine.begin(), mine.end(), k) == mine.end()) {
            return false;
        }
    }
    return true;
}

}  // namespace

Result<MaterialStabilityReport> TestMaterialStability(Renderer& renderer,
                                                      const ColorPipeline& color,
                                                      const std::string& material,
                                                      const MaterialStabilityOptions& options) {
    if (options.size < 9 || options.size > 1025 || options.size % 2 == 0) {
        return Error{DiagCode::kBadCommandLine,
                     "the stability image must be odd, 9 to 1025 pixels"};
    }
    runtime::MaterialInstance m;
    if (Status e = runtime::InstanceFromMaterialFile(runtime::tool_access::Packs(renderer),
                                                     material, color, m);
        !e.ok()) {
        return e.error();
    }
    const pack::Pack& pk = renderer.pack(m.pack);
    const pack::ShaderRec sr = pk.Shader(m.shader).value();
    MaterialStabilityReport report;
    report.material = material;
    report.shader = std::string(pk.String(sr.name));
    const Scene scene = StabilityScene();
    FrameSettings settings;
    settings.width = settings.height = options.size;
    settings.camera = 0;
    runtime::CameraSetup camera;
    if (Status e = runtime::ChooseCamera(scene, settings, camera); !e.ok()) {
        return e.error();
    }
    // The material's values, then each Range property at its ends.
    std::vector<std::pair<std::string, std::map<std::string, std::vector<float>, std::less<>>>>
        values{{"(material)", m.values}};
    for (uint32_t i = sr.first_property; i < sr.first_property + sr.property_count; ++i) {
        const auto p = pk.Get<pack::PropertyRec>(pack::SectionTag::kProperties, i).value();
        if (pack::PropertyType(p.type) != pack::PropertyType::kRange) {
            continue;
        }
        for (const auto& [v, end] : {std::pair{p.range_min, "min"}, {p.range_max, "max"}}) {
            auto at = m.values;
            at[std::string(pk.String(p.name))] = {v};
            char name[128];
            std::snprintf(name, sizeof name, "%s = %g (Range %s)",
                          std::string(pk.String(p.name)).c_str(), double(v), end);
            values.emplace_back(name, std::move(at));
        }
    }
    for (uint32_t pass = sr.first_pass; pass < sr.first_pass + sr.pass_count; ++pass) {
        const std::string_view mode = pack::LightModeOf(pk, pass);
        const bool additive = mode == pack::kLightModeForwardAdd;
        if (!(mode.empty() || mode == pack::kLightModeAlways ||
              mode == pack::kLightModeForwardBase || additive)) {
            continue;  // not drawn by the forward path
        }
        const pack::PassRec rec = pk.Pass(pass).value();
        for (uint32_t v = rec.first_variant; v < rec.first_variant + rec.variant_count; ++v) {
            const std::vector<std::string> keywords =
                pk.KeywordsOf(pass, pack::VariantKey(pk.Variant(v).value().key));
            if (!MaterialSelects(keywords, m.keywords)) {
                continue;
            }
            ++report.variants;
            auto has = [&](const char* k) {
                return std::find(keywords.begin(), keywords.end(), k) != keywords.end();
            };
            const LightType type = !additive                  ? LightType::kDirectional
                                   : has(pack::kKeywordPoint) ? LightType::kPoint
                                   : has(pack::kKeywordSpot)  ? LightType::kSpot
                                                              : LightType::kDirectional;
            for (const LightSetup& setup : Setups(type)) {
                for (const auto& [properties, vals] : values) {
                    runtime::MaterialInstance at = m;
                    at.values = vals;
                    HarnessPass draw;
                    draw.material = &at;
                    draw.pass = pass;
                    draw.additive = additive;
                    draw.keywords = keywords;
                    draw.lights = {setup.light, setup.vertex};
                    draw.vertex_light = !additive && has(pack::kKeywordVertexLight);
                    LinearImage image;
                    ++report.renders;
                    if (Status e =
                            DrawHarnessPass(renderer, color, scene, settings, camera, draw, image);
                        !e.ok()) {
                        return e.error();
                    }
                    StabilityFinding f;
                    for (size_t i = 0; i < image.rgba.size(); ++i) {
                        if (!std::isfinite(image.rgba[i]) && f.bad++ == 0) {
                            f.x = uint32_t(i / 4 % image.width);
                            f.y = uint32_t(i / 4 / image.width);
                        }
                    }
                    if (f.bad == 0) {
                        continue;
                    }
                    f.values = image.rgba.size();
                    f.shader = report.shader;
                    f.pass = pack::PassLabel(pk, pass);
                    f.keywords = keywords;
                    f.properties = properties;
                    f.light = setup.name;
                    f.inputs = Inputs(setup, f.x, f.y, options.size);
                    report.findings.push_back(std::move(f));
                }
            }
        }
    }
    if (report.variants == 0) {
        return Error{DiagCode::kBadCommandLine,
                     material + ": no variant of \"" + report.shader +
                         "\" the forward path draws has this material's keywords"};
    }
    return report;
}

}  // namespace kiln::tools
