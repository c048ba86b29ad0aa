#include "kiln/pack/seal.h"

#include <xxhash.h>

#include "kiln/pack/format.h"
#include "kiln/pack/records.h"

namespace kiln::pack {
namespace {

uint64_t Sum(std::span<const uint8_t> bytes) {
    return XXH64(bytes.data(), bytes.size(), 0);
}

void PutU64(std::span<uint8_t> at, uint64_t v) {
    for (int i = 0; i < 8; ++i)
        at[i] = uint8_t(v >> (8 * i));
}

// The section table's entries that lie inside the bytes.
std::vector<SectionEntry> Table(std::span<const uint8_t> bytes, uint32_t count) {
    std::vector<SectionEntry> out;
    for (uint32_t i = 0; i < count; ++i) {
        ByteReader r(bytes.subspan(kHeaderSize + size_t{i} * kSectionEntrySize, kSectionEntrySize));
        const SectionEntry e = r.Record<SectionEntry>();
        if (e.offset <= bytes.size() && e.size <= bytes.size() - e.offset)
            out.push_back(e);
    }
    return out;
}

}  // namespace

void Seal(std::span<uint8_t> bytes) {
    if (bytes.size() < kHeaderSize)
        return;
    PutU64(bytes.subspan(kChecksumOffset, 8), 0);
    ByteReader hr(bytes.first(kHeaderSize));
    const Header h = hr.Record<Header>();
    const uint32_t count = h.section_count;
    if (count <= kMaxSections &&
        kHeaderSize + uint64_t{count} * kSectionEntrySize <= bytes.size()) {
        const std::vector<SectionEntry> table = Table(bytes, count);
        const uint64_t table_sum = Sum(bytes.first(kHeaderSize + count * kSectionEntrySize));
        for (const SectionEntry& sums : table) {
            if (sums.tag != uint32_t(SectionTag::kSums))
                continue;
            const size_t n = sums.size / RecordSize<SectionSumRec>();
            for (size_t i = 0; i < n; ++i) {
                const size_t at = sums.offset + i * RecordSize<SectionSumRec>();
                ByteReader r(bytes.subspan(at, RecordSize<SectionSumRec>()));
                const SectionSumRec rec = r.Record<SectionSumRec>();
                uint64_t value = rec.sum;
                if (rec.tag == kTableSumTag) {
                    value = table_sum;
                } else {
                    for (const SectionEntry& e : table) {
                        if (e.tag == rec.tag && e.tag != uint32_t(SectionTag::kSums)) {
                            value = Sum(bytes.subspan(e.offset, e.size));
                            break;
                        }
                    }
                }
                PutU64(bytes.subspan(at + 8, 8), value);
            }
        }
    }
    PutU64(bytes.subspan(kChecksumOffset, 8), Sum(bytes));
}

}  // namespace kiln::pack
