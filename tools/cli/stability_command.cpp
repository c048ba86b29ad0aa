// kiln stability: numerical stability on stiff and extreme inputs (kiln/tools/stability.h,
// docs/accuracy.md). With --material, each material's fragment variants under extreme light
// set-ups and at the ends of their Ranges; without, the templates' lighting functions on
// adversarial grids against the CPU reference. Any non-finite value is a K0028 error.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "commands.h"
#include "kiln/base/files.h"
#include "kiln/compile.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/variant_selector.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/tools/stability.h"
#include "kiln/tools/template_stability.h"
#include "render_setup.h"

namespace kiln::cli {
namespace {

struct StabilityArgs {
    std::vector<std::string> materials, packs, include_dirs, sources;
    std::vector<std::string> precisions;  // --precision: full, half (binary16), relaxed
    tools::MaterialStabilityOptions options;
    std::string device, templates;
};

// A half build needs shaderFloat16; without it the build is skipped with a warning.
bool CanRun(pack::Precision p, const runtime::Renderer& renderer, DiagnosticList& diags) {
    if (p != pack::Precision::kHalf || renderer.HasFloat16())
        return true;
    diags.Warning(DiagCode::kRenderFailed, "", kNoPosition,
                  "the binary16 (--precision half) checks are skipped: device '" +
                      renderer.DeviceName() + "' has no shaderFloat16");
    return false;
}

// Compiles `sources` with the templates under test and `defines` into a temporary pack and
// adds it to the renderer.
bool AddCompiledPack(const StabilityArgs& a,
                     const std::vector<std::string>& sources,
                     const std::vector<std::pair<std::string, std::string>>& defines,
                     pack::Precision precision,
                     runtime::Renderer& renderer,
                     DiagnosticList& diags,
                     const GlobalOptions& global) {
    CompileOptions options;
    options.precision = precision;
    options.include_dirs = a.include_dirs;
    options.defines = defines;
    options.all_features = true;  // every material's shader_feature combination
    options.templates_dir = a.templates.empty() ? DefaultTemplatesDir() : a.templates;
    DiagnosticList compiled;  // its own list: `diags` may hold earlier runs' findings
    CompileOutput out = CompileShaders(sources, options, compiled);
    std::vector<const SourceFile*> views;
    for (const auto& f : out.files) {
        views.push_back(f.get());
    }
    if (!compiled.all().empty()) {
        PrintDiagnostics(compiled, views, global);
    }
    if (!out.ok) {
        PrintDiagnostics(diags, {}, global);
        return false;
    }
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("kiln-stability-" + std::to_string(getpid()) + ".kpack"))
                                 .string();
    Status added = base::WriteFileAtomically(path, out.pack, {.inputs = {}, .durable = false});
    if (added.ok()) {
        added = AddCheckedPack(renderer, path);  // mapped: the name can go now
    }
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    if (!added.ok()) {
        diags.Error(added.error().code, path, kNoPosition, added.error().message);
        PrintDiagnostics(diags, {}, global);
        return false;
    }
    return true;
}

std::string GridHarness(const StabilityArgs& a) {
    const std::string mine = (a.templates.empty() ? DefaultTemplatesDir() : a.templates) + "/" +
                             pack::kStabilityGridFile;
    return std::filesystem::exists(mine) ? mine
                                         : DefaultTemplatesDir() + "/" + pack::kStabilityGridFile;
}

// A strict build (templates/KilnStrictMath.cginc): the define, and what its NaN means.
struct StrictMode {
    const char* define;
    const char* cause;
};
constexpr StrictMode kStrictModes[] = {
    {"KILN_STRICT_NORMALIZE", "normalize of a zero (or within-rounding-of-zero) vector"},
    {"KILN_STRICT_POW", "pow(x, y) with x < 0, or x = 0 and y <= 0 (undefined in SPIR-V)"},
};

struct Totals {
    size_t variants = 0, renders = 0, findings = 0;
    std::set<std::string> seen;  // findings already reported (by an earlier strict mode)
};

// Runs every material; `cause` names what a strict build's NaN means and its precision ("" for
// a plain build of the packs).
void RunMaterials(runtime::Renderer& renderer,
                  const runtime::ColorPipeline& color,
                  const StabilityArgs& a,
                  const std::string& cause,
                  Totals& totals,
                  DiagnosticList& diags) {
    for (const std::string& material : a.materials) {
        Result<tools::MaterialStabilityReport> ran =
            tools::TestMaterialStability(renderer, color, material, a.options);
        if (!ran) {
            // Errors from the material file carry its path and position already.
            const bool placed = ran.error().message.rfind(material + ":", 0) == 0;
            diags.Error(ran.error().code, placed ? "" : material, kNoPosition, ran.error().message);
            continue;
        }
        const tools::MaterialStabilityReport& r = ran.value();
        std::vector<const tools::StabilityFinding*> fresh;
        for (const tools::StabilityFinding& f : r.findings) {
            const std::string key = material + "|" + f.pass + "|" + pack::JoinKeywords(f.keywords) +
                                    "|" + f.properties + "|" + f.light + "|" + std::to_string(f.x) +
                                    "," + std::to_string(f.y);
            if (totals.seen.insert(key).second)
                fresh.push_back(&f);
        }
        totals.variants += r.variants;
        totals.renders += r.renders;
        totals.findings += fresh.size();
        std::printf(
            "%s (shader \"%s\"%s%s): %zu variants, %zu renders, %zu with non-finite "
            "values\n",
            material.c_str(), r.shader.c_str(), cause.empty() ? "" : ", strict: ", cause.c_str(),
            r.variants, r.renders, fresh.size());
        for (const tools::StabilityFinding* f : fresh) {
            std::printf("  %-14s %-20s %-32s %-56s %zu/%zu at (%u, %u): %s\n", f->pass.c_str(),
                        pack::JoinKeywords(f->keywords).c_str(), f->properties.c_str(),
                        f->light.c_str(), f->bad, f->values, f->x, f->y, f->inputs.c_str());
            diags.Error(DiagCode::kNotFinite, material, kNoPosition,
                        (cause.empty() ? std::string() : cause + ": ") + "pass '" + f->pass +
                            "' variant '" + pack::JoinKeywords(f->keywords) + "' with " +
                            f->properties + ", " + f->light + ": " + std::to_string(f->bad) +
                            " non-finite values, the first at pixel (" + std::to_string(f->x) +
                            ", " + std::to_string(f->y) + ") where " + f->inputs);
        }
    }
}

// The grid table; returns the number of failing cases.
size_t PrintGrid(const tools::TemplateStabilityReport& r,
                 DiagnosticList& diags,
                 const std::string& precision) {
    const std::string build = "--precision " + precision + ": ";
    size_t failed = 0;
    std::printf("%-22s %7s %7s %11s %11s %11s %9s  %s\n", "case", "values", "NaN/Inf", "max abs",
                "max rel", "bound", "max ULP", "worst input");
    for (const tools::GridCaseReport& c : r.cases) {
        std::printf("%-22s %7zu %7zu %11.3g %11.3g %11.3g %9llu  %s\n", c.name.c_str(), c.values,
                    c.non_finite, c.max_abs, c.max_rel, c.bound,
                    static_cast<unsigned long long>(c.max_ulp), c.worst.c_str());
        if (c.non_finite > 0) {
            diags.Error(DiagCode::kNotFinite, "", kNoPosition,
                        build + c.name + ": " + std::to_string(c.non_finite) + " of " +
                            std::to_string(c.values) + " values are not finite, the first at " +
                            c.first_non_finite);
        }
        if (c.max_rel > c.bound) {
            diags.Error(DiagCode::kOutsideBounds, "", kNoPosition,
                        build + c.name + ": relative error " + std::to_string(c.max_rel) +
                            " is above its bound " + std::to_string(c.bound) + " at " + c.worst);
        }
        failed += c.ok() ? 0 : 1;
    }
    if (r.energy.empty())
        return failed;
    std::printf("\n%-36s %12s  %s\n", "white furnace (directional albedo)", "max", "at");
    for (const tools::EnergyReport& e : r.energy) {
        std::printf("%-36s %12.6f  %s\n", e.brdf.c_str(), e.max_albedo, e.where.c_str());
        if (!e.ok()) {
            diags.Error(DiagCode::kOutsideBounds, "", kNoPosition,
                        build + e.brdf + ": directional albedo " + std::to_string(e.max_albedo) +
                            " exceeds 1 + 1e-3 at " + e.where + " (it creates energy)");
            ++failed;
        }
    }
    return failed;
}

}  // namespace

std::function<int()> AddStabilityCommand(CLI::App* cmd, const GlobalOptions& global) {
    auto a = std::make_shared<StabilityArgs>();
    cmd->add_option("--material", a->materials,
                    ".material files to check (repeatable); without it the templates are checked");
    cmd->add_option("--templates", a->templates,
                    "The include library to check (default: the shipped templates/)");
    cmd->add_option("-I,--include-dir", a->include_dirs,
                    "Folders searched before the templates (a planted include overrides its "
                    "namesake)");
    cmd->add_option("--pack", a->packs,
                    "Variant packs holding the materials' shaders (default: the shipped "
                    "materials.kpack)");
    cmd->add_option("--source", a->sources,
                    "The materials' .shader files: check strict builds of them (normalize of a "
                    "zero vector and undefined pow made NaN on every driver) instead of a pack's");
    cmd->add_option("--precision", a->precisions,
                    "Builds to check: full (32-bit half), half (binary16 arithmetic; skipped "
                    "with a warning where the device has no shaderFloat16) or relaxed; the "
                    "grids and --source builds (default: full,half)")
        ->delimiter(',')
        ->check(CLI::IsMember({"full", "half", "relaxed"}));
    cmd->add_option("--size", a->options.size,
                    "The square image's side in pixels, odd (default 33)")
        ->check(CLI::Range(9, 1025).description(""));
    cmd->add_option("--device", a->device, "Use a Vulkan device whose name contains this");
    return [a, &global] {
        CommandDiagnostics run(global);
        DiagnosticList& diags = run.diags;
        Result<runtime::ColorPipeline> made_color = runtime::ColorPipeline::Create({});
        if (!made_color)
            return run.Fail(made_color.error(), "");
        const runtime::ColorPipeline color = std::move(made_color).value();
        const runtime::RendererOptions options = HarnessRendererOptions(true, a->device);
        auto validation = [&](const runtime::Renderer& renderer) {
            for (const std::string& m : renderer.ValidationMessages())
                diags.Error(DiagCode::kRenderFailed, "", kNoPosition, "validation: " + m);
        };
        if (a->precisions.empty())
            a->precisions = {"full", "half"};
        if (a->materials.empty()) {
            size_t builds = 0, cases = 0, checks = 0, failed = 0;
            std::string device;
            for (const std::string& precision : a->precisions) {
                Result<runtime::Renderer> made = runtime::Renderer::Create(options);
                if (!made)
                    return run.Fail(made.error(), "");
                runtime::Renderer renderer = std::move(made).value();
                device = renderer.DeviceName();
                const pack::Precision p = pack::PrecisionFromName(precision);
                if (!CanRun(p, renderer, diags))
                    continue;
                if (!AddCompiledPack(*a, {GridHarness(*a)}, {}, p, renderer, diags, global))
                    return int(kExitInputError);
                Result<tools::TemplateStabilityReport> ran =
                    tools::TestTemplateStability(renderer, color, {.precision = p});
                if (!ran)
                    return run.Fail(ran.error(), "");
                if (checks > 0)
                    ran.value().energy.clear();  // CPU integrals: the same in every build
                std::printf("%s-precision build (--precision %s):\n",
                            p == pack::Precision::kHalf ? "binary16" : "32-bit", precision.c_str());
                failed += PrintGrid(ran.value(), diags, precision);
                std::printf("\n");
                ++builds;
                cases += ran.value().cases.size();
                checks += ran.value().energy.size();
                validation(renderer);
            }
            std::printf(
                "kiln stability: %zu grid cases and %zu white-furnace checks in %zu builds on "
                "'%s': %zu failed\n",
                cases, checks, builds, device.c_str(), failed);
            return run.Finish(ExitCodeFor(diags));
        }
        if (a->packs.empty() && a->sources.empty())
            a->packs.push_back(ShippedPackPath());
        Totals totals;
        std::string device;
        // A plain run over the packs; with --source, one run per precision and strict build of
        // the sources (their shaders found first), each finding reported by the first build that
        // shows it.
        const size_t runs = a->sources.empty() ? 1 : std::size(kStrictModes) * a->precisions.size();
        for (size_t i = 0; i < runs; ++i) {
            Result<runtime::Renderer> made = runtime::Renderer::Create(options);
            if (!made)
                return run.Fail(made.error(), "");
            runtime::Renderer renderer = std::move(made).value();
            std::string cause;
            if (!a->sources.empty()) {
                const StrictMode& mode = kStrictModes[i % std::size(kStrictModes)];
                const std::string& precision = a->precisions[i / std::size(kStrictModes)];
                const pack::Precision p = pack::PrecisionFromName(precision);
                if (!CanRun(p, renderer, diags))
                    continue;
                cause = std::string(mode.cause) + " (--precision " + precision + ")";
                if (!AddCompiledPack(*a, a->sources, {{mode.define, "1"}}, p, renderer, diags,
                                     global))
                    return int(kExitInputError);
            }
            for (const std::string& p : a->packs) {
                if (Status added = AddCheckedPack(renderer, p); !added.ok())
                    return run.Fail(added.error(), p);
            }
            RunMaterials(renderer, color, *a, cause, totals, diags);
            validation(renderer);
            device = renderer.DeviceName();
        }
        std::printf(
            "kiln stability: %zu materials, %zu variants, %zu renders on '%s': %zu "
            "findings\n",
            a->materials.size(), totals.variants, totals.renders, device.c_str(), totals.findings);
        return run.Finish(ExitCodeFor(diags));
    };
}

}  // namespace kiln::cli
