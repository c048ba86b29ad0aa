#include "render/render_path.h"

#include <mutex>

#include "kiln/base/text.h"

namespace kiln::runtime {
namespace {

// The registered paths, the built-in ones first. Paths are never removed: a PathRenderer*
// stays valid for the program's life.
struct Registry {
    std::mutex mutex;
    std::vector<std::unique_ptr<PathRenderer>> paths;

    Registry() {
        paths.push_back(MakeForwardPath());
        paths.push_back(MakeDeferredPath());
    }
};

Registry& Paths() {
    static Registry registry;
    return registry;
}

std::vector<std::string> Names(Registry& r) {
    std::vector<std::string> names;
    for (const auto& p : r.paths) {
        names.emplace_back(p->Name());
    }
    return names;
}

}  // namespace

const PathRenderer* FindPathRenderer(std::string_view name) {
    Registry& r = Paths();
    std::lock_guard lock(r.mutex);
    for (const auto& p : r.paths) {
        if (base::EqualsIgnoreCase(p->Name(), name)) {
            return p.get();
        }
    }
    return nullptr;
}

bool RegisterPathRenderer(std::unique_ptr<PathRenderer> path) {
    if (!path || path->Name().empty() || FindPathRenderer(path->Name())) {
        return false;
    }
    Registry& r = Paths();
    std::lock_guard lock(r.mutex);
    r.paths.push_back(std::move(path));
    return true;
}

Error UnknownPath(std::string_view name) {
    Registry& r = Paths();
    std::lock_guard lock(r.mutex);
    const std::vector<std::string> names = Names(r);
    std::string list;
    for (const std::string& n : names) {
        list += (list.empty() ? "" : ", ") + n;
    }
    return Error{DiagCode::kBadScene, "unknown render path '" + std::string(name) +
                                          "' (there are " + list + ")" +
                                          base::DidYouMean(name, names)};
}

std::vector<RenderPathInfo> RenderPaths() {
    Registry& r = Paths();
    std::lock_guard lock(r.mutex);
    std::vector<RenderPathInfo> out;
    for (const auto& p : r.paths) {
        out.push_back({std::string(p->Name()), std::string(p->Summary())});
    }
    return out;
}

}  // namespace kiln::runtime
