// kiln test PACK... [--shader S] [--sample N --seed S] [--size N] [--keep-failures DIR] [--json]:
// every variant drawn in the runtime's test harness and checked (kiln/tools/variant_test.h).
// Each failure is a K0027 error naming the shader, pass, keyword set, property values and check,
// with its render kept as a PNG; the exit status is 1 when any variant fails.
#include <cstdio>
#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "kiln/pack/variant_selector.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/tools/variant_test.h"
#include "render_setup.h"

namespace kiln::cli {
namespace {

// A file name from a failure's description: letters, digits, '-', '_' and '.' only.
std::string FileName(size_t index, const tools::VariantTestFailure& f) {
    std::string raw = f.shader + "_" + f.pass + "_" + pack::JoinKeywords(f.keywords) + "_" +
                      f.properties + "_" + f.check;
    for (char& c : raw) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.')
            c = '_';
    }
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "%03zu-", index + 1);
    return prefix + raw.substr(0, 160) + ".png";
}

}  // namespace

std::function<int()> AddTestCommand(CLI::App* cmd, const GlobalOptions& global) {
    struct Args {
        std::vector<std::string> packs, shaders;
        tools::VariantTestOptions options;
        uint32_t sample = 0;
        std::string keep = "kiln-test-failures", device;
        bool json = false, no_validation = false;
    };
    auto a = std::make_shared<Args>();
    cmd->add_option("packs", a->packs, "Variant packs (.kpack)")->required();
    cmd->add_option("--shader", a->shaders, "Only this shader (repeatable)");
    cmd->add_option("--sample", a->sample, "Test N variants chosen with --seed instead of all")
        ->check(CLI::PositiveNumber.description(""))
        ->option_text("N");
    cmd->add_option("--seed", a->options.seed, "Seed of --sample (default 1)");
    cmd->add_option("--size", a->options.size, "Harness image side in pixels (default 64)")
        ->check(CLI::Range(16, 4096).description(""))
        ->option_text("N");
    cmd->add_option("--keep-failures", a->keep,
                    "Folder for the PNG of each failing render (default kiln-test-failures)");
    cmd->add_flag("--json", a->json, "Print the report as JSON on stdout");
    cmd->add_flag("--no-validation", a->no_validation,
                  "Do not enable VK_LAYER_KHRONOS_validation (its messages fail a variant)");
    cmd->add_option("--device", a->device, "Use a Vulkan device whose name contains this");
    return [a, &global] {
        CommandDiagnostics run(global);
        DiagnosticList& diags = run.diags;
        Result<runtime::ColorPipeline> made_color = runtime::ColorPipeline::Create({});
        if (!made_color)
            return run.Fail(made_color.error(), "");
        const runtime::ColorPipeline color = std::move(made_color).value();
        const runtime::RendererOptions options =
            HarnessRendererOptions(!a->no_validation, a->device);
        std::string failed_pack;
        Result<runtime::Renderer> made = MakeRenderer(options, a->packs, &failed_pack);
        if (!made)
            return run.Fail(made.error(), failed_pack);
        runtime::Renderer renderer = std::move(made).value();
        a->options.shaders = a->shaders;
        if (a->sample > 0)
            a->options.sample = a->sample;
        Result<tools::VariantTestReport> ran = tools::TestVariants(renderer, color, a->options);
        if (!ran)
            return run.Fail(ran.error(), "");
        const tools::VariantTestReport& report = ran.value();
        nlohmann::ordered_json failures = nlohmann::ordered_json::array();
        for (size_t i = 0; i < report.failures.size(); ++i) {
            const tools::VariantTestFailure& f = report.failures[i];
            std::string png;
            if (!f.image.rgba.empty()) {
                std::error_code ec;
                std::filesystem::create_directories(a->keep, ec);
                png = (std::filesystem::path(a->keep) / FileName(i, f)).string();
                if (!runtime::WriteDisplayPng(png, f.image, color).ok())
                    png.clear();
            }
            diags.Error(DiagCode::kVariantTestFailed, f.pack, kNoPosition,
                        "shader '" + f.shader + "' pass '" + f.pass + "' variant '" +
                            pack::JoinKeywords(f.keywords) + "' with " + f.properties + ": " +
                            f.check + ": " + f.message +
                            (png.empty() ? std::string() : " (render kept in " + png + ")"));
            failures.push_back({{"pack", f.pack},
                                {"shader", f.shader},
                                {"pass", f.pass},
                                {"keywords", f.keywords},
                                {"properties", f.properties},
                                {"check", f.check},
                                {"message", f.message},
                                {"png", png}});
        }
        if (a->json) {
            const nlohmann::ordered_json doc = {{"kiln_test", 1},
                                                {"variants", report.variants},
                                                {"renders", report.renders},
                                                {"skipped", report.skipped},
                                                {"skipped_variants", report.skipped_variants},
                                                {"failures", failures},
                                                {"passed", report.failures.empty()}};
            std::printf("%s\n", doc.dump(2).c_str());
        } else {
            for (const std::string& s : report.skipped)
                std::printf("skipped %s\n", s.c_str());
            const size_t skips = report.skipped.size();
            const std::string skipped =
                skips == 0 ? ""
                           : " (" + std::to_string(report.skipped_variants) +
                                 " not tested, for the " + std::to_string(skips) + " reason" +
                                 (skips == 1 ? "" : "s") + " listed above)";
            std::printf(
                "kiln test: %zu of %zu variants tested%s, %zu renders on '%s': %zu failures\n",
                report.variants, report.variants + report.skipped_variants, skipped.c_str(),
                report.renders, renderer.DeviceName().c_str(), report.failures.size());
        }
        return run.Finish(ExitCodeFor(diags));
    };
}

}  // namespace kiln::cli
