#include "render_setup.h"

#include "kiln/base/text.h"

namespace kiln::cli {

Result<runtime::Renderer> MakeRenderer(const runtime::RendererOptions& options,
                                       const std::vector<std::string>& packs,
                                       std::string* failed_pack) {
    Result<runtime::Renderer> made = runtime::Renderer::Create(options);
    if (!made)
        return made;
    for (const std::string& p : packs) {
        if (Status added = AddCheckedPack(made.value(), p); !added.ok()) {
            if (failed_pack != nullptr)
                *failed_pack = p;
            return added.error();
        }
    }
    return made;
}

Status AddCheckedPack(runtime::Renderer& renderer, const std::string& path) {
    if (Status added = renderer.AddPack(path); !added.ok())
        return added;
    const Status checked = renderer.pack(renderer.pack_count() - 1).CheckVariantData();
    if (!checked.ok())
        return Error{checked.error().code, path + ": " + checked.error().message};
    return {};
}

}  // namespace kiln::cli

namespace kiln::cli {

runtime::RendererOptions HarnessRendererOptions(bool validation, const std::string& device) {
    runtime::RendererOptions options;
    options.validation = validation;
    options.device_filter = device;
    options.float32_target = true;
    return options;
}

void AddPathOption(CLI::App& cmd, std::string& name) {
    const std::vector<runtime::RenderPathInfo> paths = runtime::RenderPaths();
    std::string help = "Render path (default forward): ", names;
    std::vector<std::string> candidates;
    for (const runtime::RenderPathInfo& p : paths) {
        help += (names.empty() ? "" : "; ") + p.name + ", " + p.summary;
        names += (names.empty() ? "" : "|") + p.name;
        candidates.push_back(p.name);
    }
    cmd.add_option("--path", name, help)
        ->check(CLI::Validator(
            [paths, candidates](std::string& value) -> std::string {
                for (const runtime::RenderPathInfo& p : paths) {
                    if (base::EqualsIgnoreCase(p.name, value)) {
                        value = p.name;
                        return "";
                    }
                }
                std::string list;
                for (const std::string& c : candidates) {
                    list += (list.empty() ? "" : ", ") + c;
                }
                return "unknown render path '" + value + "' (there are " + list + ")" +
                       base::DidYouMean(value, candidates);
            },
            "", ""))
        ->option_text(names);
}

}  // namespace kiln::cli
