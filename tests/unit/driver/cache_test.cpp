// The compile cache distrusts its entries: each kind of damage that once gave exit 3, a wrong pack,
// a crash or a hang is now a miss, the compile gives the same pack as a clean one, and the entry is
// repaired. Temporary files left by killed compiles go once they are a day old. (The whole-pack
// entries are removed before each compile here, so that the module entries are read.)
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "driver/cache.h"
#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {
namespace fs = std::filesystem;

struct CachedCompile {
    ScratchDir dir;
    CompileOptions options;
    std::vector<uint8_t> clean_pack;
    std::vector<std::string> keys;  // of the entries a compile stores

    CachedCompile() {
        options.cache_dir = dir.path() + "/cache";
        CompileRun cold = Compile({Shader()}, options);
        EXPECT_TRUE(cold.out.ok) << Brief(cold.diags);
        clean_pack = cold.out.pack;
        for (const auto& e : fs::recursive_directory_iterator(options.cache_dir)) {
            if (e.is_regular_file() && e.path().extension() == ".spv")
                keys.push_back(e.path().stem().string());
        }
        std::sort(keys.begin(), keys.end());
        EXPECT_EQ(keys.size(), 3u);
        RemovePackEntries();
    }
    void RemovePackEntries() const {
        std::vector<fs::path> packs;
        for (const auto& e : fs::recursive_directory_iterator(options.cache_dir)) {
            if (e.path().extension() == ".kpack")
                packs.push_back(e.path());
        }
        EXPECT_EQ(packs.size(), 1u);
        for (const fs::path& p : packs)
            fs::remove(p);
    }
    static std::string Shader() { return DataPath("data/compile/multi_light.shader"); }
    std::string Entry(size_t i) const { return driver::Cache(options.cache_dir).PathFor(keys[i]); }

    // Compiles again: the pack must be the clean one, the damaged entry compiled again (and the
    // others taken from the cache), and the entry a valid one afterwards.
    void ExpectRepaired(size_t damaged) {
        CompileRun again = Compile({Shader()}, options);
        ASSERT_TRUE(again.out.ok) << Brief(again.diags);
        EXPECT_EQ(again.out.pack, clean_pack);
        EXPECT_EQ(again.out.stats.glslang_compiles, 1u);
        EXPECT_EQ(again.out.stats.cache_hits, keys.size() - 1);
        struct stat st {};
        ASSERT_EQ(lstat(Entry(damaged).c_str(), &st), 0);
        EXPECT_TRUE(S_ISREG(st.st_mode));
        RemovePackEntries();
        CompileRun warm = Compile({Shader()}, options);
        EXPECT_EQ(warm.out.stats.cache_hits, keys.size());
        RemovePackEntries();
    }
};

TEST(CompileCache, AnEntryWithACorrectHashButNotSpirvIsAMiss) {
    CachedCompile c;
    // Garbage behind a SPIR-V header, stored through the cache itself so key and hash are right.
    const driver::Cache cache(c.options.cache_dir);
    ASSERT_TRUE(cache.Store(c.keys[0], {0x07230203, 0x00010300, 0, 100, 0, 0xdeadbeef, 7, 7}));
    ASSERT_TRUE(cache.Load(c.keys[0]));
    c.ExpectRepaired(0);
}

TEST(CompileCache, AValidEntrySwappedForAnotherIsAMiss) {
    CachedCompile c;
    fs::copy_file(c.Entry(1), c.Entry(0), fs::copy_options::overwrite_existing);
    EXPECT_FALSE(driver::Cache(c.options.cache_dir).Load(c.keys[0]));
    c.ExpectRepaired(0);
}

TEST(CompileCache, AnEntryThatIsADirectoryIsAMissAndReplaced) {
    CachedCompile c;
    fs::remove(c.Entry(0));
    fs::create_directories(c.Entry(0) + "/inside");
    c.ExpectRepaired(0);
}

TEST(CompileCache, AnEntryThatIsALinkToADeviceIsAMissAndReplaced) {
    CachedCompile c;
    fs::remove(c.Entry(0));
    fs::create_symlink("/dev/zero", c.Entry(0));
    c.ExpectRepaired(0);
}

TEST(CompileCache, AnEntryThatIsAFifoIsAMissNotAHang) {
    CachedCompile c;
    fs::remove(c.Entry(0));
    ASSERT_EQ(mkfifo(c.Entry(0).c_str(), 0600), 0);
    c.ExpectRepaired(0);
}

TEST(CompileCache, TruncatedAndOversizedEntriesAreMisses) {
    CachedCompile c;
    fs::resize_file(c.Entry(0), 30);
    c.ExpectRepaired(0);
    fs::resize_file(c.Entry(0), driver::Cache::kMaxEntryBytes + 1);
    c.ExpectRepaired(0);
}

TEST(CompileCache, TemporaryFilesADayOldAreRemoved) {
    CachedCompile c;
    const std::string old_temp = c.Entry(0) + ".tmp.123.4";
    const std::string new_temp = c.Entry(0) + ".tmp.123.5";
    WriteFile(old_temp, "partial");
    WriteFile(new_temp, "partial");
    fs::last_write_time(old_temp, fs::file_time_type::clock::now() - std::chrono::hours(25));
    const driver::Cache cache(c.options.cache_dir);
    EXPECT_EQ(cache.RemoveStaleTemporaries(24 * 60 * 60), 1u);
    EXPECT_FALSE(fs::exists(old_temp));
    EXPECT_TRUE(fs::exists(new_temp));
}

}  // namespace
}  // namespace kiln::test
