#include "kiln/tools/variant_test.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <tuple>

#include "harness/harness_scene.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"

namespace kiln::tools {

using runtime::ColorPipeline;
using runtime::FrameSettings;
using runtime::LightMode;
using runtime::LightType;
using runtime::LinearImage;
using runtime::Renderer;
using runtime::Scene;
namespace {

struct Case {
    uint32_t pack, shader, pass, variant;
};

// A Range property: its name and ends.
struct RangeProperty {
    std::string name;
    float min, max;
};

// What a render draws with: the variant, the material's values, the light.
struct Setup {
    std::string properties = "(defaults)";
    std::map<std::string, std::vector<float>> values;  // on top of the defaults
    float intensity = 1;                               // of the light (and the vertex light)
    bool no_light = false;                             // draw as with no light at all
};

std::string Describe(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

// The first non-finite pixel, as a message; "" when every pixel is finite.
std::string CheckFinite(const LinearImage& img) {
    size_t bad = 0, first = 0;
    for (size_t i = 0; i < img.rgba.size(); ++i) {
        if (!std::isfinite(img.rgba[i]) && bad++ == 0) {
            first = i / 4;
        }
    }
    if (bad == 0) {
        return "";
    }
    return std::to_string(bad) + " of " + std::to_string(img.rgba.size()) +
           " channel values are not finite (the first at pixel " +
           std::to_string(first % img.width) + ", " + std::to_string(first / img.width) + ")";
}

// The brightest channel above `background` in the central eighth of the image (all on the sphere,
// facing the light).
float CentreMax(const LinearImage& img, float background) {
    float most = 0;
    const uint32_t r = std::max(1u, img.width / 8);
    for (uint32_t y = img.height / 2 - r; y < img.height / 2 + r; ++y) {
        for (uint32_t x = img.width / 2 - r; x < img.width / 2 + r; ++x) {
            for (int c = 0; c < 3; ++c) {
                const float v = img.rgba[(size_t(y) * img.width + x) * 4 + size_t(c)];
                most = std::isfinite(v) ? std::max(most, v - background) : most;
            }
        }
    }
    return most;
}

struct Harness {
    Renderer& renderer;
    const ColorPipeline& color;
    const VariantTestOptions& options;
    Scene scene = HarnessScene();
    runtime::CameraSetup camera;
    VariantTestReport report;

    FrameSettings Settings(bool additive) const {
        FrameSettings f;
        f.width = f.height = options.size;
        f.camera = 0;
        f.background = glm::vec3(additive ? 0.25f : 0.0f);
        return f;
    }

    // One render of a variant with `setup`.
    Status Draw(const Case& c,
                bool additive,
                const std::vector<std::string>& keywords,
                const Setup& setup,
                LinearImage& out) {
        const pack::Pack& pk = renderer.pack(c.pack);
        const bool point = std::count(keywords.begin(), keywords.end(), pack::kKeywordPoint) > 0;
        const bool spot = std::count(keywords.begin(), keywords.end(), pack::kKeywordSpot) > 0;
        const LightType type = !additive ? LightType::kDirectional
                               : point   ? LightType::kPoint
                               : spot    ? LightType::kSpot
                                         : LightType::kDirectional;
        runtime::MaterialInstance m;  // the draw plan's material: lives for this frame
        runtime::InstanceFromDefaults(pk, c.pack, c.shader, color, m);
        // A main colour (`_Color`, Unity's Material.color) that defaults to black would hide
        // every lighting check (Ronja's tutorial shaders tint with black by default): the
        // harness draws it white.
        if (auto it = m.values.find("_Color"); it != m.values.end() && it->second.size() >= 3 &&
                                               it->second[0] == 0 && it->second[1] == 0 &&
                                               it->second[2] == 0) {
            it->second = {1, 1, 1, it->second.size() > 3 ? it->second[3] : 1};
        }
        for (const auto& [name, v] : setup.values) {
            m.values[name] = v;
        }
        HarnessPass draw;
        draw.material = &m;
        draw.pass = c.pass;
        draw.additive = additive;
        draw.keywords = keywords;
        draw.lights = {HarnessLight(type, setup.intensity * 4.0f),
                       HarnessLight(LightType::kPoint, setup.intensity * 4.0f)};
        draw.pixel_light = !setup.no_light;
        draw.vertex_light = !additive && !setup.no_light &&
                            std::count(keywords.begin(), keywords.end(), pack::kKeywordVertexLight);
        return DrawHarnessPass(renderer, color, scene, Settings(additive), camera, draw, out);
    }

    void Fail(const Case& c,
              const std::vector<std::string>& keywords,
              const Setup& setup,
              std::string check,
              std::string message,
              LinearImage image) {
        const pack::Pack& pk = renderer.pack(c.pack);
        report.failures.push_back({runtime::tool_access::PackPath(renderer, c.pack),
                                   std::string(pk.String(pk.Shader(c.shader).value().name)),
                                   pack::PassLabel(pk, c.pass), keywords, setup.properties,
                                   std::move(check), std::move(message), std::move(image)});
    }

    // Draws one setup and checks it; false when the variant cannot be drawn at all.
    bool Run(const Case& c,
             bool additive,
             bool lit,
             const std::vector<std::string>& keywords,
             const Setup& setup,
             LinearImage& out) {
        const size_t messages = renderer.ValidationMessages().size();
        ++report.renders;
        if (Status e = Draw(c, additive, keywords, setup, out); !e.ok()) {
            Fail(c, keywords, setup, "pipeline", e.error().message, {});
            return false;
        }
        const std::vector<std::string> all = renderer.ValidationMessages();
        if (all.size() > messages) {
            Fail(c, keywords, setup, "validation", all[messages], out);
        }
        if (std::string bad = CheckFinite(out); !bad.empty()) {
            Fail(c, keywords, setup, "finite", bad, out);
            return true;
        }
        const float background = additive ? 0.25f : 0.0f;
        if (lit && !setup.no_light && setup.intensity > 0 && CentreMax(out, background) <= 1e-4f) {
            Fail(c, keywords, setup, "lit",
                 std::string(additive ? "the pass adds no light" : "the sphere is black") +
                     " where the light faces it (brightest channel " +
                     Describe(CentreMax(out, background) + background) + ")",
                 out);
        }
        if (additive) {
            float lowest = 1;
            for (size_t i = 0; i < out.rgba.size(); ++i) {
                lowest = i % 4 == 3 ? lowest : std::min(lowest, out.rgba[i]);
            }
            if (lowest < 0.25f - 1e-4f) {
                Fail(c, keywords, setup, "additive",
                     "the pass darkens what was drawn before it: a channel fell from 0.25 to " +
                         Describe(lowest),
                     out);
            }
        }
        return true;
    }

    void Test(const Case& c) {
        const pack::Pack& pk = renderer.pack(c.pack);
        const std::vector<std::string> keywords =
            pk.KeywordsOf(c.pass, pack::VariantKey(pk.Variant(c.variant).value().key));
        const std::string_view mode = pack::LightModeOf(pk, c.pass);
        const bool additive = mode == pack::kLightModeForwardAdd;
        const bool lit = additive || mode == pack::kLightModeForwardBase;
        ++report.variants;
        LinearImage image, zero, none;
        if (!Run(c, additive, lit, keywords, {}, image)) {
            return;  // no pipeline: nothing else can be drawn
        }
        Setup dark;
        dark.intensity = 0;
        dark.properties = "(defaults), light intensity 0";
        Setup unlit;
        unlit.no_light = true;
        unlit.properties = "(defaults), no light";
        if (Run(c, additive, lit, keywords, dark, zero) &&
            Run(c, additive, lit, keywords, unlit, none) && zero.rgba.size() == none.rgba.size()) {
            float diff = 0;
            for (size_t i = 0; i < zero.rgba.size(); ++i) {
                diff = std::max(diff, std::abs(zero.rgba[i] - none.rgba[i]));
            }
            if (!(diff <= 1e-5f)) {
                Fail(c, keywords, dark, "no-light",
                     "a light of intensity 0 changes the image by up to " + Describe(diff) +
                         " from the image without a light",
                     zero);
            }
        }
        for (const RangeProperty& r : Ranges(c)) {
            for (const auto& [value, end] : {std::pair{r.min, "min"}, {r.max, "max"}}) {
                Setup at;
                at.values[r.name] = {value};
                at.properties =
                    r.name + " = " + Describe(value) + " (Range " + std::string(end) + ")";
                Run(c, additive, lit, keywords, at, image);
            }
        }
    }

    std::vector<RangeProperty> Ranges(const Case& c) const {
        const pack::Pack& pk = renderer.pack(c.pack);
        const pack::ShaderRec sr = pk.Shader(c.shader).value();
        std::vector<RangeProperty> out;
        for (uint32_t i = sr.first_property; i < sr.first_property + sr.property_count; ++i) {
            const auto p = pk.Get<pack::PropertyRec>(pack::SectionTag::kProperties, i).value();
            if (pack::PropertyType(p.type) == pack::PropertyType::kRange) {
                out.push_back({std::string(pk.String(p.name)), p.range_min, p.range_max});
            }
        }
        return out;
    }
};

// Every variant of the passes the forward path draws; the others are listed as skipped.
std::vector<Case> Cases(const Renderer& renderer,
                        const VariantTestOptions& options,
                        VariantTestReport& report) {
    // A skipped pass or shader, with its variant count.
    auto skip = [&](std::string what, size_t variants) {
        report.skipped.push_back(what + " (" + std::to_string(variants) + " variant" +
                                 (variants == 1 ? ")" : "s)"));
        report.skipped_variants += variants;
    };
    auto shader_variants = [](const pack::Pack& pk, const pack::ShaderRec& sr) {
        size_t n = 0;
        for (uint32_t pass = sr.first_pass; pass < sr.first_pass + sr.pass_count; ++pass) {
            n += pk.Pass(pass).value().variant_count;
        }
        return n;
    };
    std::vector<Case> out;
    for (uint32_t p = 0; p < renderer.pack_count(); ++p) {
        const pack::Pack& pk = renderer.pack(p);
        for (uint32_t sh = 0; sh < pk.Count(pack::SectionTag::kShaders); ++sh) {
            const pack::ShaderRec sr = pk.Shader(sh).value();
            const std::string name(pk.String(sr.name));
            if (!options.shaders.empty() &&
                std::find(options.shaders.begin(), options.shaders.end(), name) ==
                    options.shaders.end()) {
                continue;
            }
            if (name == pack::kShaderDeferredShading) {
                // Drawn over a G-buffer, never on an object: the harness's scene cannot draw it.
                skip("shader \"" + name +
                         "\": the deferred path's light pass, drawn over a G-buffer, not on an "
                         "object",
                     shader_variants(pk, sr));
                continue;
            }
            if (name == pack::kShaderScreenSpaceShadows) {
                // Drawn over the camera's depth with a light's shadow map, never on an object.
                skip("shader \"" + name +
                         "\": the screen-space shadow collector, drawn over the camera's "
                         "depth, not on an object",
                     shader_variants(pk, sr));
                continue;
            }
            for (uint32_t pass = sr.first_pass; pass < sr.first_pass + sr.pass_count; ++pass) {
                const pack::PassRec rec = pk.Pass(pass).value();
                const std::string_view mode = pack::LightModeOf(pk, pass);
                if (!(mode.empty() || mode == pack::kLightModeAlways ||
                      mode == pack::kLightModeForwardBase || mode == pack::kLightModeForwardAdd)) {
                    skip("shader \"" + name + "\" pass \"" + pack::PassLabel(pk, pass) +
                             "\": LightMode " + std::string(mode) +
                             " is not drawn by the forward path",
                         rec.variant_count);
                    continue;
                }
                for (uint32_t v = rec.first_variant; v < rec.first_variant + rec.variant_count; ++v)
                    out.push_back({p, sh, pass, v});
            }
        }
    }
    if (options.sample && *options.sample < out.size()) {
        std::mt19937_64 rng(options.seed);
        std::shuffle(out.begin(), out.end(), rng);
        out.resize(*options.sample);
        std::sort(out.begin(), out.end(), [](const Case& a, const Case& b) {
            return std::tie(a.pack, a.variant) < std::tie(b.pack, b.variant);
        });
    }
    return out;
}

}  // namespace

Result<VariantTestReport> TestVariants(Renderer& renderer,
                                       const ColorPipeline& color,
                                       const VariantTestOptions& options) {
    if (renderer.pack_count() == 0) {
        return Error{DiagCode::kRenderFailed, "no variant pack loaded"};
    }
    if (options.size < 16 || options.size > 4096) {
        return Error{DiagCode::kBadCommandLine, "the harness image must be 16 to 4096 pixels"};
    }
    Harness h{renderer, color, options, HarnessScene(), {}, {}};
    if (Status e = runtime::ChooseCamera(h.scene, h.Settings(false), h.camera); !e.ok()) {
        return e.error();
    }
    for (const Case& c : Cases(renderer, options, h.report)) {
        h.Test(c);
    }
    return std::move(h.report);
}

}  // namespace kiln::tools
