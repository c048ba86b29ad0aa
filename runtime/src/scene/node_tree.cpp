#include "scene/node_tree.h"

#include <algorithm>

namespace kiln::runtime {
namespace {

std::string NodeName(const tinygltf::Model& model, int index) {
    const std::string& name = model.nodes[size_t(index)].name;
    return "node " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

Error SceneError(const std::string& path, const std::string& what) {
    return Error{DiagCode::kBadScene, path + ": " + what};
}

// Each node's parent (-1: none), or an error for a bad child index or a second parent.
Status Parents(const tinygltf::Model& model, const std::string& path, std::vector<int>& parent) {
    const size_t n = model.nodes.size();
    parent.assign(n, -1);
    for (size_t i = 0; i < n; ++i) {
        for (int child : model.nodes[i].children) {
            if (child < 0 || size_t(child) >= n) {
                return SceneError(path, NodeName(model, int(i)) + " has child " +
                                            std::to_string(child) + ", which does not exist (" +
                                            std::to_string(n) + " nodes)");
            }
            if (parent[size_t(child)] != -1 || size_t(child) == i) {
                const int other = parent[size_t(child)] == -1 ? int(i) : parent[size_t(child)];
                return SceneError(
                    path, NodeName(model, child) + " is a child of " + NodeName(model, other) +
                              (other == int(i) ? " twice" : " and of " + NodeName(model, int(i))) +
                              " (glTF node hierarchies are trees: one parent at most)");
            }
            parent[size_t(child)] = int(i);
        }
    }
    return {};
}

}  // namespace

Status WalkNodeTree(const tinygltf::Model& model,
                    const std::string& path,
                    const std::vector<int>* roots,
                    std::vector<NodeVisit>& out) {
    out.clear();
    std::vector<int> parent;
    if (Status e = Parents(model, path, parent); !e.ok())
        return e;
    std::vector<int> starts;
    if (roots == nullptr) {
        for (size_t i = 0; i < parent.size(); ++i) {
            if (parent[i] == -1)
                starts.push_back(int(i));
        }
    } else {
        starts = *roots;
    }
    std::vector<bool> root(model.nodes.size(), false);
    for (int r : starts) {
        if (r < 0 || size_t(r) >= model.nodes.size()) {
            return SceneError(path, "the scene's root node " + std::to_string(r) +
                                        " does not exist (" + std::to_string(model.nodes.size()) +
                                        " nodes)");
        }
        if (parent[size_t(r)] != -1 || root[size_t(r)]) {
            return SceneError(path, NodeName(model, r) +
                                        (root[size_t(r)] ? " is listed twice as a scene root"
                                                         : " is a scene root and a child of " +
                                                               NodeName(model, parent[size_t(r)])));
        }
        root[size_t(r)] = true;
    }
    // Depth-first with an explicit stack: a 100,000-node chain needs no call stack. With one
    // parent per node and parentless roots, no node is pushed twice.
    std::vector<NodeVisit> stack;
    for (auto it = starts.rbegin(); it != starts.rend(); ++it)
        stack.push_back({*it, -1});
    while (!stack.empty()) {
        const NodeVisit v = stack.back();
        stack.pop_back();
        out.push_back(v);
        const std::vector<int>& children = model.nodes[size_t(v.node)].children;
        for (auto it = children.rbegin(); it != children.rend(); ++it)
            stack.push_back({*it, v.node});
    }
    return {};
}

}  // namespace kiln::runtime
