// The node hierarchy of a glTF scene, checked and flattened without recursion. glTF 2.0 (section
// 3.5.2, "Nodes and Hierarchy"): the hierarchy is a set of disjoint strict trees, so a node has
// at most one parent and a scene's root nodes have none. A child index that does not exist, a
// node with two parents (a DAG: its subtree would be instanced once per path, exponentially),
// a child listed twice, or a root that is someone's child is an error; together these rule out
// cycles, so the walk below visits every node at most once whatever the file holds.
#ifndef KILN_RUNTIME_SCENE_NODE_TREE_H_
#define KILN_RUNTIME_SCENE_NODE_TREE_H_

#include <tiny_gltf.h>

#include <optional>
#include <string>
#include <vector>

#include "kiln/result.h"

namespace kiln::runtime {

struct NodeVisit {
    int node = 0;
    int parent = -1;  // -1 for a root; a parent always comes before its children
};

// The nodes of the scene `roots` (all parentless nodes when the file has no scenes), pre-order.
Status WalkNodeTree(const tinygltf::Model& model,
                    const std::string& path,
                    const std::vector<int>* roots,
                    std::vector<NodeVisit>& out);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_SCENE_NODE_TREE_H_
