#include "hlsl/plan_memo.h"

#include <algorithm>

namespace kiln::hlsl {

PlanMemo::Node* PlanMemo::Node::Child(const MacroValue& value) const {
    for (const auto& [seen, child] : next) {
        if (seen == value)
            return child.get();
    }
    return nullptr;
}

std::shared_ptr<const IncludeWalk> PlanMemo::Find(const std::shared_ptr<const SourceFile>& file,
                                                  const std::string& context,
                                                  const PpMacros& macros) {
    std::lock_guard<std::mutex> lock(mu_);
    const auto tree = trees_.find(Key(file.get(), context));
    if (tree == trees_.end())
        return nullptr;
    const Node* node = &tree->second.root;
    while (!node->walk) {
        if (node->name.empty())
            return nullptr;  // nothing kept here yet
        node = node->Child(macros.Value(node->name));
        if (!node)
            return nullptr;
    }
    ++tree->second.hits;
    return node->walk;
}

bool PlanMemo::Open(const std::shared_ptr<const SourceFile>& file, const std::string& context) {
    std::lock_guard<std::mutex> lock(mu_);
    if (bytes_ >= kMaxBytes)
        return false;
    const auto tree = trees_.find(Key(file.get(), context));
    if (tree == trees_.end())
        return true;
    const Tree& t = tree->second;
    return t.walks < kMaxWalksPerFile &&
           (t.walks < kTrialWalks || t.hits >= t.walks * kHitsPerWalk);
}

void PlanMemo::Add(const std::shared_ptr<const SourceFile>& file,
                   const std::string& context,
                   std::shared_ptr<const IncludeWalk> walk) {
    std::lock_guard<std::mutex> lock(mu_);
    Tree& tree = trees_[Key(file.get(), context)];
    tree.file = file;
    if (bytes_ >= kMaxBytes || tree.walks >= kMaxWalksPerFile)
        return;
    Node* node = &tree.root;
    for (const auto& [name, value] : walk->reads) {
        // A walk that read the same values so far read the same next name; a node that says
        // otherwise (a file that changed under the same address cannot: it is kept) is left.
        if (node->walk || (!node->name.empty() && node->name != name))
            return;
        node->name = name;
        Node* next = node->Child(value);
        if (!next) {
            node->next.emplace_back(value, std::make_unique<Node>());
            next = node->next.back().second.get();
        }
        node = next;
    }
    if (!node->name.empty())
        return;
    if (!node->walk)
        ++tree.walks;
    else
        bytes_ -= std::min(bytes_, node->walk->bytes);
    bytes_ += walk->bytes;
    node->walk = std::move(walk);
}

}  // namespace kiln::hlsl
