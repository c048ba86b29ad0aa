// kiln report --scaling's files (kiln/tools/scaling.h): the table in Markdown, CSV and JSON, and
// the plot (GPU time against light count on logarithmic axes, one colour per object count, the
// forward path solid and the deferred path dashed), one cairo drawing for SVG and PNG.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "accuracy/cairo_output.h"
#include "kiln/base/files.h"
#include "kiln/runtime/color.h"
#include "kiln/tools/scaling.h"

namespace kiln::tools {
namespace {

namespace fs = std::filesystem;

double TimeOf(const ScalingRow& r) {
    return r.gpu_ms.median >= 0 ? r.gpu_ms.median : r.cpu_ms.median;
}

std::string Num(double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string Ms(const Spread& s) {
    return s.median < 0 ? "-" : Num(s.median, 3) + " (" + Num(s.min, 3) + "-" + Num(s.max, 3) + ")";
}

std::vector<uint32_t> Values(const ScalingReport& r, bool objects) {
    std::set<uint32_t> out;
    for (const ScalingRow& row : r.rows) {
        out.insert(objects ? row.objects : row.lights);
    }
    return {out.begin(), out.end()};
}

std::string CrossoverText(const ScalingReport& r, uint32_t objects) {
    const std::optional<uint32_t> c = Crossover(r, objects);
    if (!c) {
        return "forward faster at every light count measured";
    }
    if (*c == Values(r, false).front()) {
        return "deferred faster at every light count measured";
    }
    return "deferred faster from " + std::to_string(*c) + " lights";
}

std::string Markdown(const ScalingReport& r) {
    std::string md = "# Forward against deferred: time against objects and lights\n\n";
    md += "Device: " + r.device + ". Images " + std::to_string(r.width) + "x" +
          std::to_string(r.height) +
          ". Scenes: a grid of N spheres over a floor (N + 1 objects) lit by M ranged point "
          "lights, every light per pixel (kiln::tools::ScalingScene). Per scene, each path's "
          "first frame, then " +
          std::to_string(r.warmup) + " untimed and " + std::to_string(r.frames) +
          " timed rounds of one frame of each path in turn; median (min-max) of the timed "
          "frames. GPU: timestamp queries around each pass. CPU: from the Render call to the "
          "submission (planning, building and recording the draws).\n\n";
    md += "| objects | lights | path | draws | GPU ms | CPU ms | first frame ms |\n";
    md += "|---|---|---|---|---|---|---|\n";
    for (const ScalingRow& row : r.rows) {
        md += "| " + std::to_string(row.objects) + " | " + std::to_string(row.lights) + " | " +
              row.path + " | " + std::to_string(row.draws) + " | " + Ms(row.gpu_ms) + " | " +
              Ms(row.cpu_ms) + " | " + Num(row.first_frame_ms, 1) + " |\n";
    }
    md += "\nCrossover (GPU time; CPU where there is none):\n\n";
    for (uint32_t n : Values(r, true)) {
        md += "- " + std::to_string(n) + " objects: " + CrossoverText(r, n) + "\n";
    }
    md += "\n![GPU time against lights](scaling.png)\n";
    return md;
}

std::string Csv(const ScalingReport& r) {
    std::string csv =
        "objects,lights,path,draws,gpu_ms_median,gpu_ms_min,gpu_ms_max,cpu_ms_median,cpu_ms_min,"
        "cpu_ms_max,first_frame_ms\n";
    for (const ScalingRow& row : r.rows) {
        csv += std::to_string(row.objects) + "," + std::to_string(row.lights) + "," + row.path +
               "," + std::to_string(row.draws) + "," + Num(row.gpu_ms.median, 4) + "," +
               Num(row.gpu_ms.min, 4) + "," + Num(row.gpu_ms.max, 4) + "," +
               Num(row.cpu_ms.median, 4) + "," + Num(row.cpu_ms.min, 4) + "," +
               Num(row.cpu_ms.max, 4) + "," + Num(row.first_frame_ms, 2) + "\n";
    }
    return csv;
}

std::string Json(const ScalingReport& r) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    auto spread = [](const Spread& s) {
        return nlohmann::ordered_json{{"median", s.median}, {"min", s.min}, {"max", s.max}};
    };
    for (const ScalingRow& row : r.rows) {
        rows.push_back({{"objects", row.objects},
                        {"lights", row.lights},
                        {"path", row.path},
                        {"draws", row.draws},
                        {"gpu_ms", spread(row.gpu_ms)},
                        {"cpu_ms", spread(row.cpu_ms)},
                        {"first_frame_ms", row.first_frame_ms}});
    }
    nlohmann::ordered_json crossover = nlohmann::ordered_json::object();
    for (uint32_t n : Values(r, true)) {
        const std::optional<uint32_t> c = Crossover(r, n);
        crossover[std::to_string(n)] = c ? nlohmann::ordered_json(*c) : nlohmann::ordered_json();
    }
    const nlohmann::ordered_json doc = {
        {"kiln_scaling", 1},  {"device", r.device}, {"width", r.width}, {"height", r.height},
        {"frames", r.frames}, {"warmup", r.warmup}, {"rows", rows},     {"crossover", crossover}};
    return doc.dump(1) + "\n";
}

// The plot: log2 lights across, log10 milliseconds up.
void Draw(cairo_t* cr, const ScalingReport& r, double w, double h) {
    constexpr double kL = 80, kR = 190, kT = 48, kB = 60;
    const std::vector<uint32_t> lights = Values(r, false), objects = Values(r, true);
    double lo = 1e300, hi = 0;
    for (const ScalingRow& row : r.rows) {
        if (TimeOf(row) > 0) {
            lo = std::min(lo, TimeOf(row));
            hi = std::max(hi, TimeOf(row));
        }
    }
    if (!(hi > 0)) {
        lo = 0.1, hi = 1;
    }
    const double y0 = std::pow(10.0, std::floor(std::log10(lo)));
    const double y1 = std::pow(10.0, std::ceil(std::log10(hi * 1.05)));
    const double x0 = std::log2(double(std::max(lights.front(), 1u)));
    const double x1 = std::max(std::log2(double(std::max(lights.back(), 1u))), x0 + 1);
    auto X = [&](double l) {
        return kL + (w - kL - kR) * (std::log2(std::max(l, 1.0)) - x0) / (x1 - x0);
    };
    auto Y = [&](double ms) {
        return h - kB -
               (h - kT - kB) * (std::log10(std::max(ms, y0)) - std::log10(y0)) /
                   (std::log10(y1) - std::log10(y0));
    };
    auto text = [&](const std::string& s, double x, double y, double size, bool bold = false) {
        cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                               bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr, size);
        cairo_text_extents_t te;
        cairo_text_extents(cr, s.c_str(), &te);
        cairo_move_to(cr, x, y);
        cairo_show_text(cr, s.c_str());
        return te.x_advance;
    };
    auto line = [&](double ax, double ay, double bx, double by, double width) {
        cairo_set_line_width(cr, width);
        cairo_move_to(cr, ax, ay);
        cairo_line_to(cr, bx, by);
        cairo_stroke(cr);
    };
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text("Frame time against lights, forward (solid) and deferred (dashed)", kL, 26, 15, true);
    line(kL, kT, kL, h - kB, 1.2);
    line(kL, h - kB, w - kR, h - kB, 1.2);
    for (uint32_t l : lights) {
        line(X(l), h - kB, X(l), h - kB + 5, 1);
        text(std::to_string(l), X(l) - 8, h - kB + 18, 11);
    }
    for (double d = y0; d <= y1 * 1.0001; d *= 10) {
        line(kL - 5, Y(d), kL, Y(d), 1);
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", d);
        text(buf, kL - 10 - 7.0 * double(std::string(buf).size()), Y(d) + 4, 11);
    }
    const bool gpu = !r.rows.empty() && r.rows[0].gpu_ms.median >= 0;
    text("point lights (log scale)", (kL + w - kR) / 2 - 70, h - 18, 12);
    cairo_save(cr);
    cairo_translate(cr, 22, (kT + h - kB) / 2 + 110);
    cairo_rotate(cr, -M_PI / 2);
    text(std::string(gpu ? "GPU" : "CPU") + " ms per frame (log scale)", 0, 0, 12);
    cairo_restore(cr);
    static const double kColours[][3] = {{0.12, 0.47, 0.71}, {0.84, 0.15, 0.16},
                                         {0.17, 0.63, 0.17}, {0.58, 0.40, 0.74},
                                         {1.00, 0.50, 0.05}, {0.55, 0.34, 0.29}};
    for (size_t k = 0; k < objects.size(); ++k) {
        const double* c = kColours[k % 6];
        for (const char* path : {"forward", "deferred"}) {
            const bool dashed = std::string(path) == "deferred";
            const double dash[] = {7, 5};
            cairo_set_dash(cr, dash, dashed ? 2 : 0, 0);
            cairo_set_source_rgb(cr, c[0], c[1], c[2]);
            cairo_set_line_width(cr, 2);
            bool first = true;
            for (const ScalingRow& row : r.rows) {
                if (row.objects == objects[k] && row.path == path && TimeOf(row) > 0) {
                    first ? cairo_move_to(cr, X(row.lights), Y(TimeOf(row)))
                          : cairo_line_to(cr, X(row.lights), Y(TimeOf(row)));
                    first = false;
                }
            }
            cairo_stroke(cr);
            cairo_set_dash(cr, nullptr, 0, 0);
        }
        // The legend: one line per object count.
        const double ly = kT + 10 + 20 * double(k);
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        line(w - kR + 14, ly - 4, w - kR + 44, ly - 4, 2.5);
        cairo_set_source_rgb(cr, 0, 0, 0);
        text(std::to_string(objects[k]) + " objects", w - kR + 52, ly, 11);
    }
    const double ly = kT + 20 + 20 * double(objects.size());
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    line(w - kR + 14, ly - 4, w - kR + 44, ly - 4, 2);
    text("forward", w - kR + 52, ly, 11);
    const double dash[] = {7, 5};
    cairo_set_dash(cr, dash, 2, 0);
    line(w - kR + 14, ly + 16, w - kR + 44, ly + 16, 2);
    cairo_set_dash(cr, nullptr, 0, 0);
    text("deferred", w - kR + 52, ly + 20, 11);
}

}  // namespace

std::string ScalingPlotSvg(const ScalingReport& r) {
    std::string desc =
        "GPU milliseconds per frame against point lights, forward solid and "
        "deferred dashed, one colour per object count; crossover:";
    for (uint32_t n : Values(r, true)) {
        desc += " " + std::to_string(n) + " objects, " + CrossoverText(r, n) + ";";
    }
    return CairoSvg([&](cairo_t* cr, double w, double h) { Draw(cr, r, w, h); }, 960, 600,
                    "Frame time against lights, forward and deferred", desc);
}

std::vector<uint8_t> ScalingPlotImage(const ScalingReport& r, uint32_t width, uint32_t height) {
    return CairoImage([&](cairo_t* cr, double w, double h) { Draw(cr, r, w, h); }, width, height);
}

Status WriteScalingReport(const ScalingReport& r, const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        return Error{DiagCode::kCannotWriteFile,
                     dir + ": cannot create the folder: " + ec.message()};
    }
    const base::WriteOptions replace_links{.follow_symlinks = false};
    for (const auto& [name, text] : {std::pair<std::string, std::string>{"scaling.md", Markdown(r)},
                                     {"scaling.csv", Csv(r)},
                                     {"scaling.json", Json(r)},
                                     {"scaling.svg", ScalingPlotSvg(r)}}) {
        if (Status e =
                base::WriteFileAtomically((fs::path(dir) / name).string(), text, replace_links);
            !e.ok()) {
            return e;
        }
    }
    return runtime::WritePng((fs::path(dir) / "scaling.png").string(), 960, 600,
                             ScalingPlotImage(r, 960, 600), replace_links);
}

}  // namespace kiln::tools
