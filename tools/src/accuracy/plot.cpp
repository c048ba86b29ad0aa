// The report's figure: mean FLIP (y) against time per frame (x), one point per configuration
// named by its table row and name, the Pareto front joined in time order. One drawing, made with
// cairo, renders both the PNG and the SVG (fonts through fontconfig: DejaVu Sans, installed by
// scripts/setup.sh). The FLIP axis is logarithmic where the worst value is more than 8 times the
// best; labels are placed around their point so that none overlaps another, a point, the legend
// or the edge (AccuracyPlotTexts gives their boxes to the test that checks it).
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "accuracy/cairo_output.h"
#include "kiln/tools/accuracy_report.h"

namespace kiln::tools {
namespace {

constexpr double kLeft = 84, kRight = 24, kTop = 48, kBottom = 62;
constexpr double kPoint = 5;  // a point's radius

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

std::string F(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// Where the axes put a value.
struct Axes {
    double width, height;
    double time_max = 1;
    bool log = false;
    double flip_min = 0, flip_max = 0.01;  // log: powers of ten around the values

    double X(double ms) const { return kLeft + (width - kLeft - kRight) * ms / time_max; }
    double Y(double flip) const {
        const double plot = height - kTop - kBottom;
        if (log) {
            const double f = std::max(flip, flip_min);
            return height - kBottom -
                   plot * (std::log10(f) - std::log10(flip_min)) /
                       (std::log10(flip_max) - std::log10(flip_min));
        }
        return height - kBottom - plot * flip / flip_max;
    }
};

Axes AxesOf(const AccuracyReport& r, double width, double height) {
    Axes a{width, height};
    double lo = 1e300, hi = 0;
    for (const AccuracyRow& row : r.rows) {
        a.time_max = std::max(a.time_max, TimeOf(row));
        if (row.flip > 0) {
            lo = std::min(lo, row.flip);
        }
        hi = std::max(hi, row.flip);
    }
    const double t = TickStep(a.time_max * 1.1);
    a.time_max = t * std::ceil(a.time_max * 1.1 / t);
    // The worst more than 8 times the best: a log axis, or the accurate configurations (most of
    // them) would sit in the bottom few percent of the plot, on the time axis.
    a.log = hi > 0 && lo < 1e300 && hi / lo > 8;
    if (a.log) {
        a.flip_min = std::pow(10.0, std::floor(std::log10(lo)));
        a.flip_max = std::pow(10.0, std::ceil(std::log10(hi * 1.05)));
    } else {
        a.flip_max = std::max(hi, 0.01);
        const double f = TickStep(a.flip_max * 1.1);
        a.flip_max = f * std::ceil(a.flip_max * 1.1 / f);
    }
    return a;
}

struct Box {
    double x, y, w, h;
    bool Overlaps(const Box& o) const {
        return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
    }
    bool Inside(double x0, double y0, double x1, double y1) const {
        return x >= x0 && y >= y0 && x + w <= x1 && y + h <= y1;
    }
};

// The drawing, with every text it drew and where.
class Figure {
  public:
    Figure(cairo_t* cr, const AccuracyReport& r, double w, double h)
        : cr_(cr), r_(r), a_(AxesOf(r, w, h)) {}

    std::vector<PlotText> Draw();

  private:
    // Draws `s` with its top-left corner at (x, y); returns its box.
    Box Text(const std::string& s, double x, double y, double size, bool bold = false) {
        cairo_select_font_face(cr_, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                               bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr_, size);
        cairo_font_extents_t fe;
        cairo_font_extents(cr_, &fe);
        cairo_text_extents_t te;
        cairo_text_extents(cr_, s.c_str(), &te);
        cairo_move_to(cr_, x, y + fe.ascent);
        cairo_show_text(cr_, s.c_str());
        return {x, y, te.x_advance, fe.ascent + fe.descent};
    }
    double TextWidth(const std::string& s, double size) {
        cairo_select_font_face(cr_, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                               CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr_, size);
        cairo_text_extents_t te;
        cairo_text_extents(cr_, s.c_str(), &te);
        return te.x_advance;
    }
    void Color(double r, double g, double b) { cairo_set_source_rgb(cr_, r, g, b); }
    void Line(double x0, double y0, double x1, double y1, double width) {
        cairo_set_line_width(cr_, width);
        cairo_move_to(cr_, x0, y0);
        cairo_line_to(cr_, x1, y1);
        cairo_stroke(cr_);
    }
    void AxesAndTicks();
    void Legend();
    void Points();

    cairo_t* cr_;
    const AccuracyReport& r_;
    Axes a_;
    std::vector<PlotText> texts_;
    std::vector<Box> taken_;  // points, labels and the legend: what a label must not cover
};

void Figure::AxesAndTicks() {
    const bool gpu = !r_.rows.empty() && r_.rows[0].gpu_ms.median >= 0;
    Color(0, 0, 0);
    const std::string title_text =
        (gpu ? "Mean FLIP against GPU time: " : "Mean FLIP against CPU time: ") + r_.scene;
    const Box title = Text(title_text, kLeft, 12, 15, true);
    texts_.push_back({"title", title_text, title.x, title.y, title.w, title.h, 0});
    const double x0 = a_.X(0), y0 = a_.Y(a_.log ? a_.flip_min : 0);
    Line(x0, a_.Y(a_.flip_max), x0, y0, 1.2);
    Line(x0, y0, a_.X(a_.time_max), y0, 1.2);
    for (double t = 0; t <= a_.time_max * 1.0001; t += TickStep(a_.time_max)) {
        Line(a_.X(t), y0, a_.X(t), y0 + 5, 1);
        const std::string s = F(t);
        Text(s, a_.X(t) - TextWidth(s, 11) / 2, y0 + 8, 11);
    }
    auto y_tick = [&](double f, bool labelled) {
        Line(x0 - (labelled ? 5 : 3), a_.Y(f), x0, a_.Y(f), 1);
        if (labelled) {
            const std::string s = F(f);
            Text(s, x0 - 8 - TextWidth(s, 11), a_.Y(f) - 7, 11);
        }
    };
    if (a_.log) {
        for (double decade = a_.flip_min; decade <= a_.flip_max * 1.0001; decade *= 10) {
            y_tick(decade, true);
            for (double m : {2.0, 5.0}) {
                if (decade * m < a_.flip_max) {
                    y_tick(decade * m, false);
                }
            }
        }
    } else {
        for (double f = 0; f <= a_.flip_max * 1.0001; f += TickStep(a_.flip_max)) {
            y_tick(f, true);
        }
    }
    const std::string x_title = std::string(gpu ? "GPU" : "CPU") +
                                " time per frame, ms (median of " + std::to_string(r_.frames) +
                                " frames)";
    const double plot_mid = (kLeft + a_.width - kRight) / 2;
    const Box xt = Text(x_title, plot_mid - TextWidth(x_title, 12) / 2, a_.height - 24, 12);
    texts_.push_back({"x-axis", x_title, xt.x, xt.y, xt.w, xt.h, 0});
    const std::string y_title = std::string("mean FLIP against the reference, 0 = identical") +
                                (a_.log ? " (log scale)" : "");
    cairo_save(cr_);
    const double y_mid = (kTop + a_.height - kBottom) / 2;
    cairo_translate(cr_, 14, y_mid + TextWidth(y_title, 12) / 2);
    cairo_rotate(cr_, -M_PI / 2);
    Text(y_title, 0, 0, 12);
    cairo_restore(cr_);
    texts_.push_back(
        {"y-axis", y_title, 14, y_mid - TextWidth(y_title, 12) / 2, 16, TextWidth(y_title, 12), 0});
}

void Figure::Legend() {
    const std::string front = "Pareto front: no other configuration is faster and more accurate";
    const std::string other = "other configurations";
    const double w = std::max(TextWidth(front, 11), TextWidth(other, 11)) + 30;
    const double x = a_.width - kRight - w - 6, y = kTop;
    Color(1, 1, 1);
    cairo_rectangle(cr_, x, y, w, 40);
    cairo_fill(cr_);
    Color(0.6, 0.6, 0.6);
    cairo_set_line_width(cr_, 1);
    cairo_rectangle(cr_, x, y, w, 40);
    cairo_stroke(cr_);
    const double rows[2][3] = {{0.84, 0.15, 0.16}, {0.12, 0.47, 0.71}};
    for (int i = 0; i < 2; ++i) {
        Color(rows[i][0], rows[i][1], rows[i][2]);
        cairo_arc(cr_, x + 12, y + 12 + 16 * i, 4.5, 0, 2 * M_PI);
        cairo_fill(cr_);
        Color(0, 0, 0);
        Text(i == 0 ? front : other, x + 22, y + 5 + 16 * i, 11);
    }
    taken_.push_back({x, y, w, 40});
    texts_.push_back({"legend", front + "; " + other, x, y, w, 40, 0});
}

void Figure::Points() {
    std::vector<const AccuracyRow*> front;
    for (const AccuracyRow& row : r_.rows) {
        if (row.pareto) {
            front.push_back(&row);
        }
        taken_.push_back({a_.X(TimeOf(row)) - kPoint - 1, a_.Y(row.flip) - kPoint - 1,
                          2 * kPoint + 2, 2 * kPoint + 2});
    }
    std::sort(front.begin(), front.end(),
              [](const AccuracyRow* a, const AccuracyRow* b) { return TimeOf(*a) < TimeOf(*b); });
    Color(0.84, 0.15, 0.16);
    cairo_set_line_width(cr_, 2);
    for (size_t i = 0; i < front.size(); ++i) {
        const double x = a_.X(TimeOf(*front[i])), y = a_.Y(front[i]->flip);
        i == 0 ? cairo_move_to(cr_, x, y) : cairo_line_to(cr_, x, y);
    }
    cairo_stroke(cr_);
    for (const AccuracyRow& row : r_.rows) {
        row.pareto ? Color(0.84, 0.15, 0.16) : Color(0.12, 0.47, 0.71);
        cairo_arc(cr_, a_.X(TimeOf(row)), a_.Y(row.flip), kPoint, 0, 2 * M_PI);
        cairo_fill(cr_);
    }
    // Each label at the first place around its point, nearest first, that covers nothing placed
    // yet and stays in the plot; farther than the nearest ring, a leader line joins it.
    const double x_min = kLeft + 2, y_min = kTop, x_max = a_.width - kRight,
                 y_max = a_.height - kBottom - 2;
    for (size_t i = 0; i < r_.rows.size(); ++i) {
        const AccuracyRow& row = r_.rows[i];
        const std::string s = std::to_string(i + 1) + " " + row.config.name;
        const double w = TextWidth(s, 11), h = 14;
        const double px = a_.X(TimeOf(row)), py = a_.Y(row.flip);
        Box chosen{px + 8, py - h - 2, w, h};
        bool found = false;
        for (int ring = 1; ring <= 12 && !found; ++ring) {
            const double d = 8 + (ring - 1) * 12;
            for (int k = 0; k < 16 && !found; ++k) {
                const double angle = -M_PI / 4 + k * M_PI / 8;
                const double cx = px + std::cos(angle) * d, cy = py - std::sin(angle) * d;
                // The box hangs off the point on the side it lies.
                const Box b{std::cos(angle) >= -1e-9 ? cx : cx - w,
                            std::sin(angle) >= -1e-9 ? cy - h : cy, w, h};
                if (!b.Inside(x_min, y_min, x_max, y_max)) {
                    continue;
                }
                if (std::none_of(taken_.begin(), taken_.end(),
                                 [&](const Box& t) { return t.Overlaps(b); })) {
                    chosen = b;
                    found = true;
                    if (ring > 1) {  // a leader from the point to the label's nearest corner
                        Color(0.55, 0.55, 0.55);
                        const double lx = std::clamp(px, b.x, b.x + b.w);
                        const double ly = std::clamp(py, b.y, b.y + b.h);
                        Line(px, py, lx, ly, 0.8);
                    }
                }
            }
        }
        Color(0, 0, 0);
        Text(s, chosen.x, chosen.y, 11);
        taken_.push_back(chosen);
        texts_.push_back({"label", s, chosen.x, chosen.y, chosen.w, chosen.h, i});
    }
}

std::vector<PlotText> Figure::Draw() {
    Color(1, 1, 1);
    cairo_paint(cr_);
    AxesAndTicks();
    Legend();
    Points();
    return texts_;
}

}  // namespace

std::vector<PlotText> AccuracyPlotTexts(const AccuracyReport& r, double width, double height) {
    cairo_surface_t* surface = cairo_recording_surface_create(CAIRO_CONTENT_COLOR, nullptr);
    cairo_t* cr = cairo_create(surface);
    std::vector<PlotText> texts = Figure(cr, r, width, height).Draw();
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    return texts;
}

std::string AccuracyPlotSvg(const AccuracyReport& r) {
    std::vector<PlotText> texts;
    auto draw = [&](cairo_t* cr, double w, double h) { texts = Figure(cr, r, w, h).Draw(); };
    // The texts first (the SVG's title and description), from a recording of the same drawing.
    texts = AccuracyPlotTexts(r, 960, 600);
    std::string title, desc;
    for (const PlotText& t : texts) {
        if (t.kind == "title") {
            title = t.text;
        } else {
            desc += (desc.empty() ? "" : "; ") + t.kind + ": " + t.text;
        }
    }
    return CairoSvg(draw, 960, 600, title, desc);
}

std::vector<uint8_t> AccuracyPlotImage(const AccuracyReport& r, uint32_t width, uint32_t height) {
    return CairoImage([&](cairo_t* cr, double w, double h) { Figure(cr, r, w, h).Draw(); }, width,
                      height);
}

}  // namespace kiln::tools
