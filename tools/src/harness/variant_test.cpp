#include "kiln/tools/variant_test.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <tuple>

#include "harness/variant_harness.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"

namespace kiln::tools {

using runtime::FrameSettings;
using runtime::LightType;
namespace {

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

// The forward passes' checks of one variant (kiln/tools/variant_test.h).
struct ForwardTest {
    Harness& h;
    const Case& c;

    // One render of the variant with `setup`.
    Status Draw(bool additive,
                const std::vector<std::string>& keywords,
                const Setup& setup,
                LinearImage& out) {
        const bool point = std::count(keywords.begin(), keywords.end(), pack::kKeywordPoint) > 0;
        const bool spot = std::count(keywords.begin(), keywords.end(), pack::kKeywordSpot) > 0;
        const LightType type = !additive ? LightType::kDirectional
                               : point   ? LightType::kPoint
                               : spot    ? LightType::kSpot
                                         : LightType::kDirectional;
        runtime::MaterialInstance m;  // the draw plan's material: lives for this frame
        h.Material(c, m);
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
        return DrawHarnessPass(h.renderer, h.color, h.scene, h.Settings(additive), h.camera, draw,
                               out);
    }

    // Draws one setup and checks it; false when the variant cannot be drawn at all.
    bool Run(bool additive,
             bool lit,
             const std::vector<std::string>& keywords,
             const Setup& setup,
             LinearImage& out) {
        const size_t messages = h.renderer.ValidationMessages().size();
        ++h.report.renders;
        if (Status e = Draw(additive, keywords, setup, out); !e.ok()) {
            h.Fail(c, keywords, setup.properties, "pipeline", e.error().message, {});
            return false;
        }
        const std::vector<std::string> all = h.renderer.ValidationMessages();
        if (all.size() > messages) {
            h.Fail(c, keywords, setup.properties, "validation", all[messages], out);
        }
        if (std::string bad = CheckFinite(out.rgba, out.width, 4); !bad.empty()) {
            h.Fail(c, keywords, setup.properties, "finite", bad, out);
            return true;
        }
        const float background = additive ? 0.25f : 0.0f;
        if (lit && !setup.no_light && setup.intensity > 0 && CentreMax(out, background) <= 1e-4f) {
            h.Fail(c, keywords, setup.properties, "lit",
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
                h.Fail(c, keywords, setup.properties, "additive",
                       "the pass darkens what was drawn before it: a channel fell from 0.25 to " +
                           Describe(lowest),
                       out);
            }
        }
        return true;
    }

    void Test() {
        const pack::Pack& pk = h.renderer.pack(c.pack);
        const std::vector<std::string> keywords = h.Keywords(c);
        const std::string_view mode = pack::LightModeOf(pk, c.pass);
        const bool additive = mode == pack::kLightModeForwardAdd;
        const bool lit = additive || mode == pack::kLightModeForwardBase;
        ++h.report.variants;
        LinearImage image, zero, none;
        if (!Run(additive, lit, keywords, {}, image)) {
            return;  // no pipeline: nothing else can be drawn
        }
        Setup dark;
        dark.intensity = 0;
        dark.properties = "(defaults), light intensity 0";
        Setup unlit;
        unlit.no_light = true;
        unlit.properties = "(defaults), no light";
        if (Run(additive, lit, keywords, dark, zero) && Run(additive, lit, keywords, unlit, none) &&
            zero.rgba.size() == none.rgba.size()) {
            float diff = 0;
            for (size_t i = 0; i < zero.rgba.size(); ++i) {
                diff = std::max(diff, std::abs(zero.rgba[i] - none.rgba[i]));
            }
            if (!(diff <= 1e-5f)) {
                h.Fail(c, keywords, dark.properties, "no-light",
                       "a light of intensity 0 changes the image by up to " + Describe(diff) +
                           " from the image without a light",
                       zero);
            }
        }
        for (const RangeProperty& r : Ranges()) {
            for (const auto& [value, end] : {std::pair{r.min, "min"}, {r.max, "max"}}) {
                Setup at;
                at.values[r.name] = {value};
                at.properties =
                    r.name + " = " + Describe(value) + " (Range " + std::string(end) + ")";
                Run(additive, lit, keywords, at, image);
            }
        }
    }

    std::vector<RangeProperty> Ranges() const {
        const pack::Pack& pk = h.renderer.pack(c.pack);
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

// Every variant of the packs (of --shader's shaders) that a path draws, each with the kind of
// pass it is; the others are counted in `h`'s skips with the reason.
std::vector<std::pair<Case, PassKind>> Cases(Harness& h) {
    const Renderer& renderer = h.renderer;
    std::vector<std::pair<Case, PassKind>> out;
    for (uint32_t p = 0; p < renderer.pack_count(); ++p) {
        const pack::Pack& pk = renderer.pack(p);
        for (uint32_t sh = 0; sh < pk.Count(pack::SectionTag::kShaders); ++sh) {
            const pack::ShaderRec sr = pk.Shader(sh).value();
            const std::string name(pk.String(sr.name));
            if (!h.options.shaders.empty() &&
                std::find(h.options.shaders.begin(), h.options.shaders.end(), name) ==
                    h.options.shaders.end()) {
                continue;
            }
            for (uint32_t pass = sr.first_pass; pass < sr.first_pass + sr.pass_count; ++pass) {
                const pack::PassRec rec = pk.Pass(pass).value();
                const std::optional<PassKind> kind = KindOf(pk, name, pass);
                for (uint32_t v = rec.first_variant; v < rec.first_variant + rec.variant_count;
                     ++v) {
                    const Case c{p, sh, pass, v};
                    const std::string why =
                        !kind ? "LightMode " + std::string(pack::LightModeOf(pk, pass)) +
                                    " is drawn by no path of the runtime"
                              : Unreachable(*kind, pk.String(rec.name), h.Keywords(c));
                    if (why.empty()) {
                        out.push_back({c, *kind});
                    } else {
                        h.Skip(c, why);
                    }
                }
            }
        }
    }
    if (h.options.sample && *h.options.sample < out.size()) {
        std::mt19937_64 rng(h.options.seed);
        std::shuffle(out.begin(), out.end(), rng);
        out.resize(*h.options.sample);
        std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
            return std::tie(a.first.pack, a.first.variant) <
                   std::tie(b.first.pack, b.first.variant);
        });
    }
    return out;
}

}  // namespace

std::string Describe(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

std::string CheckFinite(std::span<const float> values, uint32_t width, uint32_t channels) {
    size_t bad = 0, first = 0;
    for (size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i]) && bad++ == 0) {
            first = i / channels;
        }
    }
    if (bad == 0) {
        return "";
    }
    width = std::max(width, 1u);
    return std::to_string(bad) + " of " + std::to_string(values.size()) +
           " channel values are not finite (the first at pixel " + std::to_string(first % width) +
           ", " + std::to_string(first / width) + ")";
}

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

FrameSettings Harness::Settings(bool additive) const {
    FrameSettings f;
    f.width = f.height = options.size;
    f.camera = 0;
    f.background = glm::vec3(additive ? 0.25f : 0.0f);
    return f;
}

void Harness::Material(const Case& c, MaterialInstance& m) const {
    runtime::InstanceFromDefaults(renderer.pack(c.pack), c.pack, c.shader, color, m);
    // A main colour (`_Color`, Unity's Material.color) that defaults to black would hide every
    // lighting check (Ronja's tutorial shaders tint with black by default): the harness draws
    // it white.
    if (auto it = m.values.find("_Color"); it != m.values.end() && it->second.size() >= 3 &&
                                           it->second[0] == 0 && it->second[1] == 0 &&
                                           it->second[2] == 0) {
        it->second = {1, 1, 1, it->second.size() > 3 ? it->second[3] : 1};
    }
}

std::vector<std::string> Harness::Keywords(const Case& c) const {
    const pack::Pack& pk = renderer.pack(c.pack);
    return pk.KeywordsOf(c.pass, pack::VariantKey(pk.Variant(c.variant).value().key));
}

void Harness::Fail(const Case& c,
                   const std::vector<std::string>& keywords,
                   std::string properties,
                   std::string check,
                   std::string message,
                   LinearImage image) {
    const pack::Pack& pk = renderer.pack(c.pack);
    report.failures.push_back({runtime::tool_access::PackPath(renderer, c.pack),
                               std::string(pk.String(pk.Shader(c.shader).value().name)),
                               pack::PassLabel(pk, c.pass), keywords, std::move(properties),
                               std::move(check), std::move(message), std::move(image)});
}

void Harness::Skip(const Case& c, const std::string& reason) {
    const pack::Pack& pk = renderer.pack(c.pack);
    const std::string what = "shader \"" +
                             std::string(pk.String(pk.Shader(c.shader).value().name)) +
                             "\" pass \"" + pack::PassLabel(pk, c.pass) + "\": " + reason;
    auto it =
        std::find_if(skips.begin(), skips.end(), [&](const auto& s) { return s.first == what; });
    (it != skips.end() ? it->second : skips.emplace_back(what, 0).second) += 1;
}

void Harness::TestForward(const Case& c) {
    ForwardTest{*this, c}.Test();
}

Result<VariantTestReport> TestVariants(Renderer& renderer,
                                       const ColorPipeline& color,
                                       const VariantTestOptions& options) {
    if (renderer.pack_count() == 0) {
        return Error{DiagCode::kRenderFailed, "no variant pack loaded"};
    }
    if (options.size < 16 || options.size > 4096) {
        return Error{DiagCode::kBadCommandLine, "the harness image must be 16 to 4096 pixels"};
    }
    Harness h{renderer, color, options};
    if (Status e = runtime::ChooseCamera(h.scene, h.Settings(false), h.camera); !e.ok()) {
        return e.error();
    }
    for (const auto& [c, kind] : Cases(h)) {
        if (kind == PassKind::kForward) {
            h.TestForward(c);
        } else {
            h.TestOtherPass(kind, c);
        }
    }
    for (const auto& [what, variants] : h.skips) {
        h.report.skipped.push_back(what + " (" + std::to_string(variants) + " variant" +
                                   (variants == 1 ? ")" : "s)"));
        h.report.skipped_variants += variants;
    }
    return std::move(h.report);
}

}  // namespace kiln::tools
