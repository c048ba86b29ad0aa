// Builds a variant pack in memory (format: runtime/include/kiln/pack/format.h and
// docs/pack-format.md). Strings are interned and SPIR-V modules deduplicated by content, both in
// first-insertion order, so identical inputs give identical bytes.
#ifndef KILN_PACK_PACK_BUILDER_H_
#define KILN_PACK_PACK_BUILDER_H_

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "kiln/pack/format.h"
#include "spirv/reflection.h"

namespace kiln::pack_builder {

class PackBuilder {
  public:
    pack::StrRef Str(std::string_view s);
    // Adds a module unless an identical one (same stage, bytes and reflection) exists; returns
    // its index. `reflection` is compared with later modules' and must outlive the builder.
    uint32_t AddModule(pack::Stage stage,
                       std::span<const uint32_t> words,
                       const spirv::Reflection& reflection);

    std::vector<pack::ShaderRec> shaders;
    std::vector<pack::PropertyRec> properties;
    std::vector<pack::AttributeRec> attributes;
    std::vector<pack::PassRec> passes;
    std::vector<pack::TagRec> tags;
    std::vector<pack::StateRec> states;
    std::vector<pack::KeywordSetRec> keyword_sets;
    std::vector<pack::StrRef> keywords;
    std::vector<pack::VariantRec> variants;      // must be sorted by (pass, key) before Finish
    std::vector<pack::KeywordAliasRec> aliases;  // sorted by (set, from); written when any
    std::vector<pack::GrabRec> grabs;            // sorted by pass; written when any

    // VariantRec::stages for a variant with these geometry/tessellation modules: 0 when it has
    // none, else 1 + the index of an identical record (added unless one exists).
    uint32_t AddStages(const pack::VariantStagesRec& stages);

    uint32_t module_count() const { return static_cast<uint32_t>(modules_.size()); }

    // Serializes everything, with the checksum filled in; once (the SPIR-V moves into the pack).
    std::vector<uint8_t> Finish(pack::MetaRec meta);

  private:
    std::string strings_;
    std::unordered_map<std::string, uint32_t> string_offsets_;
    std::vector<uint8_t> spirv_;
    std::vector<pack::ModuleRec> modules_;
    std::vector<const spirv::Reflection*> reflections_;  // per module, for the dedup comparison
    std::multimap<uint64_t, uint32_t> module_by_hash_;
    std::vector<pack::InterfaceVarRec> interface_;
    std::vector<pack::BlockRec> blocks_;
    std::vector<pack::MemberRec> members_;
    std::vector<pack::ResourceRec> resources_;
    std::vector<pack::VariantStagesRec> stages_;
};

}  // namespace kiln::pack_builder

#endif  // KILN_PACK_PACK_BUILDER_H_
