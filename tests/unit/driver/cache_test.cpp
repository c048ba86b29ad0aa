// The compile cache distrusts its entries: each kind of damage that once gave exit 3, a wrong pack,
// a crash or a hang is now a miss, the compile gives the same pack as a clean one, and the entry is
// repaired. The modules of a shader are one file (driver/module_store.h): damage to one module is
// a miss for it, damage to the file a miss for all. Temporary files left by killed compiles go
// once they are a day old. (The whole-pack entries are removed before each compile here, so that
// the modules are read.)
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "driver/cache.h"
#include "driver/module_bundle.h"
#include "driver/module_store.h"
#include "kiln/base/bytes.h"
#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {
namespace fs = std::filesystem;

using Modules = std::vector<std::pair<std::string, std::string>>;

struct CachedCompile {
    ScratchDir dir;
    CompileOptions options;
    std::vector<uint8_t> clean_pack;
    Modules modules;  // (key, payload) of the file a compile stores

    CachedCompile() {
        options.cache_dir = dir.path() + "/cache";
        CompileRun cold = Compile({Shader()}, options);
        EXPECT_TRUE(cold.out.ok) << Brief(cold.diags);
        clean_pack = cold.out.pack;
        for (const auto& e : fs::recursive_directory_iterator(options.cache_dir))
            EXPECT_NE(e.path().extension(), ".spv") << "a module in a file of its own";
        modules = Read();
        std::sort(modules.begin(), modules.end());
        EXPECT_EQ(modules.size(), 3u);
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
    std::string File() const {
        return driver::ModuleStore(driver::Cache(options.cache_dir)).PathFor(Shader());
    }
    Modules Read() const {
        std::optional<Modules> read = driver::ReadModuleBundle(ReadFile(File()));
        EXPECT_TRUE(read.has_value());
        Modules out = read.value_or(Modules{});
        std::sort(out.begin(), out.end());
        return out;
    }

    // Compiles again: the pack must be the clean one, the `damaged` modules compiled again (and
    // the others taken from the cache), and the file whole afterwards.
    void ExpectRepaired(size_t damaged) {
        CompileRun again = Compile({Shader()}, options);
        ASSERT_TRUE(again.out.ok) << Brief(again.diags);
        EXPECT_EQ(again.out.pack, clean_pack);
        EXPECT_EQ(again.out.stats.glslang_compiles, damaged);
        EXPECT_EQ(again.out.stats.cache_hits, modules.size() - damaged);
        struct stat st {};
        ASSERT_EQ(lstat(File().c_str(), &st), 0);
        EXPECT_TRUE(S_ISREG(st.st_mode));
        EXPECT_EQ(Read(), modules);
        RemovePackEntries();
        CompileRun warm = Compile({Shader()}, options);
        EXPECT_EQ(warm.out.stats.cache_hits, modules.size());
        RemovePackEntries();
    }
};

std::string SpirvBytes(const std::vector<uint32_t>& words) {
    std::string out;
    for (uint32_t w : words)
        base::AppendLe32(out, w);
    return out;
}

TEST(CompileCache, AModuleWithACorrectHashButNotSpirvIsAMiss) {
    CachedCompile c;
    // Garbage behind a SPIR-V header, with its key and a hash that holds.
    Modules forged = c.modules;
    forged[0].second = SpirvBytes({0x07230203, 0x00010300, 0, 100, 0, 0xdeadbeef, 7, 7});
    WriteFile(c.File(), driver::BuildModuleBundle(forged));
    ASSERT_TRUE(driver::ModuleStore(driver::Cache(c.options.cache_dir))
                    .Load(forged[0].first, CachedCompile::Shader()));
    c.ExpectRepaired(1);
}

TEST(CompileCache, AValidModuleUnderAnotherKeyIsAMiss) {
    CachedCompile c;
    // Module 1's payload and hash under module 0's key.
    std::string file = driver::ModuleBundleHeader();
    std::vector<driver::ModuleEntry> entries;
    for (size_t i = 0; i < c.modules.size(); ++i) {
        const auto& [key, payload] = c.modules[i == 0 ? 1 : i];
        entries.push_back({c.modules[i].first, file.size(), static_cast<uint32_t>(payload.size()),
                           driver::EntryHash(key, payload)});
        file += payload;
    }
    file += driver::ModuleBundleTail(entries, file.size());
    WriteFile(c.File(), file);
    driver::ModuleStore store{driver::Cache(c.options.cache_dir)};
    EXPECT_FALSE(store.Load(c.modules[0].first, CachedCompile::Shader()));
    EXPECT_TRUE(store.Load(c.modules[1].first, CachedCompile::Shader()));
    c.ExpectRepaired(1);
}

TEST(CompileCache, AModuleSharedByShadersIsFoundInTheFileOfAnyOfThem) {
    // A program two shaders share is stored in the file of whichever compiled it first, which
    // depends on timing; the next compile finds it from either shader, whichever files it read.
    ScratchDir dir;
    const std::vector<uint32_t> words = {0x07230203, 0x00010300, 0, 1, 0};
    const std::string a = dir.path() + "/A.shader", b = dir.path() + "/B.shader";
    const std::string key = driver::HashKey({"a program A and B share"});
    {
        driver::ModuleStore first(driver::Cache(dir.path() + "/cache"), {a, b});
        first.Store(key, words, a);
        first.Flush();
    }
    driver::ModuleStore next(driver::Cache(dir.path() + "/cache"), {a, b});
    const std::optional<std::vector<uint32_t>> found = next.Load(key, b);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(*found, words);
    // A store that knows only the asking shader's file misses (what timing decided before).
    driver::ModuleStore alone(driver::Cache(dir.path() + "/cache"));
    EXPECT_FALSE(alone.Load(key, b).has_value());
}

TEST(CompileCache, AFileThatIsADirectoryIsAMissAndReplaced) {
    CachedCompile c;
    fs::remove(c.File());
    fs::create_directories(c.File() + "/inside");
    c.ExpectRepaired(3);
}

TEST(CompileCache, AFileThatIsALinkToADeviceIsAMissAndReplaced) {
    CachedCompile c;
    fs::remove(c.File());
    fs::create_symlink("/dev/zero", c.File());
    c.ExpectRepaired(3);
}

TEST(CompileCache, AFileThatIsAFifoIsAMissNotAHang) {
    CachedCompile c;
    fs::remove(c.File());
    ASSERT_EQ(mkfifo(c.File().c_str(), 0600), 0);
    c.ExpectRepaired(3);
}

TEST(CompileCache, TruncatedAndOversizedFilesAreMisses) {
    CachedCompile c;
    fs::resize_file(c.File(), 30);
    c.ExpectRepaired(3);
    fs::resize_file(c.File(), driver::Cache::kMaxPackEntryBytes + 1);
    c.ExpectRepaired(3);
}

TEST(CompileCache, AModuleOfItsOwnFromAnOlderKilnIsStillRead) {
    CachedCompile c;
    const driver::Cache cache(c.options.cache_dir);
    for (const auto& [key, payload] : c.modules) {
        std::vector<uint32_t> words(payload.size() / 4);
        for (size_t i = 0; i < words.size(); ++i)
            words[i] = base::LoadLe32(payload, i * 4);
        ASSERT_TRUE(cache.Store(key, words));
    }
    fs::remove(c.File());
    CompileRun again = Compile({CachedCompile::Shader()}, c.options);
    ASSERT_TRUE(again.out.ok) << Brief(again.diags);
    EXPECT_EQ(again.out.pack, c.clean_pack);
    EXPECT_EQ(again.out.stats.glslang_compiles, 0u);
    EXPECT_EQ(again.out.stats.cache_hits, 3u);
}

TEST(CompileCache, TemporaryFilesADayOldAreRemoved) {
    CachedCompile c;
    const std::string old_temp = c.File() + ".tmp.123.4";
    const std::string new_temp = c.File() + ".tmp.123.5";
    WriteFile(old_temp, "partial");
    WriteFile(new_temp, "partial");
    fs::last_write_time(old_temp, fs::file_time_type::clock::now() - std::chrono::hours(25));
    const driver::Cache cache(c.options.cache_dir);
    EXPECT_EQ(cache.RemoveStaleTemporaries(24 * 60 * 60), 1u);
    EXPECT_FALSE(fs::exists(old_temp));
    EXPECT_TRUE(fs::exists(new_temp));
}

TEST(CompileCache, TheKeyOfCodeIsTheKeyOfCodeOf) {
    const std::vector<std::string> parts = {"kiln 1", "O", "vert", "vert"};
    const std::string reduced =
        "#line 1 \"a.shader\"\n  float4 f() {\r\n\n\t\treturn 0; \t\n}\n   #line 9\nx";
    EXPECT_EQ(driver::CodeOf(reduced, false), "float4 f() {\nreturn 0;\n}\nx\n");
    for (bool debug : {false, true}) {
        std::vector<std::string> all = parts;
        all.push_back(driver::CodeOf(reduced, debug));
        EXPECT_EQ(driver::HashKeyOfCode(parts, reduced, debug), driver::HashKey(all)) << debug;
    }
    // A line moved is the same code; a changed line is not.
    EXPECT_EQ(driver::HashKeyOfCode(parts, "\n\n" + reduced, false),
              driver::HashKeyOfCode(parts, reduced, false));
    EXPECT_NE(driver::HashKeyOfCode(parts, reduced + "y", false),
              driver::HashKeyOfCode(parts, reduced, false));
}

}  // namespace
}  // namespace kiln::test
