// WriteAccuracyReport: the tables (Markdown, CSV, JSON), the plot and the images of a report.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include <nlohmann/json.hpp>

#include "kiln/base/files.h"
#include "kiln/tools/accuracy_report.h"

namespace kiln::tools {

using runtime::ColorPipeline;
using runtime::FrameStats;
using runtime::WriteDisplayPng;
using runtime::WritePng;
namespace {

namespace fs = std::filesystem;

std::string Num(double v, int digits) {
    if (std::isinf(v)) {
        return "inf";
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string Sci(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

std::string Ms(const Spread& s) {
    if (s.median < 0) {
        return "-";
    }
    return Num(s.median, 3) + " (" + Num(s.min, 3) + "-" + Num(s.max, 3) + ")";
}

}  // namespace

std::string TimingMethod(const AccuracyReport& r) {
    return "Timing: each configuration's first frame apart (with the pipelines it created); then " +
           std::to_string(r.warmup) + " untimed and " + std::to_string(r.frames) +
           " timed rounds of one frame of every configuration in turn (A B C ... A B C ...), so "
           "that each is measured on a device as warm as the others and none after a pause; "
           "median (min-max) of the timed frames. GPU: timestamp queries around each pass, "
           "summed. CPU: from the Render call to the submission (planning, building and "
           "recording the draws), not the wait for the GPU nor the read-back. Frames after the "
           "first of a configuration create no Vulkan object (docs/runtime.md, \"Frame "
           "resources\").";
}

namespace {

std::string Markdown(const AccuracyReport& r) {
    std::string md = "# Accuracy report: " + r.scene + "\n\n";
    md += "Device: " + r.device + ". Images " + std::to_string(r.width) + "x" +
          std::to_string(r.height) + ". Reference: every light per pixel, fp32 targets, " +
          std::to_string(r.supersample) + "x" + std::to_string(r.supersample) + " supersampled (" +
          Num(r.reference_ms, 1) + " ms). " + TimingMethod(r) +
          " FLIP: mean over the image (0 identical, 1 most different); RMSE, max and PSNR in "
          "linear light.\n\n";
    md += "Configurations:\n\n";
    for (size_t i = 0; i < r.rows.size(); ++i) {
        const AccuracyConfig& c = r.rows[i].config;
        md += std::to_string(i + 1) + ". `" + c.name +
              "`: " + (c.description.empty() ? c.group : c.description) + ".\n";
    }
    md +=
        "\nPareto: no other configuration is both faster and more accurate, each beyond the "
        "measurements' noise: faster by more than half the larger of the two frame-time spreads "
        "(max - min), more accurate by more than " +
        Num(kParetoFlipTolerance, 4) + " FLIP.\n\n";
    md +=
        "| # | configuration | group | packs | FLIP | RMSE | max abs | PSNR dB | GPU ms | "
        "CPU ms | first frame ms (pipelines) | Pareto |\n";
    md += "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (size_t i = 0; i < r.rows.size(); ++i) {
        const AccuracyRow& row = r.rows[i];
        md += "| " + std::to_string(i + 1) + " | " + row.config.name + " | " + row.config.group +
              " | " + row.config.label + " | " + Num(row.flip, 4) + " | " + Sci(row.error.rmse) +
              " | " + Sci(row.error.max_abs) + " | " + Num(row.error.psnr, 1) + " | " +
              Ms(row.gpu_ms) + " | " + Ms(row.cpu_ms) + " | " + Num(row.first_frame_ms, 1) + " (" +
              std::to_string(row.first_pipelines) + ") | " + (row.pareto ? "yes" : "") + " |\n";
    }
    md += "\nGPU time per pass (median ms):\n\n| configuration | passes |\n|---|---|\n";
    for (const AccuracyRow& row : r.rows) {
        std::string passes;
        for (const FrameStats::PassTime& p : row.pass_ms) {
            passes += (passes.empty() ? "" : ", ") + p.pass + " " + Num(p.gpu_ms, 3);
        }
        md += "| " + row.config.name + " | " + (passes.empty() ? "not measured" : passes) + " |\n";
    }
    md += "\n![FLIP against time, the Pareto front joined](plot.png)\n\n";
    md +=
        "Renders are in `render/`, FLIP heat maps in `heat/` (black: no difference, pale "
        "yellow: the largest), the reference in `reference.png`.\n";
    return md;
}

std::string Csv(const AccuracyReport& r) {
    std::string csv =
        "configuration,group,packs,flip_mean,rmse,max_abs,psnr_db,gpu_ms_median,gpu_ms_min,"
        "gpu_ms_max,cpu_ms_median,cpu_ms_min,cpu_ms_max,first_frame_ms,first_pipelines,pareto\n";
    for (const AccuracyRow& row : r.rows) {
        csv += row.config.name + "," + row.config.group + "," + row.config.label + "," +
               Sci(row.flip) + "," + Sci(row.error.rmse) + "," + Sci(row.error.max_abs) + "," +
               Num(row.error.psnr, 2) + "," + Sci(row.gpu_ms.median) + "," + Sci(row.gpu_ms.min) +
               "," + Sci(row.gpu_ms.max) + "," + Sci(row.cpu_ms.median) + "," +
               Sci(row.cpu_ms.min) + "," + Sci(row.cpu_ms.max) + "," + Sci(row.first_frame_ms) +
               "," + std::to_string(row.first_pipelines) + "," + (row.pareto ? "1" : "0") + "\n";
    }
    return csv;
}

nlohmann::json SpreadJson(const Spread& s) {
    if (s.median < 0) {
        return nullptr;
    }
    return {{"median", s.median}, {"min", s.min}, {"max", s.max}};
}

std::string Json(const AccuracyReport& r) {
    nlohmann::json rows = nlohmann::json::array();
    for (const AccuracyRow& row : r.rows) {
        nlohmann::json passes = nlohmann::json::object();
        for (const FrameStats::PassTime& p : row.pass_ms) {
            passes[p.pass] = p.gpu_ms;
        }
        rows.push_back({{"configuration", row.config.name},
                        {"group", row.config.group},
                        {"packs", row.config.label},
                        {"flip_mean", row.flip},
                        {"rmse", row.error.rmse},
                        {"max_abs", row.error.max_abs},
                        {"psnr_db", std::isinf(row.error.psnr) ? nlohmann::json("inf")
                                                               : nlohmann::json(row.error.psnr)},
                        {"gpu_ms", SpreadJson(row.gpu_ms)},
                        {"gpu_ms_per_pass", passes},
                        {"cpu_ms", SpreadJson(row.cpu_ms)},
                        {"first_frame_ms", row.first_frame_ms},
                        {"first_pipelines", row.first_pipelines},
                        {"pareto", row.pareto}});
    }
    const nlohmann::json j = {
        {"scene", r.scene},      {"device", r.device},           {"width", r.width},
        {"height", r.height},    {"supersample", r.supersample}, {"frames", r.frames},
        {"warmup", r.warmup},    {"timing", TimingMethod(r)},    {"reference_ms", r.reference_ms},
        {"configurations", rows}};
    return j.dump(1) + "\n";
}

}  // namespace

Status WriteAccuracyReport(const AccuracyReport& report,
                           const ColorPipeline& color,
                           const std::string& dir) {
    std::error_code ec;
    fs::create_directories(fs::path(dir) / "render", ec);
    fs::create_directories(fs::path(dir) / "heat", ec);
    if (ec) {
        return Error{DiagCode::kCannotWriteFile,
                     dir + ": cannot create the report folder: " + ec.message()};
    }
    auto path = [&](const std::string& name) { return (fs::path(dir) / name).string(); };
    if (Status e = WriteDisplayPng(path("reference.png"), report.reference, color); !e.ok()) {
        return e;
    }
    for (const AccuracyRow& row : report.rows) {
        if (Status e =
                WriteDisplayPng(path("render/" + row.config.name + ".png"), row.image, color);
            !e.ok()) {
            return e;
        }
        if (Status e = WritePng(path("heat/" + row.config.name + ".png"), report.width,
                                report.height, HeatMap(row.flip_map));
            !e.ok()) {
            return e;
        }
    }
    constexpr uint32_t kPlotWidth = 800, kPlotHeight = 500;
    if (Status e = WritePng(path("plot.png"), kPlotWidth, kPlotHeight,
                            AccuracyPlotImage(report, kPlotWidth, kPlotHeight));
        !e.ok()) {
        return e;
    }
    for (const auto& [name, text] :
         {std::pair{"plot.svg", AccuracyPlotSvg(report)}, std::pair{"report.md", Markdown(report)},
          std::pair{"report.csv", Csv(report)}, std::pair{"report.json", Json(report)}}) {
        if (Status e = base::WriteFileAtomically(path(name), text); !e.ok()) {
            return e;
        }
    }
    return {};
}

}  // namespace kiln::tools
