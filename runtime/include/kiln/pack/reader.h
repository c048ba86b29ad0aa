// Reading a variant pack. Pack::Open validates everything before the pack is used: magic, format
// version, checksum, every section bound, every string reference and every cross-record index.
// After a successful Open no accessor can read outside the bytes. The bytes are not copied: the
// caller keeps them alive (a MappedFile, or a buffer).
//
// Opened with OpenChecks::kOnFirstUse (format 1.4 packs, which carry a sum per section), open time
// does not grow with the variants: the sections that grow with them are checked, sums and
// records, the first time one of them is read, and a module's SPIR-V against its hash whenever it
// is read. Until then nothing of them is returned; a damaged one is an error from that first read
// on (CheckVariantData), never a record.
#ifndef KILN_PACK_READER_H_
#define KILN_PACK_READER_H_

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/pack/format.h"
#include "kiln/pack/records.h"
#include "kiln/pack/variant_key.h"
#include "kiln/result.h"

namespace kiln::pack {

// Errors are kiln::Error with DiagCode kCannotReadFile (cannot open or map the file),
// kPackTruncated (shorter than its header says), kNotAPack (wrong magic), kPackVersion (another
// format major version), kPackChecksum (bytes changed after writing) or kBadPack (structurally
// invalid: a bound, index or alignment).

// A read-only file mapping.
class MappedFile {
  public:
    MappedFile() = default;
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    MappedFile(MappedFile&& other) noexcept;
    MappedFile& operator=(MappedFile&& other) noexcept;
    ~MappedFile();

    static Result<MappedFile> Map(const std::string& path);
    std::span<const uint8_t> bytes() const { return {data_, size_}; }

  private:
    const uint8_t* data_ = nullptr;
    size_t size_ = 0;
};

// What Pack::Open checks before it returns.
enum class OpenChecks {
    kAll,  // the whole-file checksum, then every section's records
    // The header and section table against their sum, and the sections that grow with shaders
    // and passes (strings, shaders, properties, passes, tags, state, keywords) against theirs and
    // record by record; the variant data (VARI, VSTG, MODL, IOVR, BLCK, MEMB, RSRC) on first use,
    // SPIR-V per module on every read. A pack without per-section sums (format 1.3 and older)
    // gets kAll.
    kOnFirstUse,
};

class Pack {
  public:
    // The pack views `bytes`, which must outlive it.
    static Result<Pack> Open(std::span<const uint8_t> bytes, OpenChecks checks = OpenChecks::kAll);

    // The deferred checks of kOnFirstUse, run once (the first caller runs them, others wait):
    // success at once for a pack opened with kAll. Every accessor of the variant data calls it;
    // an engine that wants the damage reported at load calls it there.
    Status CheckVariantData() const;
    // Whether the variant data is checked at first use (format 1.4 opened with kOnFirstUse).
    bool deferred() const { return deferred_ != nullptr; }

    uint16_t format_minor() const { return header_.format_minor; }
    MetaRec meta() const {
        return Count(SectionTag::kMeta) ? Record<MetaRec>(SectionTag::kMeta, 0) : MetaRec{};
    }
    std::string_view String(StrRef ref) const;

    uint32_t Count(SectionTag tag) const { return sections_[Index(tag)].record_count; }
    // Record `index` of a section; an error when index >= Count(tag). Indices read from a pack's
    // records are always in range (Open checked them); an index an engine computes is checked.
    template <class Rec>
    Result<Rec> Get(SectionTag tag, uint32_t index) const {
        if (index >= Count(tag)) {
            return OutOfRange(tag, index);
        }
        if (deferred_ != nullptr && IsVariantData(tag)) {
            if (Status checked = CheckVariantData(); !checked.ok())
                return checked.error();
        }
        return Record<Rec>(tag, index);
    }
    // The sections kOnFirstUse checks on first use.
    static bool IsVariantData(SectionTag tag);
    Result<ShaderRec> Shader(uint32_t i) const { return Get<ShaderRec>(SectionTag::kShaders, i); }
    Result<PassRec> Pass(uint32_t i) const { return Get<PassRec>(SectionTag::kPasses, i); }
    Result<ModuleRec> Module(uint32_t i) const { return Get<ModuleRec>(SectionTag::kModules, i); }
    // The geometry and tessellation modules of a variant (kNoModule where it has none).
    Result<VariantStagesRec> Stages(const VariantRec& v) const {
        if (v.stages == 0)
            return VariantStagesRec{};
        return Get<VariantStagesRec>(SectionTag::kVariantStages, v.stages - 1);
    }
    // Every module of a variant: vertex, fragment, then geometry, hull and domain where it has
    // them (an empty list when the stages record cannot be read).
    std::vector<uint32_t> ModulesOf(const VariantRec& v) const {
        std::vector<uint32_t> out = {v.vertex_module, v.fragment_module};
        if (const Result<VariantStagesRec> s = Stages(v); s) {
            for (uint32_t m : {s.value().geometry_module, s.value().tess_control_module,
                               s.value().tess_eval_module}) {
                if (m != kNoModule)
                    out.push_back(m);
            }
        } else {
            out.clear();
        }
        return out;
    }
    Result<VariantRec> Variant(uint32_t i) const {
        return Get<VariantRec>(SectionTag::kVariants, i);
    }
    Result<KeywordSetRec> KeywordSet(uint32_t i) const {
        return Get<KeywordSetRec>(SectionTag::kKeywordSets, i);
    }
    Result<std::string_view> Keyword(uint32_t i) const;
    // A module's SPIR-V; empty for a record that is not this pack's (and, for a pack whose
    // variant data is checked on first use, for bytes that do not match the module's hash).
    std::span<const uint8_t> Spirv(const ModuleRec& module) const;
    // The same as 32-bit words (the bytes are little-endian and 4-aligned within the pack);
    // empty when the caller's buffer is not 4-aligned (a mapped file always is).
    std::span<const uint32_t> SpirvWords(const ModuleRec& module) const;

    std::optional<uint32_t> FindShader(std::string_view name) const;
    // A pass by its one name (PassLabel, kiln/pack/pass_id.h), else by its Name, else by its
    // LightMode tag (first match in SubShader order); case-insensitive.
    std::optional<uint32_t> FindPass(uint32_t shader, std::string_view name) const;
    // Binary search of the sorted variant table: O(log n). Keyword aliases (KALI) are applied
    // first: a key that enables an aliased keyword finds the variant of the keyword it aliases.
    std::optional<uint32_t> FindVariant(uint32_t pass, VariantKey key) const;
    // A GrabPass's texture (GrabRec): its name, "" for `GrabPass { }` (into _GrabTexture before
    // each object); none when `pass` is not a GrabPass. O(log n).
    std::optional<std::string_view> GrabTexture(uint32_t pass) const;
    // The keyword index that `index` of keyword set `keyword_set` aliases, or `index` itself.
    uint32_t AliasOf(uint32_t keyword_set, uint32_t index) const;

    // The key selecting, in each keyword set, the enabled keyword (or the set's first keyword
    // when none of its keywords is enabled). Names in no set are ignored.
    VariantKey KeyFor(uint32_t pass, const std::vector<std::string>& enabled) const;
    // Success when every name in `enabled` is a keyword of the pass; else an error naming the
    // first that is not, with the closest declared keyword (K4015). For keyword lists that must not
    // hold typos (kiln extract); KeyFor ignores such names, as Unity ignores a material keyword
    // its shader does not declare.
    Status CheckKeywords(uint32_t pass, const std::vector<std::string>& enabled) const;
    // The keyword names a key selects (no-keyword entries omitted).
    std::vector<std::string> KeywordsOf(uint32_t pass, VariantKey key) const;
    // Keyword `i` of the keyword table (KeywordSetRec::first_keyword + k); "" out of range and
    // for a set's no-keyword entry.
    std::string_view KeywordName(uint32_t i) const {
        return i < Count(SectionTag::kKeywords) ? KeywordAt(i) : std::string_view();
    }

  private:
    struct Deferred;                             // reader_validate.cpp
    struct SectionSums;                          // reader_validate.cpp
    static constexpr size_t kSectionSlots = 21;  // every SectionTag (reader.cpp checks)
    template <class Rec>
    Rec Record(SectionTag tag, uint32_t index) const {  // index < Count(tag)
        const SectionEntry& s = sections_[Index(tag)];
        const size_t size = RecordSize<Rec>();
        ByteReader r(bytes_.subspan(s.offset + size_t{index} * size, size));
        return r.Record<Rec>();
    }
    std::string_view KeywordAt(uint32_t i) const {
        return String(Record<StrRef>(SectionTag::kKeywords, i));
    }
    Error OutOfRange(SectionTag tag, uint32_t index) const;
    static size_t Index(SectionTag tag);
    Status ValidateTable(SectionSums& sums);
    Status ValidateShaders() const;
    Status ValidateVariantData() const;

    std::span<const uint8_t> bytes_;
    Header header_;
    SectionEntry sections_[kSectionSlots]{};
    std::shared_ptr<Deferred> deferred_;  // null: everything was checked at open
};

}  // namespace kiln::pack

#endif  // KILN_PACK_READER_H_
