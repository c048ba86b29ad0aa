// The file of a shader's modules (driver/module_bundle.h): what is written reads back the same; a
// file cut at any byte, an index that does not add up, a key twice or a malformed key is refused
// whole, never read in part or past its end; a payload whose hash fails is left out alone.
#include "driver/module_bundle.h"

#include <gtest/gtest.h>

#include "driver/cache.h"

namespace kiln::driver {
namespace {

using Modules = std::vector<std::pair<std::string, std::string>>;

const std::string kKeyA(32, 'a'), kKeyB(32, 'b'), kKeyC(32, '7');

Modules Sample() {
    return {{kKeyA, std::string("\x03\x02\x23\x07 module a", 14)},
            {kKeyB, ""},
            {kKeyC, std::string(1000, 'c')}};
}

TEST(ModuleBundle, WhatIsWrittenReadsBackTheSame) {
    const std::string file = BuildModuleBundle(Sample());
    EXPECT_EQ(file.size(),
              kModuleHeaderBytes + 14 + 0 + 1000 + 3 * kModuleIndexEntryBytes + kModuleFooterBytes);
    EXPECT_EQ(ReadModuleBundle(file), Sample());
    EXPECT_EQ(ReadModuleBundle(BuildModuleBundle({})), Modules{});
}

TEST(ModuleBundle, EveryTruncatedPrefixIsRefused) {
    const std::string file = BuildModuleBundle(Sample());
    for (size_t n = 0; n < file.size(); ++n)
        EXPECT_FALSE(ReadModuleBundle(std::string_view(file).substr(0, n))) << n;
    EXPECT_FALSE(ReadModuleBundle(file + "x"));  // the footer is not at the end
}

TEST(ModuleBundle, AChangedIndexOrFooterIsRefusedWhole) {
    const std::string file = BuildModuleBundle(Sample());
    const size_t index_at = file.size() - kModuleFooterBytes - 3 * kModuleIndexEntryBytes;
    for (size_t at = index_at; at < file.size(); ++at) {
        std::string changed = file;
        changed[at] = static_cast<char>(changed[at] ^ 0x01);
        EXPECT_FALSE(ReadModuleBundle(changed)) << at;
    }
    std::string header = file;
    header[4] = 2;  // another version
    EXPECT_FALSE(ReadModuleBundle(header));
}

TEST(ModuleBundle, ADamagedPayloadIsLeftOutAlone) {
    std::string file = BuildModuleBundle(Sample());
    file[kModuleHeaderBytes + 3] = 'x';  // inside module a
    const auto read = ReadModuleBundle(file);
    ASSERT_TRUE(read);
    const Modules all = Sample();
    EXPECT_EQ(*read, Modules(all.begin() + 1, all.end()));
}

TEST(ModuleBundle, AKeyTwiceOrAMalformedKeyIsRefused) {
    EXPECT_FALSE(ReadModuleBundle(BuildModuleBundle({{kKeyA, "x"}, {kKeyA, "y"}})));
    EXPECT_FALSE(ReadModuleBundle(BuildModuleBundle({{std::string(32, 'A'), "x"}})));
    EXPECT_FALSE(ReadModuleBundle(BuildModuleBundle({{std::string(31, 'a') + "/", "x"}})));
}

TEST(ModuleBundle, APayloadOutsideThePayloadAreaIsRefused) {
    // An index that names bytes of the index itself.
    std::string file = ModuleBundleHeader() + "abcd";
    const uint64_t index_at = file.size();
    file += ModuleBundleTail({{kKeyA, index_at, 4, EntryHash(kKeyA, "abcd")}}, index_at);
    EXPECT_FALSE(ReadModuleBundle(file));
    std::string inside = ModuleBundleHeader() + "abcd";
    inside +=
        ModuleBundleTail({{kKeyA, kModuleHeaderBytes, 4, EntryHash(kKeyA, "abcd")}}, inside.size());
    EXPECT_EQ(ReadModuleBundle(inside), (Modules{{kKeyA, "abcd"}}));
}

}  // namespace
}  // namespace kiln::driver
