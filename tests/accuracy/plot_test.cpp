// The report's figure (tools/src/accuracy/plot.cpp): one cairo drawing for the PNG and the SVG,
// axis titles with units, a log FLIP axis where the values span decades, and labels that cover
// neither each other, a point, the legend nor the edge, on a crowded synthetic report (13
// configurations, eight of them within a few pixels of each other, as the default report's light
// modes are).
#include <gtest/gtest.h>

#include "kiln/tools/accuracy_report.h"

namespace kiln::test {
namespace {

using tools::AccuracyReport;
using tools::AccuracyRow;
using tools::PlotText;

AccuracyReport Crowded(double flip_spread) {
    AccuracyReport r;
    r.scene = "scenes/demo/demo.gltf";
    r.frames = 10;
    const char* names[13] = {"pixel",      "auto-4",         "auto-2",       "auto-1",
                             "auto-0",     "vertex",         "sh",           "deferred",
                             "deferred-8", "deferred-8-oct", "deferred-16f", "deferred-oct",
                             "auto-4-fp16"};
    for (int i = 0; i < 13; ++i) {
        AccuracyRow row;
        row.config.name = names[i];
        // Eight configurations bunched at 10-11 ms and low error, the rest spread out.
        row.gpu_ms.median = i < 8 ? 10.0 + 0.1 * i : 4.0 + 2.5 * (i - 8);
        row.flip = i < 8 ? 0.004 + 0.0002 * i : 0.004 * std::pow(flip_spread, (i - 7) / 5.0);
        row.pareto = i == 0 || i == 8 || i == 12;
        r.rows.push_back(row);
    }
    return r;
}

TEST(AccuracyPlot, LabelsCoverNothingAndTheAxesSayWhatAndInWhatUnit) {
    for (double spread : {2.0, 200.0}) {
        SCOPED_TRACE(spread);
        const AccuracyReport r = Crowded(spread);
        const std::vector<PlotText> texts = tools::AccuracyPlotTexts(r, 960, 600);
        std::vector<PlotText> labels;
        const PlotText* legend = nullptr;
        std::string x_axis, y_axis;
        for (const PlotText& t : texts) {
            EXPECT_GE(t.x, 0) << t.text;
            EXPECT_GE(t.y, 0) << t.text;
            EXPECT_LE(t.x + t.width, 960) << t.text;
            EXPECT_LE(t.y + t.height, 600) << t.text;
            if (t.kind == "label") {
                labels.push_back(t);
            } else if (t.kind == "legend") {
                legend = &t;
            } else if (t.kind == "x-axis") {
                x_axis = t.text;
            } else if (t.kind == "y-axis") {
                y_axis = t.text;
            }
        }
        EXPECT_NE(x_axis.find("GPU time per frame, ms"), std::string::npos) << x_axis;
        EXPECT_NE(y_axis.find("mean FLIP"), std::string::npos) << y_axis;
        // Values over two decades get a log axis; within a factor of two, a linear one (the
        // threshold is 8).
        EXPECT_EQ(y_axis.find("log scale") != std::string::npos, spread > 100) << y_axis;
        ASSERT_NE(legend, nullptr);
        EXPECT_NE(legend->text.find("Pareto front"), std::string::npos);
        ASSERT_EQ(labels.size(), 13u);
        auto overlap = [](const PlotText& a, const PlotText& b) {
            return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
                   b.y < a.y + a.height;
        };
        for (size_t i = 0; i < labels.size(); ++i) {
            EXPECT_EQ(labels[i].text.find(std::to_string(i + 1) + " "), 0u) << labels[i].text;
            EXPECT_FALSE(overlap(labels[i], *legend)) << labels[i].text;
            for (size_t j = i + 1; j < labels.size(); ++j) {
                EXPECT_FALSE(overlap(labels[i], labels[j]))
                    << labels[i].text << " and " << labels[j].text;
            }
        }
    }
}

// The PNG and the SVG are the same drawing: the SVG carries the figure's words in its title and
// description, and the PNG shows the points in their colours (red on the Pareto front, blue off
// it) where the drawing put them.
TEST(AccuracyPlot, ThePngAndTheSvgAreOneDrawing) {
    const AccuracyReport r = Crowded(200);
    const std::string svg = tools::AccuracyPlotSvg(r);
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("<title>Mean FLIP against GPU time: scenes/demo/demo.gltf</title>"),
              std::string::npos);
    EXPECT_NE(svg.find("Pareto front"), std::string::npos);
    EXPECT_NE(svg.find("13 auto-4-fp16"), std::string::npos);
    const std::vector<uint8_t> png = tools::AccuracyPlotImage(r, 960, 600);
    ASSERT_EQ(png.size(), 960u * 600u * 4u);
    // Each label sits beside its point: the point is the nearest red or blue disc to it; count
    // the red and the blue pixels, which are only the points and the front's line.
    size_t red = 0, blue = 0;
    for (size_t i = 0; i < png.size(); i += 4) {
        red += png[i] > 200 && png[i + 1] < 60 && png[i + 2] < 60;
        blue += png[i] < 60 && png[i + 1] > 100 && png[i + 2] > 160;
    }
    EXPECT_GT(red, 3u * 50u);    // three Pareto points and the line joining them
    EXPECT_GT(blue, 10u * 50u);  // ten other points, about 80 pixels each
}

// The Pareto flags treat differences inside the noise as ties: a configuration a millisecond
// slower than another, whose frames vary by six, stays on the front; one slower by more than the
// spread and no more accurate leaves it; a more accurate one stays whatever its time.
TEST(AccuracyPlot, TheParetoFrontIgnoresDifferencesInsideTheNoise) {
    auto row = [](const char* name, double ms, double spread, double flip) {
        AccuracyRow r;
        r.config.name = name;
        r.gpu_ms = {ms, ms - spread / 2, ms + spread / 2};
        r.flip = flip;
        return r;
    };
    std::vector<AccuracyRow> rows = {row("a", 10, 6, 0.0100), row("b", 11, 6, 0.0100),
                                     row("c", 20, 2, 0.0101), row("d", 5, 0.2, 0.30),
                                     row("e", 30, 2, 0.0050)};
    tools::MarkParetoFront(rows);
    EXPECT_TRUE(rows[0].pareto);   // a
    EXPECT_TRUE(rows[1].pareto);   // b: 1 ms slower than a, inside a's and b's 3 ms noise
    EXPECT_FALSE(rows[2].pareto);  // c: slower than a beyond the noise, FLIP tied within 1e-4
    EXPECT_TRUE(rows[3].pareto);   // d: the fastest
    EXPECT_TRUE(rows[4].pareto);   // e: the most accurate
    // Without noise b is slower than a for the same error: off the front.
    rows[0].gpu_ms = {10, 10, 10};
    rows[1].gpu_ms = {11, 11, 11};
    tools::MarkParetoFront(rows);
    EXPECT_FALSE(rows[1].pareto);
}

}  // namespace
}  // namespace kiln::test
