// The cache's direct mode and whole-pack entries (driver/direct_cache.h, pack_cache.cpp): a
// no-change rebuild preprocesses and compiles nothing and gives the same pack; a change that moves
// lines but not code compiles nothing; a code change compiles only the programs it changes; a
// header that now shadows an include, a damaged manifest and a manifest whose module is gone are
// misses that give the pack a compile without the cache gives; the same sources in another folder
// hit; a warning is shown every time (one of loading or expansion by steps that run every time,
// any other kept with the whole pack and reported again).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {
namespace fs = std::filesystem;

// Two variants; the vertex stage reads Move() and the fragment stage Shade() from inc.cginc.
std::string Shader(const std::string& extra = "") {
    return "Shader \"Test/Direct\" {\n"
           "    Properties { _Tint (\"Tint\", Color) = (1, 1, 1, 1) }\n"
           "    SubShader { Pass {\n"
           "            CGPROGRAM\n"
           "            #pragma vertex vert\n"
           "            #pragma fragment frag\n"
           "            #pragma multi_compile _ RED\n"
           "            #include \"inc.cginc\"\n"
           "            float4 _Tint;\n" +
           extra +
           "            float4 vert(float4 p : POSITION) : SV_POSITION { return Move(p); }\n"
           "            float4 frag() : SV_Target { return Shade(_Tint); }\n"
           "            ENDCG\n"
           "    } }\n"
           "}\n";
}

const char* kInclude =
    "float4 Move(float4 p) { return p * 0.5; }\n"
    "float4 Shade(float4 c) {\n"
    "#ifdef RED\n"
    "    return float4(1, 0, 0, 1) * c;\n"
    "#else\n"
    "    return c;\n"
    "#endif\n"
    "}\n";

struct Project {
    ScratchDir dir;
    std::string shader;
    CompileOptions options;

    Project() {
        shader = dir.Write("proj/direct.shader", Shader());
        dir.Write("proj/inc.cginc", kInclude);
        options.cache_dir = dir.path() + "/cache";
    }
    CompileRun Build() const { return Compile({shader}, options); }
    // The same compile without any cache: what every cached compile must give.
    std::vector<uint8_t> Reference() const {
        CompileOptions none = options;
        none.cache_dir.clear();
        CompileRun r = Compile({shader}, none);
        EXPECT_TRUE(r.out.ok) << Brief(r.diags);
        return r.out.pack;
    }
    void RemoveEntries(const std::string& ext) const {
        std::vector<fs::path> found;
        for (const auto& e : fs::recursive_directory_iterator(options.cache_dir)) {
            if (e.path().extension() == ext)
                found.push_back(e.path());
        }
        EXPECT_FALSE(found.empty()) << ext;
        for (const fs::path& p : found)
            fs::remove(p);
    }
};

TEST(DirectCache, ANoChangeRebuildPreprocessesAndCompilesNothing) {
    Project p;
    const CompileRun cold = p.Build();
    ASSERT_TRUE(cold.out.ok) << Brief(cold.diags);
    EXPECT_EQ(cold.out.stats.direct_hits, 0u);
    EXPECT_EQ(cold.out.stats.glslang_compiles, 3u);  // one vertex, two fragment programs

    const CompileRun warm = p.Build();
    ASSERT_TRUE(warm.out.ok) << Brief(warm.diags);
    EXPECT_EQ(warm.out.pack, cold.out.pack);
    EXPECT_EQ(warm.out.stats.direct_hits, 4u);
    EXPECT_EQ(warm.out.stats.glslang_compiles, 0u);
    EXPECT_EQ(warm.out.stats.cache_hits, 3u);
    EXPECT_EQ(warm.out.stats.unique_programs, 3u);
    EXPECT_EQ(warm.out.stats.modules, cold.out.stats.modules);
    EXPECT_EQ(warm.out.stats.ms.finish, 0.0);                 // the pack was taken whole
    EXPECT_EQ(warm.out.files.size(), cold.out.files.size());  // the depfile's files

    // Without the whole pack: the modules come from the cache, still not preprocessed.
    p.RemoveEntries(".kpack");
    const CompileRun modules = p.Build();
    ASSERT_TRUE(modules.out.ok) << Brief(modules.diags);
    EXPECT_EQ(modules.out.pack, cold.out.pack);
    EXPECT_EQ(modules.out.stats.direct_hits, 4u);
    EXPECT_EQ(modules.out.stats.glslang_compiles, 0u);
    EXPECT_GT(modules.out.stats.ms.finish, 0.0);
}

// A cold compile writes one manifest for the shader file, not one per stage program, and a
// compile with other options adds its programs to it without dropping the first compile's.
TEST(DirectCache, OneManifestPerShaderKeepsEveryCompilesPrograms) {
    Project p;
    auto manifests = [&] {
        size_t n = 0;
        for (const auto& e : fs::recursive_directory_iterator(p.options.cache_dir))
            n += e.path().extension() == ".man";
        return n;
    };
    ASSERT_TRUE(p.Build().out.ok);
    EXPECT_EQ(manifests(), 1u);

    CompileOptions none = p.options;
    none.opt_level = OptimizationLevel::kNone;
    const CompileRun other = Compile({p.shader}, none);
    ASSERT_TRUE(other.out.ok) << Brief(other.diags);
    EXPECT_EQ(other.out.stats.direct_hits, 0u);
    EXPECT_EQ(manifests(), 1u);

    p.RemoveEntries(".kpack");  // so that every program is looked up
    const CompileRun again = p.Build();
    ASSERT_TRUE(again.out.ok) << Brief(again.diags);
    EXPECT_EQ(again.out.stats.direct_hits, 4u);
    EXPECT_EQ(again.out.stats.glslang_compiles, 0u);
    const CompileRun other_again = Compile({p.shader}, none);
    EXPECT_EQ(other_again.out.stats.direct_hits, 4u);
    EXPECT_EQ(other_again.out.pack, other.out.pack);
}

// A shader of the same file name in another folder shares the manifest; the earlier entries a
// compile checks only to keep them (here one that includes inc.cginc) stay out of its depfile.
TEST(DirectCache, EntriesKeptForOtherCompilesStayOutOfTheDepfile) {
    Project p;
    ASSERT_TRUE(p.Build().out.ok);
    p.dir.Write("other/inc.cginc", kInclude);  // as the first folder's, not included here
    p.dir.Write("other/own.cginc", kInclude);
    const std::string other =
        p.dir.Write("other/direct.shader", Replace(Shader(), "inc.cginc", "own.cginc"));
    const CompileRun run = Compile({other}, p.options);
    ASSERT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(run.out.stats.direct_hits, 0u);
    std::vector<std::string> names;
    for (const auto& f : run.out.files)
        names.push_back(fs::path(f->path()).filename().string());
    EXPECT_EQ(std::count(names.begin(), names.end(), "own.cginc"), 1);
    EXPECT_EQ(std::count(names.begin(), names.end(), "inc.cginc"), 0);

    // Both folders' programs are in the one manifest.
    p.RemoveEntries(".kpack");
    EXPECT_EQ(p.Build().out.stats.direct_hits, 4u);
    EXPECT_EQ(Compile({other}, p.options).out.stats.direct_hits, 4u);
}

TEST(DirectCache, LinesMovedInAnIncludeCompileNothing) {
    Project p;
    ASSERT_TRUE(p.Build().out.ok);
    p.dir.Write("proj/inc.cginc", std::string("// a comment\n\n\n") + kInclude);
    const CompileRun again = p.Build();
    ASSERT_TRUE(again.out.ok) << Brief(again.diags);
    EXPECT_EQ(again.out.stats.direct_hits, 0u);  // the include's hash changed
    EXPECT_EQ(again.out.stats.glslang_compiles, 0u);
    EXPECT_EQ(again.out.pack, p.Reference());
}

TEST(DirectCache, ACodeChangeCompilesOnlyTheProgramsItChanges) {
    Project p;
    const CompileRun cold = p.Build();
    ASSERT_TRUE(cold.out.ok);
    p.dir.Write("proj/inc.cginc", Replace(kInclude, "return float4(1, 0, 0, 1) * c;",
                                          "return float4(0.5, 0, 0, 1) * c;"));
    const CompileRun again = p.Build();
    ASSERT_TRUE(again.out.ok) << Brief(again.diags);
    EXPECT_EQ(again.out.stats.glslang_compiles, 1u);  // RED's fragment program
    EXPECT_EQ(again.out.stats.cache_hits, 2u);
    EXPECT_NE(again.out.pack, cold.out.pack);
    EXPECT_EQ(again.out.pack, p.Reference());
}

TEST(DirectCache, AHeaderThatNowShadowsAnIncludeIsAMiss) {
    Project p;
    // inc.cginc found through -I at first; then one appears beside the shader, searched first.
    fs::remove(p.dir.path() + "/proj/inc.cginc");
    p.dir.Write("lib/inc.cginc", kInclude);
    p.options.include_dirs = {p.dir.path() + "/lib"};
    const CompileRun cold = p.Build();
    ASSERT_TRUE(cold.out.ok) << Brief(cold.diags);
    p.dir.Write("proj/inc.cginc", Replace(kInclude, "p * 0.5", "p * 0.25"));
    const CompileRun again = p.Build();
    ASSERT_TRUE(again.out.ok) << Brief(again.diags);
    EXPECT_EQ(again.out.stats.direct_hits, 0u);
    EXPECT_EQ(again.out.stats.glslang_compiles, 1u);  // the vertex program
    EXPECT_NE(again.out.pack, cold.out.pack);
    EXPECT_EQ(again.out.pack, p.Reference());
}

TEST(DirectCache, TheSameSourcesInAnotherFolderHit) {
    Project p;
    const CompileRun cold = p.Build();
    ASSERT_TRUE(cold.out.ok);
    fs::create_directories(p.dir.path() + "/elsewhere");
    fs::copy(p.dir.path() + "/proj", p.dir.path() + "/elsewhere/proj", fs::copy_options::recursive);
    const CompileRun moved = Compile({p.dir.path() + "/elsewhere/proj/direct.shader"}, p.options);
    ASSERT_TRUE(moved.out.ok) << Brief(moved.diags);
    EXPECT_EQ(moved.out.stats.direct_hits, 4u);
    EXPECT_EQ(moved.out.stats.glslang_compiles, 0u);
    EXPECT_EQ(moved.out.pack, cold.out.pack);
}

TEST(DirectCache, DamagedManifestsAndMissingModulesAreMisses) {
    Project p;
    const std::vector<uint8_t> reference = p.Reference();
    ASSERT_TRUE(p.Build().out.ok);
    // Every manifest replaced by garbage of a plausible size.
    for (const auto& e : fs::recursive_directory_iterator(p.options.cache_dir)) {
        if (e.path().extension() == ".man")
            WriteFile(e.path().string(), std::string(200, 'x'));
    }
    const CompileRun damaged = p.Build();
    ASSERT_TRUE(damaged.out.ok) << Brief(damaged.diags);
    EXPECT_EQ(damaged.out.stats.direct_hits, 0u);
    EXPECT_EQ(damaged.out.pack, reference);

    // Manifests intact (rewritten above), but the modules and packs they lead to are gone.
    p.RemoveEntries(".kmod");
    p.RemoveEntries(".kpack");
    const CompileRun gone = p.Build();
    ASSERT_TRUE(gone.out.ok) << Brief(gone.diags);
    EXPECT_EQ(gone.out.stats.direct_hits, 0u);
    EXPECT_EQ(gone.out.stats.glslang_compiles, 3u);
    EXPECT_EQ(gone.out.pack, reference);
}

// A warning of a step a hit skips (here reflection's) is kept with the pack and reported again
// when the pack is taken whole; from another folder the pack is not taken (the warning would name
// the old path), and the warning names the new one.
TEST(DirectCache, ACompileWithAWarningShowsItEveryTime) {
    Project p;
    p.shader = p.dir.Write("proj/direct.shader", Replace(Shader("            float4 _Extra;\n"),
                                                         "Shade(_Tint)", "Shade(_Tint + _Extra)"));
    for (int run = 0; run < 2; ++run) {
        const CompileRun r = p.Build();
        ASSERT_TRUE(r.out.ok) << Brief(r.diags);
        EXPECT_NE(Brief(r.diags).find("'_Extra' is not in Properties"), std::string::npos)
            << "run " << run << ": " << Brief(r.diags);
        EXPECT_EQ(r.diags.all().size(), 1u) << Brief(r.diags);
        if (run == 1) {
            EXPECT_EQ(r.out.stats.ms.finish, 0.0);  // the pack was taken whole
        }
    }
    fs::create_directories(p.dir.path() + "/elsewhere");
    fs::copy(p.dir.path() + "/proj", p.dir.path() + "/elsewhere/proj", fs::copy_options::recursive);
    const std::string moved_path = p.dir.path() + "/elsewhere/proj/direct.shader";
    const CompileRun moved = Compile({moved_path}, p.options);
    ASSERT_TRUE(moved.out.ok) << Brief(moved.diags);
    EXPECT_EQ(moved.out.stats.direct_hits, 4u);
    EXPECT_GT(moved.out.stats.ms.finish, 0.0);  // not taken whole
    ASSERT_EQ(moved.diags.all().size(), 1u) << Brief(moved.diags);
    EXPECT_EQ(moved.diags.all()[0].file, moved_path);
}

// A warning of loading or expansion (here skip_variants naming no keyword) comes from steps that
// run every time: the pack is still taken whole, and the warning still shown.
TEST(DirectCache, AWarningOfExpansionStillTakesThePackWholeAndIsShown) {
    Project p;
    p.shader = p.dir.Write("proj/direct.shader",
                           Shader("            #pragma skip_variants NO_SUCH_KEYWORD\n"));
    for (int run = 0; run < 2; ++run) {
        const CompileRun r = p.Build();
        ASSERT_TRUE(r.out.ok) << Brief(r.diags);
        EXPECT_NE(Brief(r.diags).find("NO_SUCH_KEYWORD"), std::string::npos)
            << "run " << run << ": " << Brief(r.diags);
        if (run == 1) {
            EXPECT_EQ(r.out.stats.direct_hits, 4u);
            EXPECT_EQ(r.out.stats.ms.finish, 0.0);  // the pack was taken whole
        }
    }
}

}  // namespace
}  // namespace kiln::test
