// TestTemplateStability (kiln/tools/template_stability.h): the grids, their CPU reference and
// the comparison. The grid harness decodes pixel i into axis values exactly as Decode() below.
#include "kiln/tools/template_stability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

#include <glm/geometric.hpp>

#include "harness/harness_scene.h"
#include "kiln/pack/engine_names.h"
#include "kiln/reference/attenuation.h"
#include "kiln/reference/brdf.h"
#include "kiln/reference/brdf_choices.h"
#include "kiln/reference/classic_lighting.h"
#include "kiln/reference/guards.h"
#include "kiln/reference/sh.h"
#include "kiln/reference/unity_terms.h"
#include "kiln/reference/white_furnace.h"

namespace kiln::tools {

using runtime::ColorPipeline;
using runtime::FrameSettings;
using runtime::LinearImage;
using runtime::Renderer;
namespace {

using glm::dvec3;

// One axis: what the device gets (`gpu`), what the reference gets (`ref`), and how to print it.
struct Axis {
    std::string name;
    std::vector<float> gpu;
    std::vector<double> ref;
    std::vector<std::string> labels;
};

Axis Plain(std::string name, std::vector<double> values) {
    Axis a{std::move(name), {}, {}, {}};
    for (double v : values) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", v);
        a.gpu.push_back(float(v));
        a.ref.push_back(double(float(v)));  // the device's input exactly
        a.labels.push_back(buf);
    }
    return a;
}

struct GridCase {
    std::string name, functions;
    std::vector<Axis> axes;  // up to 4, up to 8 values each
    double bound = 0;
    // `flush`: denormal inputs as zero. Vulkan lets fp32 shader arithmetic flush denormals, so a
    // denormal input is compared with both references and the closer counts.
    std::function<dvec3(const double in[4], bool flush)> reference;
    int channels = 3;
    // The bound of a --precision half build, where the case computes in binary16; 0: `bound`.
    double half_bound = 0;
};

constexpr double kDenormal = 1e-40;

dvec3 WithCosine(double c, double phi) {
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    return {s * std::cos(phi), s * std::sin(phi), c};
}

// The harness's light-direction code (KilnStabilityGrid.shader LightDirection).
dvec3 LightDirection(double code, const dvec3& v, bool flush) {
    if (code <= 1.0)
        return WithCosine(code, 2.0);
    if (code == 2.0)
        return v;
    if (code == 3.0)
        return -v;
    if (code == 4.0)
        return dvec3(0.0);
    return flush ? dvec3(0.0) : dvec3(kDenormal, 0.0, kDenormal);
}

Axis CosineAxis(const char* name) {
    return Plain(name, {-1.0, 0.0, 1e-7, 1.0});
}

Axis LightAxis() {
    Axis a = Plain("light", {-1.0, 0.0, 1e-7, 1.0, 2.0, 3.0, 4.0, 5.0});
    a.labels = {"n . l = -1", "n . l = 0", "n . l = 1e-07", "n . l = 1",
                "l = v",      "l = -v",    "l = 0",         "l denormal"};
    return a;
}

Axis IntensityAxis(const char* name) {
    return Plain(name, {0.0, 1.0, 6.6e4, 1e9, 3.4e38});
}

std::vector<GridCase> Cases() {
    std::vector<GridCase> cases;
    const dvec3 n(0.0, 0.0, 1.0);
    cases.push_back(
        {"BRDF1_Unity_PBS",
         "diffuse + GGX D, Smith V, Schlick F specular + indirect, clamped to the binary16 range",
         {CosineAxis("n . v"), LightAxis(),
          Plain("perceptual roughness", {0.0, 1e-7, 0.045, 0.089, 0.5, 1.0}),
          IntensityAxis("light colour")},
         1e-3,
         [n](const double in[4], bool flush) {
             reference::StandardInputs s;
             s.diffuse_color = s.specular_color = dvec3(0.5);
             s.one_minus_reflectivity = 0.5;
             s.normal = n;
             s.view_dir = WithCosine(in[0], 0.0);
             s.light_dir = LightDirection(in[1], s.view_dir, flush);
             s.light_color = dvec3(in[3]);
             s.indirect_diffuse = s.indirect_specular = dvec3(0.1);
             s.smoothness = double(1.0f - float(in[2]));  // as the device computes it
             return reference::StandardBrdf(s);
         }});
    cases.push_back(
        {"GGX terms",
         "r: D_GGX(a); g: V_SmithGGXCorrelated(max(a, 1e-5), b); b: F_Schlick(0.04, a), "
         "roughness through PerceptualRoughnessToRoughness",
         {Plain("n . h = n . v", {0.0, 1e-7, 0.5, 0.999, 1.0}),
          Plain("n . l", {0.0, 1e-7, 0.5, 1.0}),
          Plain("perceptual roughness", {0.0, 1e-7, 0.045, 0.089, 0.5, 1.0})},
         1e-3,
         [](const double in[4], bool) {
             const double alpha = reference::RoughnessFromSmoothness(1.0 - in[2]);
             return dvec3(reference::D_GGX(in[0], alpha),
                          reference::V_SmithGGXCorrelated(std::max(in[0], 1e-5), in[1], alpha),
                          reference::F_Schlick(dvec3(0.04), in[0]).x);
         }});
    cases.push_back(
        {"BRDF choices",
         "r: D_BlinnPhong(a); g: V_SmithGGXCorrelatedFast(max(a, 1e-5), b); b: "
         "F_Exact(0.04, a)",
         cases.back().axes, 1e-3, [](const double in[4], bool) {
             const double alpha = reference::RoughnessFromSmoothness(1.0 - in[2]);
             return dvec3(reference::D_BlinnPhong(in[0], alpha),
                          reference::V_SmithGGXCorrelatedFast(std::max(in[0], 1e-5), in[1], alpha),
                          reference::F_Exact(0.04, in[0]));
         }});
    cases.push_back(
        {"Blinn-Phong",
         "r: BlinnPhong_Specular(1, C, n, BlinnPhong_HalfVector(l, v), e); g: Lambert_Diffuse",
         {CosineAxis("n . v"), LightAxis(), Plain("exponent e", {0.0, 1e-7, 1.0, 100.0, 1e4}),
          IntensityAxis("light colour")},
         1e-3,
         [n](const double in[4], bool flush) {
             const dvec3 v = WithCosine(in[0], 0.0), l = LightDirection(in[1], v, flush);
             const dvec3 c(in[3]);
             const dvec3 h = reference::BlinnPhongHalfVector(l, v);
             return dvec3(reference::BlinnPhongSpecular(dvec3(1.0), c, n, h, in[2]).x,
                          reference::LambertDiffuse(dvec3(1.0), c, n, l).y, 0.0);
         }});
    Axis range = Plain("range", {0.0, -1.0, 1e-6, 1.0, 1e6});
    for (size_t i = 0; i < range.ref.size(); ++i) {
        // What the runtime passes: 1 / range^2, 0 for an unlimited range (kiln_LightParams0.x).
        range.gpu[i] = float(reference::InverseRangeSquared(range.ref[i]));
    }
    cases.push_back({"Attenuation",
                     "r: Attenuation_Distance; g: Attenuation_InverseSquare; b: "
                     "Attenuation_RangeWindow",
                     {Plain("distance", {0.0, 1e-6, 1e-3, 1.0, 2.0, 1e6}), range},
                     1e-3,
                     [](const double in[4], bool) {
                         return dvec3(reference::DistanceAttenuation(in[0], in[1]),
                                      reference::InverseSquare(in[0]),
                                      reference::RangeWindow(in[0], in[1]));
                     },
                     3});
    auto cone = [](const char* name) {
        Axis a = Plain(name, {0.0, 0.3, 0.5, 0.6, 1.6, 3.0});
        for (size_t i = 0; i < a.ref.size(); ++i) {
            a.gpu[i] = std::cos(float(a.ref[i]));  // the runtime passes cosines
        }
        return a;
    };
    cases.push_back({"Attenuation_SpotCone",
                     "r: the cone factor (inner = outer and inner > outer included)",
                     {Plain("cosine to the axis", {-1.0, 0.0, 0.8, 0.9, 0.95, 1.0}),
                      cone("outer angle"), cone("inner angle")},
                     1e-3,
                     [](const double in[4], bool) {
                         return dvec3(reference::SpotCone(in[0], in[1], in[2]), 0.0, 0.0);
                     },
                     1});
    Axis normal = Plain("normal n . z", {-1.0, -0.5, 0.0, 1e-7, 0.5, 1.0, 2.0, 3.0});
    normal.labels[6] = "n = 0";
    normal.labels[7] = "n denormal";
    cases.push_back(
        {"SH_Irradiance",
         "rgb: irradiance / pi of a bright directional light plus a dim constant",
         {normal, Plain("azimuth", {0.0, 1.0, 2.5, 4.0}), IntensityAxis("coefficient scale")},
         1e-3,
         nullptr});
    // Case 7: binary16 arithmetic in a --precision half build (their parameters are half); the
    // bound there is 8 units of binary16 rounding (2^-11 each) over chains of a few operations.
    cases.push_back(
        {"Unity half terms",
         "r: DisneyDiffuse(a, b, d, c); g: SmithBeckmannVisibilityTerm(b, a, alpha); b: "
         "FresnelTerm(0.04, d)",
         {Plain("n . v", {0.0, 1e-7, 0.5, 1.0}), Plain("n . l", {0.0, 1e-7, 0.5, 1.0}),
          Plain("perceptual roughness", {0.0, 1e-7, 0.045, 0.089, 0.5, 1.0}),
          Plain("l . h", {0.0, 0.5, 1.0})},
         1e-3,
         [](const double in[4], bool) {
             const double alpha = reference::RoughnessFromSmoothness(1.0 - in[2]);
             return dvec3(
                 reference::DisneyDiffuse(in[0], in[1], in[3], in[2]),
                 0.25 * reference::SmithVisibility(in[1], in[0], reference::BeckmannK(alpha)),
                 reference::F_Schlick(dvec3(0.04), in[3]).x);
         },
         3,
         8.0 / 2048.0});
    return cases;
}

reference::PackedSH GridSH() {
    reference::SH9 sh;
    reference::AddDirectionalLight(sh, glm::normalize(dvec3(1.0, 0.5, 0.7)), dvec3(1.0, 0.8, 0.6));
    reference::AddConstantRadiance(sh, dvec3(0.05));
    return reference::PackSH9(sh);
}

// Distance in fp32 units between two finite floats (ordered as integers).
uint64_t UlpDistance(float a, float b) {
    auto ordered = [](float f) {
        int32_t i;
        std::memcpy(&i, &f, sizeof i);
        return i < 0 ? int64_t(INT32_MIN) - i : int64_t(i);
    };
    const int64_t d = ordered(a) - ordered(b);
    return uint64_t(d < 0 ? -d : d);
}

std::string Describe(const GridCase& c, const size_t j[4]) {
    std::string s;
    for (size_t k = 0; k < c.axes.size(); ++k) {
        if (!s.empty())
            s += ", ";
        s += c.axes[k].name + " " + c.axes[k].labels[j[k]];
    }
    return s;
}

}  // namespace

std::vector<EnergyReport> WhiteFurnaceReport() {
    const double cosines[] = {1e-3, 0.1, 0.5, 1.0};
    const double roughness[] = {0.045, 0.089, 0.25, 0.5, 1.0};
    // Lambert's albedo does not depend on the view: one integral.
    const EnergyReport lambert{"Lambert (Fd_Lambert)", reference::LambertAlbedo(), "every n . v"};
    EnergyReport ggx{"GGX, Smith, F = 1 (BRDF_Specular)", 0, ""};
    char where[96];
    for (double nv : cosines) {
        for (double p : roughness) {
            const double g = reference::GgxSmithAlbedo(nv, p * p);
            if (g > ggx.max_albedo) {
                std::snprintf(where, sizeof where, "n . v = %g, perceptual roughness %g", nv, p);
                ggx.max_albedo = g;
                ggx.where = where;
            }
        }
    }
    return {lambert, ggx};
}

Result<TemplateStabilityReport> TestTemplateStability(Renderer& renderer,
                                                      const ColorPipeline& color,
                                                      const TemplateStabilityOptions& options) {
    std::optional<uint32_t> shader;
    uint32_t pack_index = 0;
    for (; pack_index < renderer.pack_count(); ++pack_index) {
        if ((shader = renderer.pack(pack_index).FindShader(pack::kShaderStabilityGrid)))
            break;
    }
    if (!shader) {
        return Error{DiagCode::kBadCommandLine, std::string("no loaded pack has the shader \"") +
                                                    pack::kShaderStabilityGrid + "\""};
    }
    runtime::MaterialInstance m;
    runtime::InstanceFromDefaults(renderer.pack(pack_index), pack_index, *shader, color, m);
    m.name = "kiln stability grid";
    runtime::Scene scene = StabilityScene();
    scene.instances.pop_back();  // the plane alone fills the view
    const reference::PackedSH sh = GridSH();
    const char* sh_names[7] = {"_SHr", "_SHg", "_SHb", "_SHBr", "_SHBg", "_SHBb", "_SHCc"};
    for (size_t k = 0; k < 7; ++k) {
        m.values[sh_names[k]] = {sh[k][0], sh[k][1], sh[k][2], sh[k][3]};
    }
    TemplateStabilityReport report;
    std::vector<GridCase> cases = Cases();
    for (size_t ci = 0; ci < cases.size(); ++ci) {
        GridCase& c = cases[ci];
        size_t count[4] = {1, 1, 1, 1};
        for (size_t k = 0; k < c.axes.size(); ++k) {
            count[k] = c.axes[k].gpu.size();
            std::vector<float> lo(4, 0.0f), hi(4, 0.0f);
            for (size_t j = 0; j < count[k]; ++j) {
                (j < 4 ? lo[j] : hi[j - 4]) = c.axes[k].gpu[j];
            }
            m.values["_Axis" + std::to_string(k) + "Lo"] = lo;
            m.values["_Axis" + std::to_string(k) + "Hi"] = hi;
        }
        const size_t points = count[0] * count[1] * count[2] * count[3];
        const uint32_t side = uint32_t(std::ceil(std::sqrt(double(points))));
        m.values["_Grid"] = {float(side), float(points), float(ci), 0.0f};
        m.values["_Counts"] = {float(count[0]), float(count[1]), float(count[2]), float(count[3])};
        FrameSettings settings;
        settings.width = settings.height = std::max(side, 2u);
        settings.camera = 0;
        runtime::CameraSetup camera;
        if (Status e = runtime::ChooseCamera(scene, settings, camera); !e.ok())
            return e.error();
        HarnessPass draw;
        draw.material = &m;
        draw.pass = renderer.pack(pack_index).Shader(*shader).value().first_pass;
        draw.pixel_light = false;
        LinearImage image;
        if (Status e = DrawHarnessPass(renderer, color, scene, settings, camera, draw, image);
            !e.ok()) {
            return e.error();
        }
        GridCaseReport r;
        r.name = c.name;
        r.functions = c.functions;
        r.bound = options.precision == pack::Precision::kHalf && c.half_bound > 0 ? c.half_bound
                                                                                  : c.bound;
        r.points = points;
        for (const Axis& a : c.axes) {
            std::string values;
            for (const std::string& l : a.labels)
                values += (values.empty() ? "" : ", ") + l;
            r.axes.push_back(a.name + " {" + values + "}");
        }
        for (size_t i = 0; i < points; ++i) {
            const size_t j[4] = {i % count[0], i / count[0] % count[1],
                                 i / (count[0] * count[1]) % count[2],
                                 i / (count[0] * count[1] * count[2])};
            double in[4] = {0, 0, 0, 0};
            for (size_t k = 0; k < c.axes.size(); ++k)
                in[k] = c.axes[k].ref[j[k]];
            auto reference = [&](bool flush) {
                if (c.reference)
                    return c.reference(in, flush);
                // SH: the packed coefficients times the scale, in double
                reference::PackedSH scaled = sh;
                for (auto& row : scaled)
                    for (float& x : row)
                        x = float(double(x) * in[2]);
                const dvec3 nrm = in[0] <= 1.0            ? WithCosine(in[0], in[1])
                                  : in[0] == 2.0 || flush ? dvec3(0.0)
                                                          : dvec3(kDenormal, 0.0, kDenormal);
                return reference::EvalPackedSH(scaled, nrm);
            };
            const dvec3 want = reference(false), flushed = reference(true);
            const float* got = &image.rgba[(size_t(i / side) * image.width + i % side) * 4];
            for (int ch = 0; ch < c.channels; ++ch) {
                ++r.values;
                const char* channel[3] = {"r", "g", "b"};
                if (!std::isfinite(got[ch])) {
                    if (r.non_finite++ == 0) {
                        r.first_non_finite = Describe(c, j) + ": " + channel[ch] + " = " +
                                             (std::isnan(got[ch]) ? "NaN" : "infinity");
                    }
                    continue;
                }
                const double g = double(got[ch]);
                const double w =
                    std::abs(g - want[ch]) <= std::abs(g - flushed[ch]) ? want[ch] : flushed[ch];
                const double abs_err = std::abs(g - w);
                const double rel = abs_err / std::max(std::abs(w), 1e-3);
                r.max_abs = std::max(r.max_abs, abs_err);
                r.max_ulp = std::max(r.max_ulp, UlpDistance(got[ch], float(w)));
                if (rel > r.max_rel) {
                    r.max_rel = rel;
                    char buf[96];
                    std::snprintf(buf, sizeof buf, ": %s = %.7g, reference %.7g", channel[ch], g,
                                  w);
                    r.worst = Describe(c, j) + buf;
                }
            }
        }
        report.cases.push_back(std::move(r));
    }
    report.energy = WhiteFurnaceReport();
    return report;
}

}  // namespace kiln::tools
