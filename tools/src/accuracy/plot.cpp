// The report's plot: FLIP mean (y) against time per frame (x), one point per configuration
// numbered as the table's rows, the Pareto front joined in time order. SVG with text; the PNG is
// rasterised here (no font library): axes, ticks, points and the rows' numbers in a 3x5 digit
// font.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "kiln/tools/accuracy_report.h"

namespace kiln::tools {
namespace {

struct Layout {
    double width, height;
    double left = 70, right = 30, top = 40, bottom = 55;
    double time_max = 1, flip_max = 0.01;

    double X(double ms) const { return left + (width - left - right) * ms / time_max; }
    double Y(double flip) const {
        return height - bottom - (height - top - bottom) * flip / flip_max;
    }
};

double TimeOf(const AccuracyRow& row) {
    return row.gpu_ms.median >= 0 ? row.gpu_ms.median : row.cpu_ms.median;
}

// A round step for about five ticks up to `max`.
double TickStep(double max) {
    const double raw = max / 5.0;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (raw <= m * p) {
            return m * p;
        }
    }
    return 10 * p;
}

Layout LayoutOf(const AccuracyReport& r, double width, double height) {
    Layout l{width, height};
    for (const AccuracyRow& row : r.rows) {
        l.time_max = std::max(l.time_max, TimeOf(row));
        l.flip_max = std::max(l.flip_max, row.flip);
    }
    l.time_max =
        TickStep(l.time_max * 1.1) * std::ceil(l.time_max * 1.1 / TickStep(l.time_max * 1.1));
    l.flip_max =
        TickStep(l.flip_max * 1.1) * std::ceil(l.flip_max * 1.1 / TickStep(l.flip_max * 1.1));
    return l;
}

std::vector<const AccuracyRow*> Front(const AccuracyReport& r) {
    std::vector<const AccuracyRow*> front;
    for (const AccuracyRow& row : r.rows) {
        if (row.pareto) {
            front.push_back(&row);
        }
    }
    std::sort(front.begin(), front.end(),
              [](const AccuracyRow* a, const AccuracyRow* b) { return TimeOf(*a) < TimeOf(*b); });
    return front;
}

std::string F(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// The rasteriser: an RGBA8 canvas with lines, discs and digits.
struct Canvas {
    uint32_t w, h;
    std::vector<uint8_t> px;

    void Dot(int x, int y, std::array<uint8_t, 3> c) {
        if (x < 0 || y < 0 || x >= int(w) || y >= int(h)) {
            return;
        }
        uint8_t* p = &px[(size_t(y) * w + size_t(x)) * 4];
        p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
    }
    void Line(double x0, double y0, double x1, double y1, std::array<uint8_t, 3> c, int thick) {
        const int steps = int(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
        for (int i = 0; i <= steps; ++i) {
            const double t = double(i) / steps;
            const int x = int(std::lround(x0 + (x1 - x0) * t)),
                      y = int(std::lround(y0 + (y1 - y0) * t));
            for (int dy = 0; dy < thick; ++dy) {
                for (int dx = 0; dx < thick; ++dx) {
                    Dot(x + dx - thick / 2, y + dy - thick / 2, c);
                }
            }
        }
    }
    void Disc(double cx, double cy, double r, std::array<uint8_t, 3> c) {
        for (int y = int(cy - r) - 1; y <= int(cy + r) + 1; ++y) {
            for (int x = int(cx - r) - 1; x <= int(cx + r) + 1; ++x) {
                if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) {
                    Dot(x, y, c);
                }
            }
        }
    }
    // Digits and '.', each 3x5 cells of `scale` pixels, the text's top left at (x, y).
    void Text(int x, int y, const std::string& s, int scale, std::array<uint8_t, 3> c) {
        static constexpr uint16_t kGlyphs[11] = {0x7B6F, 0x2C97, 0x73E7, 0x73CF, 0x5BC9, 0x79CF,
                                                 0x79EF, 0x7249, 0x7BEF, 0x7BCF, 0x0002};
        for (char ch : s) {
            const int g = ch == '.' ? 10 : ch - '0';
            if (g >= 0 && g <= 10) {
                for (int row = 0; row < 5; ++row) {
                    for (int col = 0; col < 3; ++col) {
                        if (kGlyphs[g] >> (14 - (row * 3 + col)) & 1) {
                            for (int k = 0; k < scale * scale; ++k) {
                                Dot(x + col * scale + k % scale, y + row * scale + k / scale, c);
                            }
                        }
                    }
                }
            }
            x += 4 * scale;
        }
    }
};

}  // namespace

std::string AccuracyPlotSvg(const AccuracyReport& r) {
    const Layout l = LayoutOf(r, 800, 500);
    const bool gpu = !r.rows.empty() && r.rows[0].gpu_ms.median >= 0;
    std::string svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"500\" "
        "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"800\" height=\"500\" "
        "fill=\"white\"/>\n";
    svg += "<text x=\"400\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">FLIP against " +
           std::string(gpu ? "GPU" : "CPU") + " time: " + r.scene + "</text>\n";
    const double x0 = l.X(0), y0 = l.Y(0);
    svg += "<path d=\"M" + F(x0) + " " + F(l.Y(l.flip_max)) + " V" + F(y0) + " H" +
           F(l.X(l.time_max)) + "\" stroke=\"black\" fill=\"none\"/>\n";
    for (double t = 0; t <= l.time_max * 1.0001; t += TickStep(l.time_max)) {
        svg += "<line x1=\"" + F(l.X(t)) + "\" y1=\"" + F(y0) + "\" x2=\"" + F(l.X(t)) +
               "\" y2=\"" + F(y0 + 5) + "\" stroke=\"black\"/><text x=\"" + F(l.X(t)) + "\" y=\"" +
               F(y0 + 18) + "\" text-anchor=\"middle\">" + F(t) + "</text>\n";
    }
    for (double f = 0; f <= l.flip_max * 1.0001; f += TickStep(l.flip_max)) {
        svg += "<line x1=\"" + F(x0 - 5) + "\" y1=\"" + F(l.Y(f)) + "\" x2=\"" + F(x0) +
               "\" y2=\"" + F(l.Y(f)) + "\" stroke=\"black\"/><text x=\"" + F(x0 - 8) + "\" y=\"" +
               F(l.Y(f) + 4) + "\" text-anchor=\"end\">" + F(f) + "</text>\n";
    }
    svg += "<text x=\"" + F((l.left + l.width - l.right) / 2) + "\" y=\"" + F(l.height - 12) +
           "\" text-anchor=\"middle\">" + (gpu ? "GPU" : "CPU") +
           " ms per frame (median)</text>\n<text transform=\"translate(16 " +
           F((l.top + l.height - l.bottom) / 2) +
           ") rotate(-90)\" text-anchor=\"middle\">mean FLIP against the reference</text>\n";
    std::string front;
    for (const AccuracyRow* row : Front(r)) {
        front += (front.empty() ? "M" : " L") + F(l.X(TimeOf(*row))) + " " + F(l.Y(row->flip));
    }
    if (!front.empty()) {
        svg += "<path d=\"" + front + "\" stroke=\"#d62728\" stroke-width=\"2\" fill=\"none\"/>\n";
    }
    for (size_t i = 0; i < r.rows.size(); ++i) {
        const AccuracyRow& row = r.rows[i];
        const double x = l.X(TimeOf(row)), y = l.Y(row.flip);
        svg += "<circle cx=\"" + F(x) + "\" cy=\"" + F(y) + "\" r=\"5\" fill=\"" +
               (row.pareto ? "#d62728" : "#1f77b4") + "\"/><text x=\"" + F(x + 8) + "\" y=\"" +
               F(y - 6) + "\">" + std::to_string(i + 1) + " " + row.config.name +
               (row.config.label.empty() ? "" : " (" + row.config.label + ")") + "</text>\n";
    }
    svg += "<text x=\"" + F(l.width - l.right) + "\" y=\"" + F(l.top) +
           "\" text-anchor=\"end\" fill=\"#d62728\">red: the Pareto front</text>\n</svg>\n";
    return svg;
}

std::vector<uint8_t> AccuracyPlotImage(const AccuracyReport& r, uint32_t width, uint32_t height) {
    Canvas c{width, height, std::vector<uint8_t>(size_t(width) * height * 4, 255)};
    const Layout l = LayoutOf(r, width, height);
    const std::array<uint8_t, 3> black{0, 0, 0}, red{214, 39, 40}, blue{31, 119, 180};
    c.Line(l.X(0), l.Y(0), l.X(l.time_max), l.Y(0), black, 2);
    c.Line(l.X(0), l.Y(0), l.X(0), l.Y(l.flip_max), black, 2);
    for (double t = 0; t <= l.time_max * 1.0001; t += TickStep(l.time_max)) {
        c.Line(l.X(t), l.Y(0), l.X(t), l.Y(0) + 6, black, 1);
        const std::string s = F(t);
        c.Text(int(l.X(t)) - int(s.size()) * 4, int(l.Y(0)) + 10, s, 2, black);
    }
    for (double f = 0; f <= l.flip_max * 1.0001; f += TickStep(l.flip_max)) {
        c.Line(l.X(0) - 6, l.Y(f), l.X(0), l.Y(f), black, 1);
        const std::string s = F(f);
        c.Text(int(l.X(0)) - 10 - int(s.size()) * 8, int(l.Y(f)) - 5, s, 2, black);
    }
    const std::vector<const AccuracyRow*> front = Front(r);
    for (size_t i = 1; i < front.size(); ++i) {
        c.Line(l.X(TimeOf(*front[i - 1])), l.Y(front[i - 1]->flip), l.X(TimeOf(*front[i])),
               l.Y(front[i]->flip), red, 2);
    }
    for (size_t i = 0; i < r.rows.size(); ++i) {
        const AccuracyRow& row = r.rows[i];
        const double x = l.X(TimeOf(row)), y = l.Y(row.flip);
        c.Disc(x, y, 5, row.pareto ? red : blue);
        c.Text(int(x) + 8, int(y) - 14, std::to_string(i + 1), 2, black);
    }
    return c.px;
}

}  // namespace kiln::tools
