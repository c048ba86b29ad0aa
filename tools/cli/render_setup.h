// What the commands kiln-render runs share to set up the renderer.
#ifndef KILN_TOOLS_CLI_RENDER_SETUP_H_
#define KILN_TOOLS_CLI_RENDER_SETUP_H_

#include <string>
#include <vector>

#include "kiln/runtime/renderer.h"

namespace kiln::cli {

// A renderer made with `options` and `packs` added in order (the first pack's shaders are found
// first). On failure the error, and in `failed_pack` the pack it is about ("" for the device).
Result<runtime::Renderer> MakeRenderer(const runtime::RendererOptions& options,
                                       const std::vector<std::string>& packs,
                                       std::string* failed_pack = nullptr);

}  // namespace kiln::cli

#endif  // KILN_TOOLS_CLI_RENDER_SETUP_H_
