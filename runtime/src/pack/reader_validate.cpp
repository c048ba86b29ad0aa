// Pack::Open: the header, the section table and every record checked (all at open, or the
// variant data on first use, kiln/pack/reader.h), and the per-section sums of format 1.4.
#include "kiln/pack/reader.h"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <mutex>
#include <string>

#include <xxhash.h>

namespace kiln::pack {
namespace {

constexpr SectionTag kAllTags[] = {
    SectionTag::kStrings,       SectionTag::kMeta,       SectionTag::kShaders,
    SectionTag::kProperties,    SectionTag::kAttributes, SectionTag::kPasses,
    SectionTag::kTags,          SectionTag::kStates,     SectionTag::kKeywordSets,
    SectionTag::kKeywords,      SectionTag::kVariants,   SectionTag::kModules,
    SectionTag::kSpirv,         SectionTag::kInterface,  SectionTag::kBlocks,
    SectionTag::kMembers,       SectionTag::kResources,  SectionTag::kKeywordAliases,
    SectionTag::kVariantStages, SectionTag::kGrabPasses, SectionTag::kSums,
};

// Sections a pack may leave out (later minor versions' additions); absent means empty.
bool Optional(SectionTag tag) {
    return tag == SectionTag::kKeywordAliases || tag == SectionTag::kVariantStages ||
           tag == SectionTag::kGrabPasses || tag == SectionTag::kSums;
}

// Encoded record size per section; 0 for raw byte sections.
size_t RecordSizeOf(SectionTag tag) {
    switch (tag) {
        case SectionTag::kStrings:
        case SectionTag::kSpirv:
            return 0;
        case SectionTag::kMeta:
            return RecordSize<MetaRec>();
        case SectionTag::kShaders:
            return RecordSize<ShaderRec>();
        case SectionTag::kProperties:
            return RecordSize<PropertyRec>();
        case SectionTag::kAttributes:
            return RecordSize<AttributeRec>();
        case SectionTag::kPasses:
            return RecordSize<PassRec>();
        case SectionTag::kTags:
            return RecordSize<TagRec>();
        case SectionTag::kStates:
            return RecordSize<StateRec>();
        case SectionTag::kKeywordSets:
            return RecordSize<KeywordSetRec>();
        case SectionTag::kKeywords:
            return RecordSize<StrRef>();
        case SectionTag::kVariants:
            return RecordSize<VariantRec>();
        case SectionTag::kModules:
            return RecordSize<ModuleRec>();
        case SectionTag::kInterface:
            return RecordSize<InterfaceVarRec>();
        case SectionTag::kBlocks:
            return RecordSize<BlockRec>();
        case SectionTag::kMembers:
            return RecordSize<MemberRec>();
        case SectionTag::kResources:
            return RecordSize<ResourceRec>();
        case SectionTag::kKeywordAliases:
            return RecordSize<KeywordAliasRec>();
        case SectionTag::kVariantStages:
            return RecordSize<VariantStagesRec>();
        case SectionTag::kGrabPasses:
            return RecordSize<GrabRec>();
        case SectionTag::kSums:
            return RecordSize<SectionSumRec>();
    }
    return 0;
}

std::string TagName(uint32_t tag) {
    std::string s;
    for (int i = 0; i < 4; ++i) {
        const char c = static_cast<char>(tag >> (8 * i));
        s += (c >= 0x20 && c < 0x7f) ? c : '?';
    }
    return s;
}

Error Corrupt(std::string message) {
    return Error{DiagCode::kBadPack, std::move(message)};
}

bool RangeOk(uint32_t first, uint32_t count, uint32_t total) {
    return first <= total && count <= total - first;
}

Error OutOfBounds(const char* section, uint32_t i) {
    return Corrupt(std::string(section) + " record " + std::to_string(i) + " is out of bounds");
}

// XXH64 of the header, its checksum field read as zero, then of the `more` bytes after it.
uint64_t HeaderSum(std::span<const uint8_t> bytes, size_t more) {
    XXH64_state_t* state = XXH64_createState();
    XXH64_reset(state, 0);
    XXH64_update(state, bytes.data(), kChecksumOffset);
    const uint8_t zeros[8] = {};
    XXH64_update(state, zeros, sizeof zeros);
    XXH64_update(state, bytes.data() + kHeaderSize, more);
    const uint64_t sum = XXH64_digest(state);
    XXH64_freeState(state);
    return sum;
}

Error SumMismatch(uint32_t tag) {
    return Error{DiagCode::kPackChecksum,
                 (tag == kTableSumTag ? std::string("pack header") : "section " + TagName(tag)) +
                     " does not match its checksum (file corrupted)"};
}

}  // namespace

// The checks kOnFirstUse defers, run once and shared by the copies of a pack.
struct Pack::Deferred {
    uint64_t sums[kSectionSlots] = {};
    std::once_flag once;
    Status status;
    std::atomic<bool> passed{false};
};

size_t Pack::Index(SectionTag tag) {
    for (size_t i = 0; i < kSectionSlots; ++i) {
        if (kAllTags[i] == tag)
            return i;
    }
    return 0;
}

bool Pack::IsVariantData(SectionTag tag) {
    switch (tag) {
        case SectionTag::kVariants:
        case SectionTag::kVariantStages:
        case SectionTag::kModules:
        case SectionTag::kInterface:
        case SectionTag::kBlocks:
        case SectionTag::kMembers:
        case SectionTag::kResources:
            return true;
        default:
            return false;
    }
}

// What the SUMS section holds, by section slot (format 1.4).
struct Pack::SectionSums {
    bool present = false;  // the pack has a SUMS section
    uint64_t of[kSectionSlots] = {};
    bool has[kSectionSlots] = {};
    uint64_t table = 0;
    bool has_table = false;
};

Result<Pack> Pack::Open(std::span<const uint8_t> bytes, OpenChecks checks) {
    if (bytes.size() < kHeaderSize) {
        return Error{DiagCode::kPackTruncated, "file is " + std::to_string(bytes.size()) +
                                                   " bytes, shorter than a pack header (32 bytes)"};
    }
    ByteReader hr(bytes.first(kHeaderSize));
    const Header h = hr.Record<Header>();
    if (h.magic != kMagic) {
        return Error{DiagCode::kNotAPack, "not a kiln pack (bad magic)"};
    }
    if (h.format_major != kFormatMajor) {
        return Error{DiagCode::kPackVersion, "pack format " + std::to_string(h.format_major) + "." +
                                                 std::to_string(h.format_minor) +
                                                 " is not supported (reader knows " +
                                                 std::to_string(kFormatMajor) + ".x)"};
    }
    if (h.file_size > bytes.size()) {
        return Error{DiagCode::kPackTruncated,
                     "pack is truncated: header says " + std::to_string(h.file_size) +
                         " bytes, file has " + std::to_string(bytes.size())};
    }
    if (h.file_size < bytes.size()) {
        return Corrupt("pack has " + std::to_string(bytes.size() - h.file_size) +
                       " trailing bytes after its end");
    }
    if (h.header_size != kHeaderSize) {
        return Corrupt("unexpected header size " + std::to_string(h.header_size));
    }
    Pack out;
    out.bytes_ = bytes;
    out.header_ = h;
    auto whole_file = [&]() -> Status {
        if (HeaderSum(bytes, bytes.size() - kHeaderSize) != h.checksum) {
            return Error{DiagCode::kPackChecksum,
                         "pack checksum does not match its contents (file corrupted)"};
        }
        return {};
    };
    SectionSums sums;
    if (checks == OpenChecks::kAll) {
        // The whole file first: any changed byte is reported as a checksum mismatch.
        if (Status sum = whole_file(); !sum.ok())
            return sum.error();
    }
    if (Status table = out.ValidateTable(sums); !table.ok())
        return table.error();
    if (checks == OpenChecks::kOnFirstUse && !sums.present) {
        if (Status sum = whole_file(); !sum.ok())  // a pack of format 1.3 or older
            return sum.error();
    }
    const bool deferred = checks == OpenChecks::kOnFirstUse && sums.present;
    if (deferred) {
        const uint64_t table_bytes = uint64_t{h.section_count} * kSectionEntrySize;
        if (HeaderSum(bytes, table_bytes) != sums.table)
            return SumMismatch(kTableSumTag);
        for (size_t i = 0; i < kSectionSlots; ++i) {
            const SectionEntry& e = out.sections_[i];
            if (!sums.has[i] || IsVariantData(kAllTags[i]) || kAllTags[i] == SectionTag::kSpirv)
                continue;
            if (XXH64(bytes.data() + e.offset, e.size, 0) != sums.of[i])
                return SumMismatch(e.tag);
        }
    }
    if (Status shaders = out.ValidateShaders(); !shaders.ok())
        return shaders.error();
    if (deferred) {
        out.deferred_ = std::make_shared<Deferred>();
        std::copy(std::begin(sums.of), std::end(sums.of), out.deferred_->sums);
    } else if (Status variants = out.ValidateVariantData(); !variants.ok()) {
        return variants.error();
    }
    return out;
}

Status Pack::CheckVariantData() const {
    if (deferred_ == nullptr || deferred_->passed.load(std::memory_order_acquire))
        return {};
    Deferred& d = *deferred_;
    std::call_once(d.once, [&] {
        for (size_t i = 0; i < kSectionSlots && d.status.ok(); ++i) {
            const SectionEntry& e = sections_[i];
            if (IsVariantData(kAllTags[i]) && e.tag != 0 &&
                XXH64(bytes_.data() + e.offset, e.size, 0) != d.sums[i]) {
                d.status = SumMismatch(e.tag);
            }
        }
        if (d.status.ok())
            d.status = ValidateVariantData();
        d.passed.store(d.status.ok(), std::memory_order_release);
    });
    return d.status;
}

Status Pack::ValidateTable(SectionSums& sums) {
    const uint64_t size = bytes_.size();
    if (header_.section_count > kMaxSections ||
        kHeaderSize + uint64_t{header_.section_count} * kSectionEntrySize > size) {
        return Corrupt("section table does not fit in the file");
    }
    static_assert(std::size(kAllTags) == kSectionSlots, "a slot for every section tag");
    bool seen[kSectionSlots] = {};
    for (uint32_t i = 0; i < header_.section_count; ++i) {
        ByteReader r(
            bytes_.subspan(kHeaderSize + size_t{i} * kSectionEntrySize, kSectionEntrySize));
        const SectionEntry e = r.Record<SectionEntry>();
        const auto* known =
            std::find(std::begin(kAllTags), std::end(kAllTags), static_cast<SectionTag>(e.tag));
        if (known == std::end(kAllTags))
            continue;  // unknown sections are skipped (minor additions)
        const size_t slot = static_cast<size_t>(known - std::begin(kAllTags));
        const std::string name = TagName(e.tag);
        if (seen[slot])
            return Corrupt("section " + name + " appears twice");
        seen[slot] = true;
        if (e.offset % kSectionAlignment != 0 || e.offset < kHeaderSize || e.offset > size ||
            e.size > size - e.offset) {
            return Corrupt("section " + name + " lies outside the file or is misaligned");
        }
        const size_t rec = RecordSizeOf(*known);
        if (rec == 0 ? e.record_count != 0 : uint64_t{e.record_count} * rec != e.size) {
            return Corrupt("section " + name + " size does not match its record count");
        }
        sections_[slot] = e;
    }
    for (size_t i = 0; i < kSectionSlots; ++i) {
        if (!seen[i] && !Optional(kAllTags[i]))
            return Corrupt("section " + TagName(uint32_t(kAllTags[i])) + " is missing");
    }
    // SUMS (format 1.4): one sum per section present but SPRV and SUMS (a module's SPIR-V has its
    // hash in MODL), and one for the header and table; no other.
    sums.present = seen[Index(SectionTag::kSums)];
    const uint32_t n_sums = Count(SectionTag::kSums);
    for (uint32_t i = 0; i < n_sums; ++i) {
        const auto s = Record<SectionSumRec>(SectionTag::kSums, i);
        if (s.reserved != 0)
            return Corrupt("SUMS record " + std::to_string(i) + " has a reserved field set");
        if (s.tag == kTableSumTag) {
            if (sums.has_table)
                return Corrupt("SUMS holds two sums for the section table");
            sums.has_table = true;
            sums.table = s.sum;
            continue;
        }
        const auto* known =
            std::find(std::begin(kAllTags), std::end(kAllTags), static_cast<SectionTag>(s.tag));
        if (known == std::end(kAllTags))
            continue;  // a section this reader does not know
        const size_t slot = static_cast<size_t>(known - std::begin(kAllTags));
        if (!seen[slot] || *known == SectionTag::kSums || *known == SectionTag::kSpirv ||
            sums.has[slot])
            return Corrupt("SUMS record " + std::to_string(i) +
                           " names a section that is absent, SPRV, SUMS itself, or summed twice");
        sums.has[slot] = true;
        sums.of[slot] = s.sum;
    }
    if (sums.present) {
        for (size_t i = 0; i < kSectionSlots; ++i) {
            if (seen[i] && !sums.has[i] && kAllTags[i] != SectionTag::kSums &&
                kAllTags[i] != SectionTag::kSpirv)
                return Corrupt("section " + TagName(uint32_t(kAllTags[i])) + " has no sum in SUMS");
        }
        if (!sums.has_table)
            return Corrupt("SUMS has no sum for the section table");
    }
    return {};
}

Status Pack::ValidateShaders() const {
    if (Count(SectionTag::kMeta) != 1)
        return Corrupt("META must hold exactly one record");
    const uint32_t strings = static_cast<uint32_t>(sections_[Index(SectionTag::kStrings)].size);
    auto str_ok = [&](StrRef s) { return s.offset <= strings && s.length <= strings - s.offset; };
    const uint32_t n_props = Count(SectionTag::kProperties),
                   n_attrs = Count(SectionTag::kAttributes), n_passes = Count(SectionTag::kPasses),
                   n_tags = Count(SectionTag::kTags), n_states = Count(SectionTag::kStates),
                   n_sets = Count(SectionTag::kKeywordSets), n_kw = Count(SectionTag::kKeywords),
                   n_vars = Count(SectionTag::kVariants), n_shaders = Count(SectionTag::kShaders);
    if (!str_ok(meta().producer))
        return OutOfBounds("META", 0);
    for (uint32_t i = 0; i < n_shaders; ++i) {
        const ShaderRec s = Record<ShaderRec>(SectionTag::kShaders, i);
        if (!str_ok(s.name) || !str_ok(s.fallback) ||
            !RangeOk(s.first_property, s.property_count, n_props) ||
            !RangeOk(s.first_pass, s.pass_count, n_passes)) {
            return OutOfBounds("SHDR", i);
        }
    }
    for (uint32_t i = 0; i < n_props; ++i) {
        const auto p = Record<PropertyRec>(SectionTag::kProperties, i);
        if (!str_ok(p.name) || !str_ok(p.display_name) || !str_ok(p.texture_default) ||
            p.type > uint32_t(PropertyType::kTextureAny) ||
            !RangeOk(p.first_attribute, p.attribute_count, n_attrs)) {
            return OutOfBounds("PROP", i);
        }
    }
    for (uint32_t i = 0; i < n_attrs; ++i) {
        const auto a = Record<AttributeRec>(SectionTag::kAttributes, i);
        if (!str_ok(a.name) || !str_ok(a.args))
            return OutOfBounds("ATTR", i);
    }
    for (uint32_t i = 0; i < n_tags; ++i) {
        const auto t = Record<TagRec>(SectionTag::kTags, i);
        if (!str_ok(t.key) || !str_ok(t.value))
            return OutOfBounds("TAGS", i);
    }
    for (uint32_t i = 0; i < n_states; ++i) {
        const auto s = Record<StateRec>(SectionTag::kStates, i);
        if (!str_ok(s.text) || s.field >= kStateFieldCount ||
            s.kind > uint32_t(StateKind::kPropertyRef)) {
            return OutOfBounds("RSTA", i);
        }
    }
    for (uint32_t i = 0; i < n_kw; ++i) {
        if (!str_ok(Record<StrRef>(SectionTag::kKeywords, i)))
            return OutOfBounds("KWRD", i);
    }
    for (uint32_t i = 0; i < n_sets; ++i) {
        const KeywordSetRec k = Record<KeywordSetRec>(SectionTag::kKeywordSets, i);
        if (!RangeOk(k.first_keyword, k.keyword_count, n_kw) || k.keyword_count == 0 ||
            k.key_bits > 32 || k.key_shift > 64 - k.key_bits ||
            k.key_bits != BitsForCount(k.keyword_count)) {
            return OutOfBounds("KSET", i);
        }
    }
    // Aliases: sorted by (set, from), in range, to a lower keyword that is no alias itself.
    const uint32_t n_aliases = Count(SectionTag::kKeywordAliases);
    for (uint32_t i = 0; i < n_aliases; ++i) {
        const auto a = Record<KeywordAliasRec>(SectionTag::kKeywordAliases, i);
        if (a.keyword_set >= n_sets || a.to >= a.from ||
            a.from >=
                Record<KeywordSetRec>(SectionTag::kKeywordSets, a.keyword_set).keyword_count ||
            a.to >= Record<KeywordSetRec>(SectionTag::kKeywordSets, a.keyword_set).keyword_count ||
            AliasOf(a.keyword_set, a.to) != a.to) {
            return OutOfBounds("KALI", i);
        }
        if (i > 0) {
            const auto prev = Record<KeywordAliasRec>(SectionTag::kKeywordAliases, i - 1);
            if (prev.keyword_set > a.keyword_set ||
                (prev.keyword_set == a.keyword_set && prev.from >= a.from)) {
                return Corrupt("keyword alias table is not sorted at record " + std::to_string(i));
            }
        }
    }
    // Passes' variant ranges follow the passes' order and do not overlap (the variant table is
    // sorted by pass); ValidateVariantData checks that each variant lies in its own pass's range.
    uint32_t variants_end = 0;
    uint32_t flagged = 0;
    for (uint32_t i = 0; i < n_passes; ++i) {
        const PassRec p = Record<PassRec>(SectionTag::kPasses, i);
        if (!str_ok(p.name) || p.shader >= n_shaders ||
            !RangeOk(p.first_tag, p.tag_count, n_tags) ||
            !RangeOk(p.first_state, p.state_count, n_states) ||
            !RangeOk(p.first_keyword_set, p.keyword_set_count, n_sets) ||
            !RangeOk(p.first_variant, p.variant_count, n_vars) ||
            (p.variant_count != 0 && p.first_variant < variants_end)) {
            return OutOfBounds("PASS", i);
        }
        if (p.variant_count != 0)
            variants_end = p.first_variant + p.variant_count;
        // A GrabPass draws nothing: no keyword sets, no variants, no render state.
        if ((p.flags & kPassGrab) &&
            (p.keyword_set_count != 0 || p.variant_count != 0 || p.state_count != 0)) {
            return OutOfBounds("PASS", i);
        }
        flagged += (p.flags & kPassGrab) != 0;
    }
    // One texture per GrabPass, sorted by pass, naming only flagged passes.
    const uint32_t n_grabs = Count(SectionTag::kGrabPasses);
    if (flagged != n_grabs)
        return Corrupt("GRAB holds " + std::to_string(n_grabs) + " records for " +
                       std::to_string(flagged) + " GrabPass passes");
    for (uint32_t i = 0; i < n_grabs; ++i) {
        const GrabRec g = Record<GrabRec>(SectionTag::kGrabPasses, i);
        if (g.pass >= n_passes ||
            !(Record<PassRec>(SectionTag::kPasses, g.pass).flags & kPassGrab) ||
            !str_ok(g.texture) ||
            (i > 0 && Record<GrabRec>(SectionTag::kGrabPasses, i - 1).pass >= g.pass)) {
            return OutOfBounds("GRAB", i);
        }
    }
    return {};
}

Status Pack::ValidateVariantData() const {
    const uint32_t strings = static_cast<uint32_t>(sections_[Index(SectionTag::kStrings)].size);
    auto str_ok = [&](StrRef s) { return s.offset <= strings && s.length <= strings - s.offset; };
    const uint32_t n_passes = Count(SectionTag::kPasses), n_vars = Count(SectionTag::kVariants),
                   n_mods = Count(SectionTag::kModules), n_io = Count(SectionTag::kInterface),
                   n_blocks = Count(SectionTag::kBlocks), n_members = Count(SectionTag::kMembers),
                   n_res = Count(SectionTag::kResources);
    // A module of the stage a slot names, or (where `optional`) none.
    const auto stage_ok = [&](uint32_t module, Stage stage, bool optional) {
        if (module == kNoModule)
            return optional;
        return module < n_mods &&
               Record<ModuleRec>(SectionTag::kModules, module).stage == uint32_t(stage);
    };
    const uint32_t n_stages = Count(SectionTag::kVariantStages);
    for (uint32_t i = 0; i < n_stages; ++i) {
        const auto r = Record<VariantStagesRec>(SectionTag::kVariantStages, i);
        if (!stage_ok(r.geometry_module, Stage::kGeometry, true) ||
            !stage_ok(r.tess_control_module, Stage::kTessControl, true) ||
            !stage_ok(r.tess_eval_module, Stage::kTessEval, true) ||
            (r.tess_control_module == kNoModule) != (r.tess_eval_module == kNoModule)) {
            return OutOfBounds("VSTG", i);
        }
    }
    for (uint32_t i = 0; i < n_vars; ++i) {
        const VariantRec v = Record<VariantRec>(SectionTag::kVariants, i);
        if (v.pass >= n_passes || !stage_ok(v.vertex_module, Stage::kVertex, false) ||
            !stage_ok(v.fragment_module, Stage::kFragment, false) || v.stages > n_stages) {
            return OutOfBounds("VARI", i);
        }
        const PassRec p = Record<PassRec>(SectionTag::kPasses, v.pass);
        if (i < p.first_variant || i - p.first_variant >= p.variant_count)
            return OutOfBounds("VARI", i);  // outside its pass's range
        if (i > 0) {
            const VariantRec prev = Record<VariantRec>(SectionTag::kVariants, i - 1);
            if (prev.pass > v.pass || (prev.pass == v.pass && prev.key >= v.key)) {
                return Corrupt("variant table is not sorted at record " + std::to_string(i));
            }
        }
    }
    const uint64_t spirv_size = sections_[Index(SectionTag::kSpirv)].size;
    for (uint32_t i = 0; i < n_mods; ++i) {
        const ModuleRec m = Record<ModuleRec>(SectionTag::kModules, i);
        if (m.spirv_offset % 4 != 0 || m.spirv_size % 4 != 0 || m.spirv_size == 0 ||
            m.spirv_offset > spirv_size || m.spirv_size > spirv_size - m.spirv_offset ||
            m.stage >= kStageCount || !RangeOk(m.first_interface, m.interface_count, n_io) ||
            !RangeOk(m.first_block, m.block_count, n_blocks) ||
            !RangeOk(m.first_resource, m.resource_count, n_res)) {
            return OutOfBounds("MODL", i);
        }
    }
    for (uint32_t i = 0; i < n_io; ++i) {
        const auto v = Record<InterfaceVarRec>(SectionTag::kInterface, i);
        if (!str_ok(v.name) || !str_ok(v.semantic))
            return OutOfBounds("IOVR", i);
    }
    for (uint32_t i = 0; i < n_blocks; ++i) {
        const auto b = Record<BlockRec>(SectionTag::kBlocks, i);
        if (!str_ok(b.name) || !RangeOk(b.first_member, b.member_count, n_members))
            return OutOfBounds("BLCK", i);
    }
    for (uint32_t i = 0; i < n_members; ++i) {
        if (!str_ok(Record<MemberRec>(SectionTag::kMembers, i).name))
            return OutOfBounds("MEMB", i);
    }
    for (uint32_t i = 0; i < n_res; ++i) {
        if (!str_ok(Record<ResourceRec>(SectionTag::kResources, i).name))
            return OutOfBounds("RSRC", i);
    }
    return {};
}

}  // namespace kiln::pack
