// kiln lint as CI runs it: each K7xxx finding at its pragma, property or pass, -Werror, --json,
// variant budgets; and the keyword aliases the findings describe, in the pack.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

std::string Wasteful() {
    return DataPath("lint/Wasteful.shader");
}

// "file:line:col: warning: ... [Kcode]" for every diagnostic of a --json report.
std::vector<std::string> Findings(const nlohmann::json& report) {
    std::vector<std::string> out;
    for (const auto& d : report["diagnostics"]) {
        out.push_back(std::to_string(d["range"]["begin"]["line"].get<int>()) + ":" +
                      std::to_string(d["range"]["begin"]["column"].get<int>()) + " " +
                      d["code"].get<std::string>());
    }
    return out;
}

TEST(Lint, EachFindingIsAtItsPragmaPropertyOrPass) {
    const RunResult r = RunKiln("lint --no-cache --json " + Wasteful());
    ASSERT_EQ(r.exit_code, 0) << r.err;  // warnings only
    const nlohmann::json report = nlohmann::json::parse(r.out);
    const std::vector<std::string> found = Findings(report);
    for (const char* expected : {
             "50:13 K7001",  // multi_compile _ UNUSED_KW: no code reads it
             "51:13 K7003",  // FOG_A and FOG_B: identical SPIR-V
             "52:13 K7002",  // BEND changes the vertex stage only
             "54:13 K7005",  // _SHINY: only a [Toggle] sets it, yet multi_compile
             "55:13 K7006",  // shader_feature GLOBALISH: looks set from code
             "66:13 K7004",  // shader_feature POINT: the engine sets it per draw
             "67:13 K7007",  // FOG_A declared with other companions in pass BASE
             "7:30 K7009",   // [Toggle(MISSING_KW)]: no pass declares it
             "8:9 K7010",    // _GLOW_ON declared, but _Glow has no [Toggle]
             "42:9 K7011",   // transparent queue, ZWrite On
             "59:9 K7011",   // ForwardAdd without Blend
             "71:9 K7011",   // Deferred pass that blends
         }) {
        EXPECT_NE(std::find(found.begin(), found.end(), expected), found.end())
            << expected << " not among:\n"
            << report["diagnostics"].dump(1);
    }
    // A keyword-switch property is not reported as having no shader variable (the old false
    // K5005); a property nothing reads and nothing switches is.
    EXPECT_EQ(std::count(found.begin(), found.end(), "9:26 K5005"), 0);
    EXPECT_EQ(std::count(found.begin(), found.end(), "8:9 K5005"), 1);
    EXPECT_EQ(report["errors"], 0);

    // The counts: per pass, the product that made them, the aliases, the budget (the pass tag).
    const auto& passes = report["shaders"][0]["passes"];
    EXPECT_EQ(report["shaders"][0]["variants"], 101);
    EXPECT_EQ(passes[0]["formula"], "2 x 3 x 2 x 2 x 2 x 2");
    EXPECT_EQ(passes[0]["variants"], 96);
    EXPECT_EQ(passes[0]["aliased"], 64);  // UNUSED_KW's half, then FOG_B's third of the rest
    EXPECT_EQ(passes[1]["budget"], 8);
}

TEST(Lint, TextShowsTheCountsAndWerrorFails) {
    const RunResult r = RunKiln("lint --no-cache " + Wasteful());
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("pass \"BASE\" (LightMode ForwardBase): 2 x 3 x 2 x 2 x 2 x 2 = 96 "
                         "variants (64 stored as aliases), budget 4096"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.err.find(Wasteful() + ":50:13: warning: keyword 'UNUSED_KW' of pass \"BASE\" "
                                      "changes no code"),
              std::string::npos)
        << r.err;
    const RunResult strict = RunKiln("lint --no-cache -Werror " + Wasteful());
    EXPECT_EQ(strict.exit_code, 1);
    EXPECT_NE(strict.err.find(":50:13: error: keyword 'UNUSED_KW'"), std::string::npos);
}

// The -W options (docs/diagnostics.md, "Warning options"): one lint check silenced by its code,
// the rest kept; one compile warning made an error, which fails the compile and writes no pack,
// also when the pack comes whole from the cache; a misspelled option named with the closest.
TEST(Lint, WnoSilencesOneCheckAndTheOthersStay) {
    const RunResult r = RunKiln("lint --no-cache --json -Wno-K7001 " + Wasteful());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> found = Findings(nlohmann::json::parse(r.out));
    EXPECT_EQ(std::count(found.begin(), found.end(), "50:13 K7001"), 0);
    EXPECT_EQ(std::count(found.begin(), found.end(), "51:13 K7003"), 1);
    EXPECT_EQ(std::count(found.begin(), found.end(), "42:9 K7011"), 1);
    // A group, and a later option naming one of its codes again.
    const RunResult group = RunKiln("lint --no-cache --json -Wno-lint -WK7011 " + Wasteful());
    ASSERT_EQ(group.exit_code, 0) << group.err;
    for (const std::string& f : Findings(nlohmann::json::parse(group.out)))
        EXPECT_TRUE(f.find("K7") == std::string::npos || f.find("K7011") != std::string::npos) << f;
    // -Werror with one code kept a warning: the lint fails on the others.
    const RunResult strict = RunKiln("lint --no-cache -Werror -Wno-error=K7001 " + Wasteful());
    EXPECT_EQ(strict.exit_code, 1);
    EXPECT_NE(strict.err.find(":50:13: warning: keyword 'UNUSED_KW'"), std::string::npos)
        << strict.err;
    EXPECT_NE(strict.err.find(":51:13: error: keywords 'FOG_A' and 'FOG_B'"), std::string::npos)
        << strict.err;
}

TEST(Lint, WerrorOfOneCodeFailsTheCompileAndWritesNoPack) {
    ScratchDir dir;
    const std::string shader = dir.Write("Global.shader", R"(Shader "T/Global" {
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        float4 _Tint;
        float4 vert(float4 p : POSITION) : SV_POSITION { return p; }
        float4 frag() : SV_Target { return _Tint; }
        ENDCG
    } }
}
)");
    const std::string pack = dir.path() + "/g.kpack", cache = dir.path() + "/cache";
    const RunResult plain = RunKiln("compile " + shader + " --cache-dir " + cache + " -o " + pack);
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_NE(plain.err.find("warning: shader global '_Tint' is not in Properties"),
              std::string::npos)
        << plain.err;
    std::filesystem::remove(pack);
    // The same compile, its pack now in the cache: the warning is an error and no pack is written.
    const RunResult strict =
        RunKiln("compile -Werror=K5006 " + shader + " --cache-dir " + cache + " -o " + pack);
    EXPECT_EQ(strict.exit_code, 1);
    EXPECT_NE(strict.err.find("error: shader global '_Tint' is not in Properties"),
              std::string::npos)
        << strict.err;
    EXPECT_FALSE(std::filesystem::exists(pack));
    const RunResult cold = RunKiln("compile -Werror=K5006 --no-cache " + shader + " -o " + pack);
    EXPECT_EQ(cold.exit_code, 1);
    EXPECT_FALSE(std::filesystem::exists(pack));
    // Silenced: no warning at all; the cache still holds it for a compile without the option.
    const RunResult quiet =
        RunKiln("compile -Wno-interface " + shader + " --cache-dir " + cache + " -o " + pack);
    EXPECT_EQ(quiet.exit_code, 0);
    EXPECT_EQ(quiet.err.find("K5006"), std::string::npos) << quiet.err;
    const RunResult again = RunKiln("compile " + shader + " --cache-dir " + cache + " -o " + pack);
    EXPECT_NE(again.err.find("[K5006]"), std::string::npos) << again.err;
}

TEST(Lint, AMisspelledWarningOptionIsAUsageError) {
    const RunResult r = RunKiln("lint -Wno-K7100 " + Wasteful());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown warning option '-Wno-K7100': expected a code (K7001) or a "
                         "group (all, lint, interface, ...); did you mean 'K7010'? [K0003]"),
              std::string::npos)
        << r.err;
    const RunResult group = RunKiln("compile -Werror=interfase " + Wasteful() + " -o -");
    EXPECT_EQ(group.exit_code, 2);
    EXPECT_NE(group.err.find("did you mean 'interface'?"), std::string::npos) << group.err;
}

TEST(Lint, ListChecksNamesEveryCheckWithItsCodes) {
    const RunResult r = RunKiln("lint --list-checks --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json checks = nlohmann::json::parse(r.out);
    std::set<std::string> codes;
    for (const auto& c : checks) {
        for (const auto& code : c["codes"])
            EXPECT_TRUE(codes.insert(code.get<std::string>()).second) << code << " twice";
    }
    for (const char* code : {"K3001", "K5004", "K5006", "K7001", "K7011"})
        EXPECT_TRUE(codes.count(code)) << code;
    EXPECT_EQ(checks.back()["name"], "pass-state");
    EXPECT_EQ(checks.back()["when"], "lint");
    EXPECT_EQ(RunKiln("lint").exit_code, 2);  // no files, no --list-checks
}

TEST(Lint, AVariantBudgetFailsTheLint) {
    const RunResult r = RunKiln("lint --no-cache --max-variants 50 " + Wasteful());
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("2 x 3 x 2 x 2 x 2 x 2 = 96 variants in pass \"BASE\", over the limit of "
                         "50 (--max-variants) [K4008]"),
              std::string::npos)
        << r.err;
    ScratchDir dir;
    std::string text = ReadFile(Wasteful());
    auto retag = [&](const std::string& from, const std::string& to) {
        const std::string tag = "\"KilnMaxVariants\" = ";
        text.replace(text.find(tag + from), tag.size() + from.size(), tag + to);
    };
    retag("\"8\"", "\"3\"");
    const RunResult tagged = RunKiln("lint --no-cache " + dir.Write("Tagged.shader", text));
    EXPECT_EQ(tagged.exit_code, 1);
    EXPECT_NE(tagged.err.find("over the limit of 3"), std::string::npos) << tagged.err;
    retag("\"3\"", "\"x\"");
    const RunResult bad = RunKiln("lint --no-cache " + dir.Write("Bad.shader", text));
    EXPECT_NE(bad.err.find("[K4020]"), std::string::npos) << bad.err;
}

TEST(Lint, TheShippedMaterialsAreClean) {
    std::string files;
    for (const char* s :
         {"Unlit", "Lambert", "LambertAmbient", "BlinnPhong", "BlinnPhongTextured",
          "EnergyConserving", "Standard", "StandardMetallic", "MultiLight", "Deferred"})
        files += DataPath("../materials/") + s + ".shader ";
    const RunResult r = RunKiln("lint --no-cache -Werror " + files);
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

// The alias merge: fewer variant records, a smaller pack, and every keyword set still found,
// with the modules the unmerged pack gives it.
TEST(Lint, TheAliasMergeShrinksThePackAndEveryLookupStillSucceeds) {
    ScratchDir dir;
    const std::string merged = dir.path() + "/merged.kpack", full = dir.path() + "/full.kpack";
    ASSERT_EQ(
        RunKiln("compile " + Wasteful() + " --all-features --no-cache -o " + merged).exit_code, 0);
    ASSERT_EQ(RunKiln("compile " + Wasteful() +
                      " --all-features --no-cache --no-keyword-aliases -o " + full)
                  .exit_code,
              0);
    pack::MappedFile fm, ff;
    pack::Pack m, f;
    ASSERT_TRUE(MapInto(merged, fm));
    ASSERT_TRUE(MapInto(full, ff));
    ASSERT_TRUE(OpenInto(fm.bytes(), m));
    ASSERT_TRUE(OpenInto(ff.bytes(), f));
    EXPECT_LT(fm.bytes().size(), ff.bytes().size());
    EXPECT_EQ(f.Count(pack::SectionTag::kVariants), 101u);
    EXPECT_EQ(m.Count(pack::SectionTag::kVariants), 101u - 64u);
    const uint32_t pass = *m.FindPass(*m.FindShader("Test/Wasteful"), "BASE");
    ASSERT_EQ(*f.FindPass(*f.FindShader("Test/Wasteful"), "BASE"), pass);
    const pack::PassRec rec = f.Pass(pass).value();
    for (uint32_t v = rec.first_variant; v < rec.first_variant + rec.variant_count; ++v) {
        const pack::VariantRec all = f.Variant(v).value();
        const std::vector<std::string> keywords = f.KeywordsOf(pass, pack::VariantKey(all.key));
        const auto found = m.FindVariant(pass, m.KeyFor(pass, keywords));
        ASSERT_TRUE(found) << pack::JoinKeywords(keywords);
        const pack::VariantRec got = m.Variant(*found).value();
        for (const auto& [a, b] : {std::pair{all.vertex_module, got.vertex_module},
                                   std::pair{all.fragment_module, got.fragment_module}}) {
            const auto x = f.Spirv(f.Module(a).value());
            const auto y = m.Spirv(m.Module(b).value());
            EXPECT_TRUE(std::equal(x.begin(), x.end(), y.begin(), y.end()))
                << pack::JoinKeywords(keywords);
        }
    }
}

}  // namespace
}  // namespace kiln::test
