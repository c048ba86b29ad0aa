// Where kiln finds the programs and files installed beside it (docs/install.md): kiln-render in
// its own folder, the shipped pack in ../share/kiln (or ../materials in the build tree).
#include <filesystem>

#include "commands.h"

namespace kiln::cli {
namespace fs = std::filesystem;

namespace {

fs::path SelfPath() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe;
}

}  // namespace

std::string RenderToolPath() {
    const fs::path self = SelfPath();
    return self.empty() ? std::string("kiln-render")
                        : (self.parent_path() / "kiln-render").string();
}

std::string ShippedPackPath(const std::string& name) {
    const fs::path self = SelfPath();
    if (self.empty()) {
        return name;
    }
    const fs::path prefix = self.parent_path().parent_path();
    std::error_code ec;
    for (const fs::path& p : {prefix / "share/kiln" / name, prefix / "materials" / name}) {
        if (fs::exists(p, ec)) {
            return p.string();
        }
    }
    return (prefix / "share/kiln" / name).string();  // named in the error
}

std::string DemoScenePath() {
#ifdef KILN_DEMO_SCENE
    std::error_code ec;
    if (fs::exists(KILN_DEMO_SCENE, ec)) {
        return KILN_DEMO_SCENE;
    }
#endif
    return "";
}

}  // namespace kiln::cli
