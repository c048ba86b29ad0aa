// Pack::Open with OpenChecks::kOnFirstUse (format 1.4): the same records as a fully checked open,
// damage in the variant data reported at its first read and never returned, SPIR-V checked
// against its module's hash, and every other byte a sum covers checked at open.
#include <gtest/gtest.h>

#include <thread>

#include "kiln/pack/reader.h"
#include "kiln/pack/seal.h"

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::pack {
namespace {

const std::vector<uint8_t>& CompiledPack() {
    static const std::vector<uint8_t> bytes = [] {
        DiagnosticList diags;
        CompileOutput out = CompileShaders({test::DataPath("data/compile/multi_light.shader"),
                                            test::DataPath("data/stages/geometry.shader")},
                                           {}, diags);
        EXPECT_TRUE(out.ok) << test::Brief(diags);
        return out.pack;
    }();
    return bytes;
}

// The section table, read by hand.
std::vector<SectionEntry> Table(const std::vector<uint8_t>& b) {
    std::vector<SectionEntry> out;
    const uint32_t n = b[12] | b[13] << 8 | b[14] << 16 | uint32_t(b[15]) << 24;
    for (uint32_t i = 0; i < n; ++i) {
        ByteReader r(std::span<const uint8_t>(b).subspan(kHeaderSize + i * kSectionEntrySize,
                                                         kSectionEntrySize));
        out.push_back(r.Record<SectionEntry>());
    }
    return out;
}

SectionEntry Section(const std::vector<uint8_t>& b, SectionTag tag) {
    for (const SectionEntry& e : Table(b)) {
        if (e.tag == uint32_t(tag))
            return e;
    }
    ADD_FAILURE() << "no such section";
    return {};
}

Pack Deferred(const std::vector<uint8_t>& b) {
    Result<Pack> opened = Pack::Open(b, OpenChecks::kOnFirstUse);
    EXPECT_TRUE(opened) << opened.error().message;
    return opened ? std::move(opened).value() : Pack();
}

TEST(PackDeferred, ReadsWhatAFullyCheckedOpenReads) {
    const std::vector<uint8_t>& b = CompiledPack();
    ASSERT_GT(Section(b, SectionTag::kSums).size, 0u) << "the writer seals per section";
    Pack full;
    ASSERT_TRUE(test::OpenInto(b, full));
    EXPECT_FALSE(full.deferred());
    const Pack lazy = Deferred(b);
    EXPECT_TRUE(lazy.deferred());
    EXPECT_EQ(lazy.format_minor(), 4);
    ASSERT_EQ(lazy.Count(SectionTag::kVariants), full.Count(SectionTag::kVariants));
    for (uint32_t pass = 0; pass < full.Count(SectionTag::kPasses); ++pass) {
        const PassRec p = full.Pass(pass).value();
        for (uint32_t v = p.first_variant; v < p.first_variant + p.variant_count; ++v) {
            const VariantRec fv = full.Variant(v).value();
            const VariantRec lv = lazy.Variant(v).value();
            EXPECT_EQ(lv.key, fv.key);
            EXPECT_EQ(lazy.FindVariant(pass, VariantKey(fv.key)), v);
            EXPECT_EQ(lazy.ModulesOf(lv), full.ModulesOf(fv));
            for (uint32_t m : lazy.ModulesOf(lv)) {
                const std::span<const uint8_t> a = lazy.Spirv(lazy.Module(m).value());
                const std::span<const uint8_t> f = full.Spirv(full.Module(m).value());
                ASSERT_FALSE(a.empty());
                EXPECT_TRUE(std::equal(a.begin(), a.end(), f.begin(), f.end()));
            }
        }
    }
}

// A byte of each variant-data section changed (and the whole-file checksum resealed, which a
// deferred open does not read): open succeeds, then the first read reports the section, no
// record of it is returned, and a fully checked open refuses the pack.
TEST(PackDeferred, DamagedVariantDataIsReportedAtFirstReadAndNeverReturned) {
    for (SectionTag tag : {SectionTag::kVariants, SectionTag::kVariantStages, SectionTag::kModules,
                           SectionTag::kInterface, SectionTag::kBlocks, SectionTag::kMembers,
                           SectionTag::kResources}) {
        std::vector<uint8_t> b = CompiledPack();
        const SectionEntry e = Section(b, tag);
        ASSERT_GT(e.size, 0u);
        b[e.offset + e.size / 2] ^= 0x10;
        const Pack lazy = Deferred(b);
        const Status checked = lazy.CheckVariantData();
        ASSERT_FALSE(checked.ok());
        EXPECT_EQ(checked.error().code, DiagCode::kPackChecksum);
        const std::string tag_name{char(e.tag), char(e.tag >> 8), char(e.tag >> 16),
                                   char(e.tag >> 24)};
        EXPECT_NE(checked.error().message.find("section " + tag_name), std::string::npos)
            << checked.error().message;
        EXPECT_FALSE(lazy.Variant(0).ok());
        EXPECT_FALSE(lazy.Module(0).ok());
        for (uint32_t pass = 0; pass < lazy.Count(SectionTag::kPasses); ++pass)
            EXPECT_FALSE(lazy.FindVariant(pass, VariantKey()));
        EXPECT_FALSE(Pack::Open(b)) << "the whole-file checksum still covers it";
    }
}

// Every bit flip is found by the time the bytes it is in are read: at open, by the first read
// of the variant data, or (SPIR-V) when its module's code is read. The whole-file checksum and
// the padding between sections, which a deferred open does not read, are the only exceptions;
// a fully checked open finds those too.
TEST(PackDeferred, EveryBitFlipIsFoundByTheTimeItsBytesAreRead) {
    const std::vector<uint8_t>& full = CompiledPack();
    const std::vector<SectionEntry> table = Table(full);
    const SectionEntry spirv = Section(full, SectionTag::kSpirv);
    auto unread = [&](size_t i) {
        if (i >= kChecksumOffset && i < kChecksumOffset + 8)
            return true;
        if (i < kHeaderSize + table.size() * kSectionEntrySize)
            return false;
        for (const SectionEntry& e : table) {
            if (i >= e.offset && i < e.offset + e.size)
                return false;
        }
        return true;
    };
    std::vector<uint8_t> b = full;
    size_t at_open = 0, at_first_read = 0, in_spirv = 0, unread_bytes = 0;
    for (size_t i = 0; i < b.size(); ++i) {
        b[i] ^= uint8_t(1u << (i % 8));
        Result<Pack> opened = Pack::Open(b, OpenChecks::kOnFirstUse);
        if (!opened) {
            ++at_open;
        } else if (!opened.value().CheckVariantData().ok()) {
            ++at_first_read;
        } else if (i >= spirv.offset && i < spirv.offset + spirv.size) {
            const Pack& p = opened.value();
            bool found = false;
            for (uint32_t m = 0; m < p.Count(SectionTag::kModules); ++m)
                found = found || p.Spirv(p.Module(m).value()).empty();
            EXPECT_TRUE(found) << "SPIR-V flip at byte " << i << " read back unchanged";
            ++in_spirv;
        } else {
            EXPECT_TRUE(unread(i)) << "flip at byte " << i << " not found";
            ++unread_bytes;
            EXPECT_FALSE(Pack::Open(b));
        }
        b[i] ^= uint8_t(1u << (i % 8));
    }
    EXPECT_GT(at_open, 0u);
    EXPECT_GT(at_first_read, 0u);
    EXPECT_GT(in_spirv, 0u);
    std::printf("flips found at open %zu, at the first read %zu, in SPIR-V %zu; unread %zu\n",
                at_open, at_first_read, in_spirv, unread_bytes);
}

TEST(PackDeferred, EveryTruncatedPrefixIsRejectedAtOpen) {
    const std::vector<uint8_t>& full = CompiledPack();
    for (size_t n = 0; n < full.size(); ++n) {
        const std::span<const uint8_t> prefix(full.data(), n);
        ASSERT_FALSE(Pack::Open(prefix, OpenChecks::kOnFirstUse)) << n;
    }
}

// A pack without SUMS (the section renamed to one the reader does not know, as a format 1.3
// pack has none) is checked whole at open, whatever the caller asked.
TEST(PackDeferred, APackWithoutSumsIsCheckedWholeAtOpen) {
    std::vector<uint8_t> b = CompiledPack();
    const std::vector<SectionEntry> table = Table(b);
    for (size_t i = 0; i < table.size(); ++i) {
        if (table[i].tag == uint32_t(SectionTag::kSums))
            b[kHeaderSize + i * kSectionEntrySize] = 'X';
    }
    test::ResealPack(b);
    ASSERT_TRUE(Pack::Open(b, OpenChecks::kOnFirstUse));
    EXPECT_FALSE(Pack::Open(b, OpenChecks::kOnFirstUse).value().deferred());
    b[Section(b, SectionTag::kVariants).offset + 1] ^= 1;  // now caught at open
    const Result<Pack> damaged = Pack::Open(b, OpenChecks::kOnFirstUse);
    ASSERT_FALSE(damaged);
    EXPECT_EQ(damaged.error().code, DiagCode::kPackChecksum);
}

// SUMS must name every section once: a record renamed leaves a section without a sum.
TEST(PackDeferred, SumsThatMissASectionAreRefused) {
    std::vector<uint8_t> b = CompiledPack();
    const SectionEntry sums = Section(b, SectionTag::kSums);
    b[sums.offset] = 'Z';  // the first record's tag: now a section the reader does not know
    Seal(b);
    for (OpenChecks checks : {OpenChecks::kAll, OpenChecks::kOnFirstUse}) {
        const Result<Pack> opened = Pack::Open(b, checks);
        ASSERT_FALSE(opened);
        EXPECT_NE(opened.error().message.find("has no sum in SUMS"), std::string::npos)
            << opened.error().message;
    }
}

// Threads that read a fresh pack at once run its deferred checks once and all see the records.
TEST(PackDeferred, ThreadsShareOneCheck) {
    const Pack lazy = Deferred(CompiledPack());
    const VariantRec first = Pack(lazy).Variant(0).value();  // a copy shares the check
    const Pack fresh = Deferred(CompiledPack());
    std::vector<std::thread> threads;
    std::atomic<int> found{0};
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&] {
            if (fresh.FindVariant(first.pass, VariantKey(first.key)) == 0u)
                ++found;
        });
    }
    for (std::thread& t : threads)
        t.join();
    EXPECT_EQ(found.load(), 4);
}

}  // namespace
}  // namespace kiln::pack
