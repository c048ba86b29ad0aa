// What the commands kiln-render runs share to set up the renderer.
#ifndef KILN_TOOLS_CLI_RENDER_SETUP_H_
#define KILN_TOOLS_CLI_RENDER_SETUP_H_

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "kiln/runtime/renderer.h"

namespace kiln::cli {

// A renderer made with `options` and `packs` added in order (the first pack's shaders are found
// first). On failure the error, and in `failed_pack` the pack it is about ("" for the device).
Result<runtime::Renderer> MakeRenderer(const runtime::RendererOptions& options,
                                       const std::vector<std::string>& packs,
                                       std::string* failed_pack = nullptr);

// Renderer::AddPack, then the pack's variant data checked at once (the renderer checks it when
// the first variant is chosen): the tools read every variant's records, and report a damaged
// pack when they load it.
Status AddCheckedPack(runtime::Renderer& renderer, const std::string& path);

// The renderer options of the harness commands (kiln test, kiln stability): 32-bit float targets,
// as their checks read linear values (fp16 would turn large finite values into Inf), the
// validation layer as asked, the --device filter.
runtime::RendererOptions HarnessRendererOptions(bool validation, const std::string& device);

// --path: a registered render path's name (runtime::RenderPaths, any case), stored as it is
// registered into `name`; another name is refused with the registered ones and the closest.
void AddPathOption(CLI::App& cmd, std::string& name);

}  // namespace kiln::cli

#endif  // KILN_TOOLS_CLI_RENDER_SETUP_H_
