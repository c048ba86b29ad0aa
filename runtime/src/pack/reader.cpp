#include "kiln/pack/reader.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <utility>

#include <xxhash.h>

#include "kiln/base/files.h"
#include "kiln/base/text.h"
#include "kiln/pack/names.h"

#include "kiln/pack/pass_id.h"

namespace kiln::pack {
namespace {

constexpr SectionTag kAllTags[] = {
    SectionTag::kStrings,       SectionTag::kMeta,       SectionTag::kShaders,
    SectionTag::kProperties,    SectionTag::kAttributes, SectionTag::kPasses,
    SectionTag::kTags,          SectionTag::kStates,     SectionTag::kKeywordSets,
    SectionTag::kKeywords,      SectionTag::kVariants,   SectionTag::kModules,
    SectionTag::kSpirv,         SectionTag::kInterface,  SectionTag::kBlocks,
    SectionTag::kMembers,       SectionTag::kResources,  SectionTag::kKeywordAliases,
    SectionTag::kVariantStages, SectionTag::kGrabPasses,
};

// Sections a pack may leave out (later minor versions' additions); absent means empty.
bool Optional(SectionTag tag) {
    return tag == SectionTag::kKeywordAliases || tag == SectionTag::kVariantStages ||
           tag == SectionTag::kGrabPasses;
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

}  // namespace

MappedFile::MappedFile(MappedFile&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
    if (this != &other) {
        this->~MappedFile();
        data_ = std::exchange(other.data_, nullptr);
        size_ = std::exchange(other.size_, 0);
    }
    return *this;
}

MappedFile::~MappedFile() {
    if (data_ != nullptr && size_ > 0) {
        munmap(const_cast<uint8_t*>(data_), size_);
    }
}

Result<MappedFile> MappedFile::Map(const std::string& path) {
    if (path == base::kStandardStream) {
        // Standard input (kiln info -): its bytes copied into an anonymous mapping, which is
        // page-aligned as a file's is and unmapped the same way.
        Result<std::string> read = base::ReadRegularFile(path, uint64_t{4} << 30);
        if (!read)
            return read.error();
        MappedFile out;
        if (read.value().empty())
            return out;
        void* p = mmap(nullptr, read.value().size(), PROT_READ | PROT_WRITE,
                       MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) {
            return Error{DiagCode::kCannotReadFile,
                         std::string("cannot hold standard input: ") + std::strerror(errno)};
        }
        std::memcpy(p, read.value().data(), read.value().size());
        out.data_ = static_cast<const uint8_t*>(p);
        out.size_ = read.value().size();
        return out;
    }
    // O_NONBLOCK: opening a FIFO must not wait for a writer (fstat then refuses it).
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        return Error{DiagCode::kCannotReadFile,
                     "cannot open '" + path + "': " + std::strerror(errno)};
    }
    struct stat st {};
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return Error{DiagCode::kCannotReadFile, "'" + path + "' is not a regular file"};
    }
    base::NoteInputFile(path);
    MappedFile out;
    if (st.st_size == 0) {
        close(fd);
        return out;  // an empty mapping; Pack::Open reports it as truncated
    }
    void* p = mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    close(fd);
    if (p == MAP_FAILED) {
        return Error{DiagCode::kCannotReadFile,
                     "cannot map '" + path + "': " + std::strerror(errno)};
    }
    out.data_ = static_cast<const uint8_t*>(p);
    out.size_ = static_cast<size_t>(st.st_size);
    return out;
}

size_t Pack::Index(SectionTag tag) {
    for (size_t i = 0; i < kSectionSlots; ++i) {
        if (kAllTags[i] == tag)
            return i;
    }
    return 0;
}

std::string_view Pack::String(StrRef ref) const {
    const SectionEntry& s = sections_[Index(SectionTag::kStrings)];
    if (ref.offset > s.size || ref.length > s.size - ref.offset)
        return {};
    return {reinterpret_cast<const char*>(bytes_.data() + s.offset + ref.offset), ref.length};
}

Result<std::string_view> Pack::Keyword(uint32_t i) const {
    if (i >= Count(SectionTag::kKeywords)) {
        return OutOfRange(SectionTag::kKeywords, i);
    }
    return KeywordAt(i);
}

Error Pack::OutOfRange(SectionTag tag, uint32_t index) const {
    const uint32_t t = uint32_t(tag);
    const std::string name{char(t), char(t >> 8), char(t >> 16), char(t >> 24)};
    return Error{DiagCode::kIndexOutOfRange, "record " + std::to_string(index) + " of section " +
                                                 name + " is out of range (the pack has " +
                                                 std::to_string(Count(tag)) + ")"};
}

std::span<const uint32_t> Pack::SpirvWords(const ModuleRec& module) const {
    static_assert(std::endian::native == std::endian::little, "SPIR-V words are little-endian");
    const std::span<const uint8_t> bytes = Spirv(module);
    if (reinterpret_cast<uintptr_t>(bytes.data()) % alignof(uint32_t) != 0) {
        return {};
    }
    return {reinterpret_cast<const uint32_t*>(bytes.data()), bytes.size() / 4};
}

std::span<const uint8_t> Pack::Spirv(const ModuleRec& module) const {
    const SectionEntry& s = sections_[Index(SectionTag::kSpirv)];
    if (module.spirv_offset > s.size || module.spirv_size > s.size - module.spirv_offset)
        return {};
    return bytes_.subspan(s.offset + module.spirv_offset, module.spirv_size);
}

Result<Pack> Pack::Open(std::span<const uint8_t> bytes) {
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
    // Checksum over the whole file with the checksum field read as zero.
    XXH64_state_t* state = XXH64_createState();
    XXH64_reset(state, 0);
    XXH64_update(state, bytes.data(), kChecksumOffset);
    const uint8_t zeros[8] = {};
    XXH64_update(state, zeros, sizeof zeros);
    XXH64_update(state, bytes.data() + kHeaderSize, bytes.size() - kHeaderSize);
    const uint64_t sum = XXH64_digest(state);
    XXH64_freeState(state);
    if (sum != h.checksum) {
        return Error{DiagCode::kPackChecksum,
                     "pack checksum does not match its contents (file corrupted)"};
    }
    Pack out;
    out.bytes_ = bytes;
    out.header_ = h;
    if (Status valid = out.Validate(); !valid.ok())
        return valid.error();
    return out;
}

Status Pack::Validate() {
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
    if (Count(SectionTag::kMeta) != 1)
        return Corrupt("META must hold exactly one record");

    const uint32_t strings = static_cast<uint32_t>(sections_[Index(SectionTag::kStrings)].size);
    auto str_ok = [&](StrRef s) { return s.offset <= strings && s.length <= strings - s.offset; };
    auto fail = [](const char* what, uint32_t i) {
        return Corrupt(std::string(what) + " record " + std::to_string(i) + " is out of bounds");
    };
    const uint32_t n_props = Count(SectionTag::kProperties),
                   n_attrs = Count(SectionTag::kAttributes), n_passes = Count(SectionTag::kPasses),
                   n_tags = Count(SectionTag::kTags), n_states = Count(SectionTag::kStates),
                   n_sets = Count(SectionTag::kKeywordSets), n_kw = Count(SectionTag::kKeywords),
                   n_vars = Count(SectionTag::kVariants), n_mods = Count(SectionTag::kModules),
                   n_io = Count(SectionTag::kInterface), n_blocks = Count(SectionTag::kBlocks),
                   n_members = Count(SectionTag::kMembers), n_res = Count(SectionTag::kResources),
                   n_shaders = Count(SectionTag::kShaders);
    if (!str_ok(meta().producer))
        return fail("META", 0);
    for (uint32_t i = 0; i < n_shaders; ++i) {
        const ShaderRec s = Record<ShaderRec>(SectionTag::kShaders, i);
        if (!str_ok(s.name) || !str_ok(s.fallback) ||
            !RangeOk(s.first_property, s.property_count, n_props) ||
            !RangeOk(s.first_pass, s.pass_count, n_passes)) {
            return fail("SHDR", i);
        }
    }
    for (uint32_t i = 0; i < n_props; ++i) {
        const auto p = Record<PropertyRec>(SectionTag::kProperties, i);
        if (!str_ok(p.name) || !str_ok(p.display_name) || !str_ok(p.texture_default) ||
            p.type > uint32_t(PropertyType::kTextureAny) ||
            !RangeOk(p.first_attribute, p.attribute_count, n_attrs)) {
            return fail("PROP", i);
        }
    }
    for (uint32_t i = 0; i < n_attrs; ++i) {
        const auto a = Record<AttributeRec>(SectionTag::kAttributes, i);
        if (!str_ok(a.name) || !str_ok(a.args))
            return fail("ATTR", i);
    }
    for (uint32_t i = 0; i < n_tags; ++i) {
        const auto t = Record<TagRec>(SectionTag::kTags, i);
        if (!str_ok(t.key) || !str_ok(t.value))
            return fail("TAGS", i);
    }
    for (uint32_t i = 0; i < n_states; ++i) {
        const auto s = Record<StateRec>(SectionTag::kStates, i);
        if (!str_ok(s.text) || s.field >= kStateFieldCount ||
            s.kind > uint32_t(StateKind::kPropertyRef)) {
            return fail("RSTA", i);
        }
    }
    for (uint32_t i = 0; i < n_kw; ++i) {
        if (!str_ok(Record<StrRef>(SectionTag::kKeywords, i)))
            return fail("KWRD", i);
    }
    for (uint32_t i = 0; i < n_sets; ++i) {
        const KeywordSetRec k = Record<KeywordSetRec>(SectionTag::kKeywordSets, i);
        if (!RangeOk(k.first_keyword, k.keyword_count, n_kw) || k.keyword_count == 0 ||
            k.key_bits > 32 || k.key_shift > 64 - k.key_bits ||
            k.key_bits != BitsForCount(k.keyword_count)) {
            return fail("KSET", i);
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
            return fail("KALI", i);
        }
        if (i > 0) {
            const auto prev = Record<KeywordAliasRec>(SectionTag::kKeywordAliases, i - 1);
            if (prev.keyword_set > a.keyword_set ||
                (prev.keyword_set == a.keyword_set && prev.from >= a.from)) {
                return Corrupt("keyword alias table is not sorted at record " + std::to_string(i));
            }
        }
    }
    for (uint32_t i = 0; i < n_passes; ++i) {
        const PassRec p = Record<PassRec>(SectionTag::kPasses, i);
        if (!str_ok(p.name) || p.shader >= n_shaders ||
            !RangeOk(p.first_tag, p.tag_count, n_tags) ||
            !RangeOk(p.first_state, p.state_count, n_states) ||
            !RangeOk(p.first_keyword_set, p.keyword_set_count, n_sets) ||
            !RangeOk(p.first_variant, p.variant_count, n_vars)) {
            return fail("PASS", i);
        }
        for (uint32_t v = p.first_variant; v < p.first_variant + p.variant_count; ++v) {
            if (Record<VariantRec>(SectionTag::kVariants, v).pass != i)
                return fail("PASS", i);
        }
        // A GrabPass draws nothing: no keyword sets, no variants, no render state.
        if ((p.flags & kPassGrab) &&
            (p.keyword_set_count != 0 || p.variant_count != 0 || p.state_count != 0)) {
            return fail("PASS", i);
        }
    }
    // One texture per GrabPass, sorted by pass, naming only flagged passes.
    const uint32_t n_grabs = Count(SectionTag::kGrabPasses);
    uint32_t flagged = 0;
    for (uint32_t i = 0; i < n_passes; ++i)
        flagged += (Record<PassRec>(SectionTag::kPasses, i).flags & kPassGrab) != 0;
    if (flagged != n_grabs)
        return Corrupt("GRAB holds " + std::to_string(n_grabs) + " records for " +
                       std::to_string(flagged) + " GrabPass passes");
    for (uint32_t i = 0; i < n_grabs; ++i) {
        const GrabRec g = Record<GrabRec>(SectionTag::kGrabPasses, i);
        if (g.pass >= n_passes ||
            !(Record<PassRec>(SectionTag::kPasses, g.pass).flags & kPassGrab) ||
            !str_ok(g.texture) ||
            (i > 0 && Record<GrabRec>(SectionTag::kGrabPasses, i - 1).pass >= g.pass)) {
            return fail("GRAB", i);
        }
    }
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
            return fail("VSTG", i);
        }
    }
    for (uint32_t i = 0; i < n_vars; ++i) {
        const VariantRec v = Record<VariantRec>(SectionTag::kVariants, i);
        if (v.pass >= n_passes || !stage_ok(v.vertex_module, Stage::kVertex, false) ||
            !stage_ok(v.fragment_module, Stage::kFragment, false) || v.stages > n_stages) {
            return fail("VARI", i);
        }
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
            return fail("MODL", i);
        }
    }
    for (uint32_t i = 0; i < n_io; ++i) {
        const auto v = Record<InterfaceVarRec>(SectionTag::kInterface, i);
        if (!str_ok(v.name) || !str_ok(v.semantic))
            return fail("IOVR", i);
    }
    for (uint32_t i = 0; i < n_blocks; ++i) {
        const auto b = Record<BlockRec>(SectionTag::kBlocks, i);
        if (!str_ok(b.name) || !RangeOk(b.first_member, b.member_count, n_members)) {
            return fail("BLCK", i);
        }
    }
    for (uint32_t i = 0; i < n_members; ++i) {
        if (!str_ok(Record<MemberRec>(SectionTag::kMembers, i).name))
            return fail("MEMB", i);
    }
    for (uint32_t i = 0; i < n_res; ++i) {
        if (!str_ok(Record<ResourceRec>(SectionTag::kResources, i).name))
            return fail("RSRC", i);
    }
    return {};
}

std::optional<uint32_t> Pack::FindShader(std::string_view name) const {
    for (uint32_t i = 0; i < Count(SectionTag::kShaders); ++i) {
        if (String(Record<ShaderRec>(SectionTag::kShaders, i).name) == name)
            return i;
    }
    return std::nullopt;
}

std::optional<uint32_t> Pack::FindPass(uint32_t shader, std::string_view name) const {
    if (shader >= Count(SectionTag::kShaders))
        return std::nullopt;
    const ShaderRec s = Record<ShaderRec>(SectionTag::kShaders, shader);
    for (uint32_t i = s.first_pass; i < s.first_pass + s.pass_count; ++i) {
        if (base::EqualsIgnoreCase(PassLabel(*this, i), name))
            return i;  // the pass's one name (kiln/pack/pass_id.h)
    }
    for (uint32_t i = s.first_pass; i < s.first_pass + s.pass_count; ++i) {
        if (base::EqualsIgnoreCase(String(Record<PassRec>(SectionTag::kPasses, i).name), name))
            return i;
    }
    for (uint32_t i = s.first_pass; i < s.first_pass + s.pass_count; ++i) {
        if (base::EqualsIgnoreCase(LightModeOf(*this, i), name))
            return i;
    }
    return std::nullopt;
}

std::optional<std::string_view> Pack::GrabTexture(uint32_t pass) const {
    uint32_t lo = 0, hi = Count(SectionTag::kGrabPasses);  // sorted by pass
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        const GrabRec g = Record<GrabRec>(SectionTag::kGrabPasses, mid);
        if (g.pass == pass)
            return String(g.texture);
        if (g.pass < pass) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return std::nullopt;
}

uint32_t Pack::AliasOf(uint32_t keyword_set, uint32_t index) const {
    const uint32_t n = Count(SectionTag::kKeywordAliases);
    uint32_t lo = 0, hi = n;  // sorted by (set, from): a binary search
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        const auto a = Record<KeywordAliasRec>(SectionTag::kKeywordAliases, mid);
        if (a.keyword_set == keyword_set && a.from == index)
            return a.to;
        if (a.keyword_set < keyword_set || (a.keyword_set == keyword_set && a.from < index)) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return index;
}

std::optional<uint32_t> Pack::FindVariant(uint32_t pass, VariantKey key) const {
    if (pass >= Count(SectionTag::kPasses))
        return std::nullopt;
    const PassRec p = Record<PassRec>(SectionTag::kPasses, pass);
    if (Count(SectionTag::kKeywordAliases) > 0) {
        for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
            const KeywordSetRec set = Record<KeywordSetRec>(SectionTag::kKeywordSets, s);
            key.Set(set.key_shift, set.key_bits, AliasOf(s, key.Get(set.key_shift, set.key_bits)));
        }
    }
    uint32_t lo = p.first_variant, hi = p.first_variant + p.variant_count;
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        const uint64_t k = Record<VariantRec>(SectionTag::kVariants, mid).key;
        if (k == key.bits())
            return mid;
        if (k < key.bits()) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return std::nullopt;
}

VariantKey Pack::KeyFor(uint32_t pass, const std::vector<std::string>& enabled) const {
    VariantKey key;
    if (pass >= Count(SectionTag::kPasses))
        return key;
    const PassRec p = Record<PassRec>(SectionTag::kPasses, pass);
    for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
        const KeywordSetRec set = Record<KeywordSetRec>(SectionTag::kKeywordSets, s);
        for (uint32_t k = 0; k < set.keyword_count; ++k) {
            const std::string_view kw = KeywordAt(set.first_keyword + k);
            if (!kw.empty() && std::find(enabled.begin(), enabled.end(), kw) != enabled.end()) {
                key.Set(set.key_shift, set.key_bits, k);
                break;
            }
        }
    }
    return key;
}

Status Pack::CheckKeywords(uint32_t pass, const std::vector<std::string>& enabled) const {
    if (pass >= Count(SectionTag::kPasses))
        return OutOfRange(SectionTag::kPasses, pass);
    std::vector<std::string> declared;
    const PassRec p = Record<PassRec>(SectionTag::kPasses, pass);
    for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
        const KeywordSetRec set = Record<KeywordSetRec>(SectionTag::kKeywordSets, s);
        for (uint32_t k = 0; k < set.keyword_count; ++k) {
            const std::string_view kw = KeywordAt(set.first_keyword + k);
            if (!kw.empty())
                declared.emplace_back(kw);
        }
    }
    for (const std::string& name : enabled) {
        if (std::find(declared.begin(), declared.end(), name) == declared.end()) {
            return Error{
                DiagCode::kUnknownKeyword,
                "keyword '" + name + "' is not declared by the pass" + DidYouMean(name, declared)};
        }
    }
    return {};
}

std::vector<std::string> Pack::KeywordsOf(uint32_t pass, VariantKey key) const {
    std::vector<std::string> out;
    if (pass >= Count(SectionTag::kPasses))
        return out;
    const PassRec p = Record<PassRec>(SectionTag::kPasses, pass);
    for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
        const KeywordSetRec set = Record<KeywordSetRec>(SectionTag::kKeywordSets, s);
        const uint32_t index = key.Get(set.key_shift, set.key_bits);
        if (index < set.keyword_count) {
            const std::string_view kw = KeywordAt(set.first_keyword + index);
            if (!kw.empty())
                out.emplace_back(kw);
        }
    }
    return out;
}

}  // namespace kiln::pack
