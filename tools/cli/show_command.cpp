// kiln show: what Kiln compiled for one (shader, pass, keyword set, stage), from a pack or a
// .shader (compiled for that variant alone): the HLSL glslang compiled, SPIR-V assembly, GLSL,
// ESSL, MSL and HLSL through SPIRV-Cross, and the reflection. kiln compile -E prints the first of
// these for every program of a compile.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "kiln/base/files.h"
#include "kiln/pack/pass_id.h"
#include "kiln/show.h"

namespace kiln::cli {

namespace {

using pack::Pack;

// The views in the order they are printed; `--hlsl` (the source view) first.
struct ViewFlags {
    bool hlsl = false, spirv = false, glsl = false, essl = false, msl = false, cross_hlsl = false,
         reflect = false, json = false;
    int count() const { return hlsl + spirv + glsl + essl + msl + cross_hlsl + reflect; }
};

struct Options {
    std::string input, stage = "frag", output = "-";
    VariantName name;
    ViewFlags views;
    CompilerFlags flags;
};

bool IsPack(std::span<const uint8_t> bytes) {
    return bytes.size() >= pack::kMagic.size() &&
           std::equal(pack::kMagic.begin(), pack::kMagic.end(), bytes.begin());
}

// A pack of the one variant asked for, compiled from the .shader with the compile's texts kept
// (`programs`); false after reporting errors.
bool CompileOneVariant(const Options& o,
                       std::vector<uint8_t>& pack_bytes,
                       std::vector<ProgramText>& programs,
                       const GlobalOptions& global) {
    std::vector<std::unique_ptr<SourceFile>> material_files;
    DiagnosticList diags = global.NewDiagnostics();
    CompileOptions options = ToCompileOptions(o.flags, material_files, diags);
    options.cache_dir.clear();  // every program preprocessed, so each has its text
    options.keep_programs = true;
    // Names are resolved against the shader's passes first, with suggestions, as for a pack.
    CompileOutput skeleton = BuildSkeletonPack({o.input}, options, diags);
    if (!skeleton.ok) {
        PrintDiagnostics(diags, Views(skeleton, material_files), global);
        return false;
    }
    Result<Pack> plan = Pack::Open(skeleton.pack);
    if (!plan) {
        ReportError(global, plan.error().code, o.input, plan.error().message);
        return false;
    }
    const std::optional<uint32_t> pass = ResolvePass(plan.value(), o.input, o.name, global);
    if (!pass)
        return false;
    pack::UsageEntry lookup;
    lookup.shader = o.name.shader;
    lookup.pass = pack::PassLabel(plan.value(), *pass);
    lookup.keywords = o.name.keywords;
    lookup.count = 1;
    options.requests = pack::UsageLog{{lookup}, {}};
    CompileOutput out = CompileShaders({o.input}, options, diags);
    PrintDiagnostics(diags, Views(out, material_files), global);
    if (!out.ok)
        return false;
    for (const PassReport& p : out.passes) {
        for (const RequestedVariantReport& r : p.excluded) {
            ReportError(global, DiagCode::kMissingVariant, o.input,
                        "shader \"" + o.name.shader + "\" pass \"" + o.name.pass +
                            "\" builds no variant with these keywords: " + r.excluded_because);
            return false;
        }
    }
    pack_bytes = std::move(out.pack);
    programs = std::move(out.programs);
    return true;
}

// The text glslang compiled for the stage, from the compile's kept programs.
std::optional<std::string> SourceView(const std::vector<ProgramText>& programs, pack::Stage stage) {
    for (const ProgramText& p : programs) {
        if (p.stage == stage)
            return ProgramView(p);
    }
    return std::nullopt;
}

int Run(const Options& o, const GlobalOptions& global) {
    if (o.views.count() == 0) {
        ReportError(global, DiagCode::kBadCommandLine, "",
                    "kiln show needs a view: --hlsl, --spirv, --glsl, --essl, --msl, "
                    "--cross-hlsl or --reflect");
        return int(kExitUsageError);
    }
    const pack::Stage stage = StageOf(o.stage);
    pack::MappedFile file;
    std::vector<uint8_t> compiled;
    std::vector<ProgramText> programs;
    std::span<const uint8_t> bytes;
    // A pack is mapped once and read from the mapping; anything else is a .shader (whose reader
    // reports a file that cannot be read).
    if (Result<pack::MappedFile> mapped = pack::MappedFile::Map(o.input);
        mapped && IsPack(mapped.value().bytes())) {
        if (o.views.hlsl) {
            ReportError(global, DiagCode::kBadCommandLine, o.input,
                        "--hlsl shows the source glslang compiled, which a pack does not keep; "
                        "give the .shader instead of the pack");
            return int(kExitUsageError);
        }
        file = std::move(mapped).value();
        bytes = file.bytes();
    } else {
        if (!CompileOneVariant(o, compiled, programs, global))
            return int(kExitInputError);
        bytes = compiled;
    }
    Result<Pack> opened = Pack::Open(bytes);
    if (!opened)
        return ReportError(global, opened.error().code, o.input, opened.error().message);
    const Pack& pack = opened.value();
    const std::optional<pack::VariantRec> v = ResolveVariant(pack, o.input, o.name, global);
    if (!v)
        return int(kExitInputError);
    const std::optional<uint32_t> at = ModuleAt(pack, *v, stage, o.input, global);
    if (!at)
        return int(kExitInputError);
    const pack::ModuleRec module = pack.Module(*at).value();
    const std::span<const uint32_t> words = pack.SpirvWords(module);

    std::string text;
    auto add = [&](const char* title, const std::string& body) {
        if (o.views.count() > 1)
            text += std::string(text.empty() ? "" : "\n") + "// ---- " + title + "\n";
        text += body;
    };
    if (o.views.hlsl) {
        const std::optional<std::string> source = SourceView(programs, stage);
        if (!source)
            return ReportError(global, DiagCode::kCannotShowModule, o.input,
                               "the compile kept no text for this stage");
        add("hlsl", *source);
    }
    const std::pair<bool, ModuleView> module_views[] = {
        {o.views.spirv, ModuleView::kSpirv},
        {o.views.glsl, ModuleView::kGlsl},
        {o.views.essl, ModuleView::kEssl},
        {o.views.msl, ModuleView::kMsl},
        {o.views.cross_hlsl, ModuleView::kCrossHlsl}};
    for (const auto& [wanted, view] : module_views) {
        if (!wanted)
            continue;
        Result<std::string> shown = ViewModule(words, view, &pack, &module);
        if (!shown)
            return ReportError(global, shown.error().code, o.input, shown.error().message);
        add(std::string(ModuleViewName(view)).c_str(), shown.value());
    }
    if (o.views.reflect)
        add("reflect", ReflectionText(pack, module, o.views.json));
    Status written = base::WriteFileAtomically(o.output, text, {{o.input}});
    if (!written.ok())
        return ReportError(global, DiagCode::kCannotWriteFile, o.output, written.error().message);
    return int(kExitOk);
}

}  // namespace

std::function<int()> AddShowCommand(CLI::App* cmd, const GlobalOptions& global) {
    auto o = std::make_shared<Options>();
    cmd->add_option("input", o->input,
                    "A .kpack, or a .shader compiled for this variant alone (- reads standard "
                    "input)")
        ->required();
    AddVariantNameOptions(*cmd, o->name);
    AddStageOption(cmd->add_option("--stage", o->stage,
                                   "vert, frag, geometry, hull or domain (default frag)"));
    cmd->add_flag("--hlsl", o->views.hlsl,
                  "The preprocessed HLSL glslang compiled, reduced to the entry point, with #line "
                  "back to the .shader (a .shader input only; kiln compile -E for every program)");
    cmd->add_flag("--spirv", o->views.spirv, "SPIR-V assembly with friendly names");
    cmd->add_flag("--glsl", o->views.glsl, "GLSL 450 with Vulkan semantics (SPIRV-Cross)");
    cmd->add_flag("--essl", o->views.essl, "ESSL 310 (SPIRV-Cross)");
    cmd->add_flag("--msl", o->views.msl, "Metal Shading Language 2.1 (SPIRV-Cross)");
    cmd->add_flag("--cross-hlsl", o->views.cross_hlsl, "HLSL shader model 5.0 (SPIRV-Cross)");
    cmd->add_flag("--reflect", o->views.reflect,
                  "Inputs and outputs, uniform blocks and push constants, resources");
    cmd->add_flag("--json", o->views.json, "--reflect as JSON");
    cmd->add_option("-o,--output", o->output, "Write to a file (default: standard output)");
    AddCompilerOptions(*cmd, o->flags, false);
    return [o, &global]() { return Run(*o, global); };
}

}  // namespace kiln::cli
