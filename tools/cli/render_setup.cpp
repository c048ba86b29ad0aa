#include "render_setup.h"

namespace kiln::cli {

Result<runtime::Renderer> MakeRenderer(const runtime::RendererOptions& options,
                                       const std::vector<std::string>& packs,
                                       std::string* failed_pack) {
    Result<runtime::Renderer> made = runtime::Renderer::Create(options);
    if (!made)
        return made;
    for (const std::string& p : packs) {
        if (Status added = made.value().AddPack(p); !added.ok()) {
            if (failed_pack != nullptr)
                *failed_pack = p;
            return added.error();
        }
    }
    return made;
}

}  // namespace kiln::cli
