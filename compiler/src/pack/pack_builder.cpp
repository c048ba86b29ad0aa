#include "pack/pack_builder.h"

#include <cstring>

#include <xxhash.h>

#include "kiln/pack/records.h"
#include "kiln/pack/seal.h"

namespace kiln::pack_builder {

using namespace kiln::pack;

StrRef PackBuilder::Str(std::string_view s) {
    auto [it, inserted] = string_offsets_.try_emplace(std::string(s), 0);
    if (inserted) {
        it->second = static_cast<uint32_t>(strings_.size());
        strings_.append(s);
    }
    return StrRef{it->second, static_cast<uint32_t>(s.size())};
}

uint32_t PackBuilder::AddModule(Stage stage,
                                std::span<const uint32_t> words,
                                const spirv::Reflection& reflection) {
    const uint64_t hash = XXH64(words.data(), words.size_bytes(), 0);
    // Reflection of an existing module with the same bytes must match too (names are reflected
    // before debug info is stripped, so equal bytes can in principle carry other names).
    auto [lo, hi] = module_by_hash_.equal_range(hash);
    for (auto it = lo; it != hi; ++it) {
        const ModuleRec& m = modules_[it->second];
        if (m.stage != uint32_t(stage) || m.spirv_size != words.size_bytes() ||
            std::memcmp(spirv_.data() + m.spirv_offset, words.data(), words.size_bytes()) != 0) {
            continue;
        }
        if (*reflections_[it->second] == reflection)
            return it->second;
    }

    ModuleRec m;
    m.spirv_offset = static_cast<uint32_t>(spirv_.size());
    m.spirv_size = static_cast<uint32_t>(words.size_bytes());
    m.hash = hash;
    m.stage = uint32_t(stage);
    const auto* bytes = reinterpret_cast<const uint8_t*>(words.data());
    spirv_.insert(spirv_.end(), bytes, bytes + words.size_bytes());
    m.first_interface = static_cast<uint32_t>(interface_.size());
    for (const spirv::InterfaceVar& v : reflection.interface) {
        interface_.push_back({Str(v.name), Str(v.semantic), v.location, v.direction,
                              uint32_t(v.base_type), v.vecsize});
    }
    m.interface_count = static_cast<uint32_t>(reflection.interface.size());
    m.first_block = static_cast<uint32_t>(blocks_.size());
    for (const spirv::Block& b : reflection.blocks) {
        blocks_.push_back({Str(b.name), uint32_t(b.kind), b.set, b.binding, b.size,
                           static_cast<uint32_t>(members_.size()),
                           static_cast<uint32_t>(b.members.size())});
        for (const spirv::BlockMember& mem : b.members) {
            members_.push_back({Str(mem.name), mem.offset, mem.size, uint32_t(mem.base_type),
                                mem.vecsize, mem.columns, mem.array_size});
        }
    }
    m.block_count = static_cast<uint32_t>(reflection.blocks.size());
    m.first_resource = static_cast<uint32_t>(resources_.size());
    for (const spirv::Resource& r : reflection.resources) {
        resources_.push_back({Str(r.name), uint32_t(r.kind), r.set, r.binding, uint32_t(r.dim),
                              r.arrayed ? 1u : 0u, r.array_size});
    }
    m.resource_count = static_cast<uint32_t>(reflection.resources.size());
    const uint32_t index = static_cast<uint32_t>(modules_.size());
    modules_.push_back(m);
    reflections_.push_back(&reflection);
    module_by_hash_.emplace(hash, index);
    return index;
}

namespace {

struct SectionData {
    SectionTag tag;
    uint32_t record_count;
    std::vector<uint8_t> bytes;
};

template <class Rec>
SectionData Records(SectionTag tag, const std::vector<Rec>& recs) {
    ByteWriter w;
    for (const Rec& r : recs)
        w.Record(r);
    return {tag, static_cast<uint32_t>(recs.size()), std::move(w.bytes())};
}

}  // namespace

uint32_t PackBuilder::AddStages(const VariantStagesRec& r) {
    if (r.geometry_module == kNoModule && r.tess_control_module == kNoModule &&
        r.tess_eval_module == kNoModule)
        return 0;
    for (size_t i = 0; i < stages_.size(); ++i) {
        const VariantStagesRec& o = stages_[i];
        if (o.geometry_module == r.geometry_module &&
            o.tess_control_module == r.tess_control_module &&
            o.tess_eval_module == r.tess_eval_module)
            return static_cast<uint32_t>(i + 1);
    }
    stages_.push_back(r);
    return static_cast<uint32_t>(stages_.size());
}

std::vector<uint8_t> PackBuilder::Finish(MetaRec meta) {
    meta.module_count = module_count();
    meta.variant_count = static_cast<uint32_t>(variants.size());
    std::vector<SectionData> sections;
    sections.push_back(Records(SectionTag::kMeta, std::vector<MetaRec>{meta}));
    sections.push_back(Records(SectionTag::kShaders, shaders));
    sections.push_back(Records(SectionTag::kProperties, properties));
    sections.push_back(Records(SectionTag::kAttributes, attributes));
    sections.push_back(Records(SectionTag::kPasses, passes));
    sections.push_back(Records(SectionTag::kTags, tags));
    sections.push_back(Records(SectionTag::kStates, states));
    sections.push_back(Records(SectionTag::kKeywordSets, keyword_sets));
    sections.push_back(Records(SectionTag::kKeywords, keywords));
    sections.push_back(Records(SectionTag::kVariants, variants));
    if (!aliases.empty())
        sections.push_back(Records(SectionTag::kKeywordAliases, aliases));
    if (!stages_.empty())
        sections.push_back(Records(SectionTag::kVariantStages, stages_));
    if (!grabs.empty())
        sections.push_back(Records(SectionTag::kGrabPasses, grabs));
    sections.push_back(Records(SectionTag::kModules, modules_));
    sections.push_back(Records(SectionTag::kInterface, interface_));
    sections.push_back(Records(SectionTag::kBlocks, blocks_));
    sections.push_back(Records(SectionTag::kMembers, members_));
    sections.push_back(Records(SectionTag::kResources, resources_));
    sections.push_back({SectionTag::kSpirv, 0, std::move(spirv_)});
    sections.push_back({SectionTag::kStrings, 0, {strings_.begin(), strings_.end()}});
    // SUMS last: a record per section above but SPRV (each module has its hash in MODL), then
    // the header's and table's (Seal fills them in).
    std::vector<SectionSumRec> sums;
    for (const SectionData& s : sections) {
        if (s.tag != SectionTag::kSpirv)
            sums.push_back({uint32_t(s.tag), 0, 0});
    }
    sums.push_back({kTableSumTag, 0, 0});
    sections.push_back(Records(SectionTag::kSums, sums));

    const uint32_t count = static_cast<uint32_t>(sections.size());
    uint64_t offset = kHeaderSize + uint64_t{count} * kSectionEntrySize;
    std::vector<SectionEntry> table;
    for (const SectionData& s : sections) {
        offset = (offset + kSectionAlignment - 1) / kSectionAlignment * kSectionAlignment;
        table.push_back({uint32_t(s.tag), s.record_count, offset, s.bytes.size()});
        offset += s.bytes.size();
    }
    Header header;
    header.section_count = count;
    header.file_size = offset;

    ByteWriter w;
    w.bytes().reserve(offset);  // one allocation: a large pack is not copied as it grows
    w.Record(header);
    for (const SectionEntry& e : table)
        w.Record(e);
    for (const SectionData& s : sections) {
        w.PadTo(kSectionAlignment);
        w.PutBytes(s.bytes);
    }
    std::vector<uint8_t> out = std::move(w.bytes());
    Seal(out);  // the per-section sums, then the whole-file checksum
    return out;
}

}  // namespace kiln::pack_builder
