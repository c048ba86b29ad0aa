// Field lists of the pack records: one Visit() per record names its fields in on-disk order. The
// writer and the reader both walk these lists, so the two sides cannot disagree on a layout.
#ifndef KILN_PACK_RECORDS_H_
#define KILN_PACK_RECORDS_H_

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "kiln/pack/format.h"

namespace kiln::pack {

template <class V>
constexpr void Visit(V& v, StrRef& r) {
    v(r.offset);
    v(r.length);
}
template <class V>
constexpr void Visit(V& v, Header& r) {
    v(r.magic);
    v(r.format_major);
    v(r.format_minor);
    v(r.header_size);
    v(r.section_count);
    v(r.file_size);
    v(r.checksum);
}
template <class V>
constexpr void Visit(V& v, SectionEntry& r) {
    v(r.tag);
    v(r.record_count);
    v(r.offset);
    v(r.size);
}
template <class V>
constexpr void Visit(V& v, MetaRec& r) {
    Visit(v, r.producer);
    v(r.opt_level);
    v(r.flags);
    v(r.variant_count);
    v(r.module_count);
}
template <class V>
constexpr void Visit(V& v, ShaderRec& r) {
    Visit(v, r.name);
    v(r.first_property);
    v(r.property_count);
    v(r.first_pass);
    v(r.pass_count);
    Visit(v, r.fallback);
}
template <class V>
constexpr void Visit(V& v, PropertyRec& r) {
    Visit(v, r.name);
    Visit(v, r.display_name);
    v(r.type);
    v(r.first_attribute);
    v(r.attribute_count);
    v(r.range_min);
    v(r.range_max);
    v(r.default_value);
    Visit(v, r.texture_default);
    v(r.reserved);
}
template <class V>
constexpr void Visit(V& v, AttributeRec& r) {
    Visit(v, r.name);
    Visit(v, r.args);
}
template <class V>
constexpr void Visit(V& v, PassRec& r) {
    Visit(v, r.name);
    v(r.shader);
    v(r.subshader);
    v(r.lod);
    v(r.first_tag);
    v(r.tag_count);
    v(r.first_state);
    v(r.state_count);
    v(r.first_keyword_set);
    v(r.keyword_set_count);
    v(r.first_variant);
    v(r.variant_count);
    v(r.flags);
}
template <class V>
constexpr void Visit(V& v, TagRec& r) {
    Visit(v, r.key);
    Visit(v, r.value);
}
template <class V>
constexpr void Visit(V& v, StateRec& r) {
    v(r.field);
    v(r.target);
    v(r.kind);
    v(r.number);
    Visit(v, r.text);
}
template <class V>
constexpr void Visit(V& v, KeywordSetRec& r) {
    v(r.kind);
    v(r.flags);
    v(r.first_keyword);
    v(r.keyword_count);
    v(r.key_shift);
    v(r.key_bits);
}
template <class V>
constexpr void Visit(V& v, KeywordAliasRec& r) {
    v(r.keyword_set);
    v(r.from);
    v(r.to);
    v(r.reserved);
}
template <class V>
constexpr void Visit(V& v, VariantRec& r) {
    v(r.pass);
    v(r.stages);
    v(r.key);
    v(r.vertex_module);
    v(r.fragment_module);
}
template <class V>
constexpr void Visit(V& v, VariantStagesRec& r) {
    v(r.geometry_module);
    v(r.tess_control_module);
    v(r.tess_eval_module);
    v(r.reserved);
}
template <class V>
constexpr void Visit(V& v, GrabRec& r) {
    v(r.pass);
    Visit(v, r.texture);
    v(r.reserved);
}
template <class V>
constexpr void Visit(V& v, ModuleRec& r) {
    v(r.spirv_offset);
    v(r.spirv_size);
    v(r.hash);
    v(r.stage);
    v(r.first_interface);
    v(r.interface_count);
    v(r.first_block);
    v(r.block_count);
    v(r.first_resource);
    v(r.resource_count);
    v(r.reserved);
}
template <class V>
constexpr void Visit(V& v, InterfaceVarRec& r) {
    Visit(v, r.name);
    Visit(v, r.semantic);
    v(r.location);
    v(r.direction);
    v(r.base_type);
    v(r.vecsize);
}
template <class V>
constexpr void Visit(V& v, BlockRec& r) {
    Visit(v, r.name);
    v(r.kind);
    v(r.set);
    v(r.binding);
    v(r.size);
    v(r.first_member);
    v(r.member_count);
}
template <class V>
constexpr void Visit(V& v, MemberRec& r) {
    Visit(v, r.name);
    v(r.offset);
    v(r.size);
    v(r.base_type);
    v(r.vecsize);
    v(r.columns);
    v(r.array_size);
}
template <class V>
constexpr void Visit(V& v, ResourceRec& r) {
    Visit(v, r.name);
    v(r.kind);
    v(r.set);
    v(r.binding);
    v(r.dim);
    v(r.arrayed);
    v(r.array_size);
}
template <class V>
constexpr void Visit(V& v, SectionSumRec& r) {
    v(r.tag);
    v(r.reserved);
    v(r.sum);
}

// Counts encoded bytes.
struct SizeVisitor {
    size_t size = 0;
    template <class T>
    constexpr void operator()(const T&) {
        size += sizeof(T);
    }
};

template <class Rec>
constexpr size_t RecordSize() {
    SizeVisitor v;
    Rec r{};
    Visit(v, r);
    return v.size;
}

static_assert(RecordSize<Header>() == kHeaderSize);
static_assert(RecordSize<SectionEntry>() == kSectionEntrySize);
static_assert(RecordSize<MetaRec>() == 24);
static_assert(RecordSize<ShaderRec>() == 32);
static_assert(RecordSize<PropertyRec>() == 64);
static_assert(RecordSize<AttributeRec>() == 16);
static_assert(RecordSize<PassRec>() == 56);
static_assert(RecordSize<TagRec>() == 16);
static_assert(RecordSize<StateRec>() == 24);
static_assert(RecordSize<KeywordSetRec>() == 24);
static_assert(RecordSize<KeywordAliasRec>() == 16);
static_assert(RecordSize<VariantStagesRec>() == 16);
static_assert(RecordSize<GrabRec>() == 16);
static_assert(RecordSize<SectionSumRec>() == 16);
static_assert(RecordSize<VariantRec>() == 24);
static_assert(RecordSize<ModuleRec>() == 48);
static_assert(RecordSize<InterfaceVarRec>() == 32);
static_assert(RecordSize<BlockRec>() == 32);
static_assert(RecordSize<MemberRec>() == 32);
static_assert(RecordSize<ResourceRec>() == 32);

// Appends little-endian bytes.
class ByteWriter {
  public:
    std::vector<uint8_t>& bytes() { return bytes_; }
    size_t size() const { return bytes_.size(); }

    template <class T>
    void operator()(const T& value) {
        Put(value);
    }
    void Put(uint16_t x) { PutLe(x, 2); }
    void Put(uint32_t x) { PutLe(x, 4); }
    void Put(int32_t x) { PutLe(static_cast<uint32_t>(x), 4); }
    void Put(uint64_t x) { PutLe(x, 8); }
    void Put(float x) { PutLe(std::bit_cast<uint32_t>(x), 4); }
    void Put(const std::array<char, 4>& a) {
        for (char c : a)
            bytes_.push_back(uint8_t(c));
    }
    void Put(const std::array<float, 4>& a) {
        for (float f : a)
            Put(f);
    }
    void PutBytes(std::span<const uint8_t> data) {
        bytes_.insert(bytes_.end(), data.begin(), data.end());
    }
    void PadTo(size_t alignment) {
        while (bytes_.size() % alignment)
            bytes_.push_back(0);
    }

    template <class Rec>
    void Record(Rec rec) {
        Visit(*this, rec);
    }

  private:
    void PutLe(uint64_t x, int n) {
        for (int i = 0; i < n; ++i)
            bytes_.push_back(uint8_t(x >> (8 * i)));
    }
    std::vector<uint8_t> bytes_;
};

// Reads little-endian bytes from a bounded span; never reads past its end. After any failed read
// ok() is false and every later read yields zeros.
class ByteReader {
  public:
    explicit ByteReader(std::span<const uint8_t> data) : data_(data) {}
    bool ok() const { return ok_; }

    template <class T>
    void operator()(T& value) {
        Get(value);
    }
    void Get(uint16_t& x) { x = static_cast<uint16_t>(GetLe(2)); }
    void Get(uint32_t& x) { x = static_cast<uint32_t>(GetLe(4)); }
    void Get(int32_t& x) { x = static_cast<int32_t>(static_cast<uint32_t>(GetLe(4))); }
    void Get(uint64_t& x) { x = GetLe(8); }
    void Get(float& x) { x = std::bit_cast<float>(static_cast<uint32_t>(GetLe(4))); }
    void Get(std::array<char, 4>& a) {
        for (char& c : a)
            c = static_cast<char>(GetLe(1));
    }
    void Get(std::array<float, 4>& a) {
        for (float& f : a)
            Get(f);
    }

    template <class Rec>
    Rec Record() {
        Rec rec{};
        Visit(*this, rec);
        return rec;
    }

  private:
    uint64_t GetLe(size_t n) {
        if (!ok_ || data_.size() - pos_ < n) {
            ok_ = false;
            return 0;
        }
        uint64_t x = 0;
        for (size_t i = 0; i < n; ++i)
            x |= uint64_t(data_[pos_ + i]) << (8 * i);
        pos_ += n;
        return x;
    }
    std::span<const uint8_t> data_;
    size_t pos_ = 0;
    bool ok_ = true;
};

}  // namespace kiln::pack

#endif  // KILN_PACK_RECORDS_H_
