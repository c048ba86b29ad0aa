// Scene-driven stripping as a user runs it: kiln compile --scene / --usage / --verify-scene /
// --explain, the packs it writes, renders from them (lavapipe) and the runtime's strict mode.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "kiln/pack/pass_id.h"
#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

std::string StripData(const std::string& name) {
    return DataPath("strip/data/" + name);
}

// Variants per pass label of the one shader in a pack.
std::map<std::string, std::vector<std::string>> VariantsByPass(const std::string& path) {
    std::map<std::string, std::vector<std::string>> out;
    pack::MappedFile file;
    pack::Pack pk;
    EXPECT_TRUE(MapInto(path, file));
    EXPECT_TRUE(OpenInto(file.bytes(), pk));
    for (uint32_t p = 0; p < pk.Count(pack::SectionTag::kPasses); ++p) {
        const pack::PassRec rec = pk.Pass(p).value();
        auto& list = out[pack::PassLabel(pk, p)];
        for (uint32_t v = rec.first_variant; v < rec.first_variant + rec.variant_count; ++v) {
            list.push_back(
                pack::JoinKeywords(pk.KeywordsOf(p, pack::VariantKey(pk.Variant(v).value().key))));
        }
    }
    return out;
}

// kiln compile of the StripLight shader, stripped to `scene` when it is not empty.
RunResult CompileStripLight(const std::string& out,
                            const std::string& scene,
                            const std::string& more = "",
                            const std::string& shader = StripData("StripLight.shader")) {
    return RunKiln("compile " + shader + " -I " + DataPath("../materials") + " -o " + out +
                   " --no-cache" + (scene.empty() ? "" : " --scene " + StripData(scene)) + " " +
                   more);
}

std::string Render(const std::string& scene, const std::string& pack, const std::string& exr) {
    const RunResult r = RunKiln("render " + StripData(scene) + " --pack " + pack +
                                " --pixel-lights 1 --width 96 --height 64 --validation -o " + exr +
                                ".png --exr " + exr);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return ReadFile(exr);
}

TEST(SceneStrip, DirectionalLightsKeepOnlyTheirVariantsAndRenderTheSame) {
    ScratchDir dir;
    const std::string full = dir.path() + "/full.kpack";
    ASSERT_EQ(CompileStripLight(full, "").exit_code, 0);
    const auto all = VariantsByPass(full);
    ASSERT_EQ(all.at("FORWARD_DELTA").size(), 3u);
    ASSERT_EQ(all.at("DEFERRED").size(), 2u);

    // One directional light: it is the main light of the base pass; nothing is additive.
    const std::string sun = dir.path() + "/sun.kpack";
    RunResult r = CompileStripLight(sun, "sun.gltf", "--verify-scene");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto kept = VariantsByPass(sun);
    EXPECT_EQ(kept.at("FORWARD"), std::vector<std::string>{"(no keywords)"});
    EXPECT_TRUE(kept.at("FORWARD_DELTA").empty());
    EXPECT_TRUE(kept.at("DEFERRED").empty());  // the forward path never draws it

    // Two directional lights: one ForwardAdd variant of the three, DIRECTIONAL.
    const std::string two = dir.path() + "/two_suns.kpack";
    r = CompileStripLight(two, "two_suns.gltf", "--verify-scene");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    kept = VariantsByPass(two);
    EXPECT_EQ(kept.at("FORWARD"), std::vector<std::string>{"(no keywords)"});
    EXPECT_EQ(kept.at("FORWARD_DELTA"), std::vector<std::string>{"DIRECTIONAL"});
    EXPECT_TRUE(kept.at("DEFERRED").empty());

    // Point lights past --pixel-lights become vertex lights: VERTEXLIGHT_ON, and POINT only.
    const std::string lamps = dir.path() + "/lamps.kpack";
    r = CompileStripLight(lamps, "lamps.gltf", "--pixel-lights 1 --verify-scene");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    kept = VariantsByPass(lamps);
    EXPECT_EQ(kept.at("FORWARD"), std::vector<std::string>{"VERTEXLIGHT_ON"});
    EXPECT_EQ(kept.at("FORWARD_DELTA"), std::vector<std::string>{"POINT"});

    // The stripped packs render bit for bit what the full pack renders (the same SPIR-V, the
    // same draws): compared as 32-bit float EXR files, no tolerance.
    for (const auto& [scene, stripped] :
         {std::pair{"sun.gltf", sun}, {"two_suns.gltf", two}, {"lamps.gltf", lamps}}) {
        const std::string a = Render(scene, full, dir.path() + "/full_" + scene + ".exr");
        const std::string b = Render(scene, stripped, dir.path() + "/strip_" + scene + ".exr");
        EXPECT_FALSE(a.empty());
        EXPECT_TRUE(a == b) << scene << ": the stripped pack renders differently";
    }
}

TEST(SceneStrip, VerifySceneFailsWhenANeededVariantIsRemovedByHand) {
    ScratchDir dir;
    std::string text = ReadFile(StripData("StripLight.shader"));
    const std::string anchor = "#pragma multi_compile DIRECTIONAL POINT SPOT";
    ASSERT_NE(text.find(anchor), std::string::npos);
    text.replace(text.find(anchor), anchor.size(),
                 anchor + "\n            #pragma skip_variants POINT");
    const std::string shader = dir.Write("StripLight.shader", text);
    const std::string out = dir.path() + "/lamps.kpack";
    const RunResult r =
        CompileStripLight(out, "lamps.gltf", "--pixel-lights 1 --verify-scene", shader);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("[K4018]"), std::string::npos) << r.err;  // looked up, not built
    EXPECT_NE(r.err.find("the stripped pack misses a lookup of the scene: shader "
                         "'Test/StripLight' pass 'FORWARD_DELTA' has no variant for keywords "
                         "'POINT'"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("[K4019]"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("point light 'Green'"), std::string::npos) << r.err;  // who needed it
    EXPECT_FALSE(fs::exists(out));  // no pack that misses what the scene needs

    // Without --verify-scene the pack is written, with the warning.
    const RunResult unverified = CompileStripLight(out, "lamps.gltf", "--pixel-lights 1", shader);
    EXPECT_EQ(unverified.exit_code, 0) << unverified.err;
    EXPECT_NE(unverified.err.find("[K4018]"), std::string::npos);
}

TEST(SceneStrip, TheRuntimeErrorsOnAMissAndRecordsItInTheUsageLog) {
    ScratchDir dir;
    const std::string sun = dir.path() + "/sun.kpack";
    ASSERT_EQ(CompileStripLight(sun, "sun.gltf").exit_code, 0);
    const std::string usage = dir.path() + "/usage.json";
    // The sun-only pack has no additive variant; the lamps scene needs one.
    const RunResult r = RunKiln("render " + StripData("lamps.gltf") + " --pack " + sun +
                                " --pixel-lights 1 --dry-run --usage " + usage);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("[K0006]"), std::string::npos) << r.err;
    const nlohmann::json doc = nlohmann::json::parse(ReadFile(usage));
    bool missed = false;
    for (const auto& l : doc["lookups"]) {
        missed = missed || (l["pass"] == "FORWARD_DELTA" && l["found"] == false);
    }
    EXPECT_TRUE(missed) << doc.dump(1);
}

TEST(SceneStrip, ADryRunLooksUpWhatARenderLooksUp) {
    ScratchDir dir;
    const std::string full = dir.path() + "/full.kpack";
    ASSERT_EQ(CompileStripLight(full, "").exit_code, 0);
    const std::string planned = dir.path() + "/planned.json",
                      rendered = dir.path() + "/rendered.json";
    const std::string common =
        "render " + StripData("lamps.gltf") + " --pack " + full + " --pixel-lights 1 ";
    ASSERT_EQ(RunKiln(common + "--dry-run --usage " + planned).exit_code, 0);
    const RunResult r =
        RunKiln(common + "--width 32 --height 32 -o " + dir.path() + "/x.png --usage " + rendered);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json a = nlohmann::json::parse(ReadFile(planned));
    const nlohmann::json b = nlohmann::json::parse(ReadFile(rendered));
    EXPECT_EQ(a, b);
    EXPECT_EQ(a["lookups"].size(), 2u);  // VERTEXLIGHT_ON base, POINT additive
    EXPECT_EQ(a["materials"].size(), 2u);
}

TEST(SceneStrip, UsageFilesStripWithoutAScene) {
    ScratchDir dir;
    const std::string usage = dir.Write("usage.json",
                                        R"({"kiln_usage": 1, "lookups": [
              {"shader": "Test/StripLight", "pass": "FORWARD_DELTA", "keywords": ["SPOT"]},
              {"shader": "Other/Shader", "pass": "P", "keywords": []}]})");
    const std::string out = dir.path() + "/u.kpack";
    const RunResult r = CompileStripLight(out, "", "--usage " + usage + " --explain-json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto kept = VariantsByPass(out);
    EXPECT_TRUE(kept.at("FORWARD").empty());
    EXPECT_EQ(kept.at("FORWARD_DELTA"), std::vector<std::string>{"SPOT"});
    const nlohmann::json explain = nlohmann::json::parse(r.out);
    EXPECT_EQ(explain["kept_variants"], 1);
    EXPECT_EQ(explain["declared_combinations"], 7);
    EXPECT_EQ(explain["other_shaders"][0]["shader"], "Other/Shader");

    // A pass the shader does not have: a stale usage file is an error, not an empty pass.
    const std::string stale = dir.Write("stale.json", R"({"kiln_usage": 1, "lookups": [
              {"shader": "Test/StripLight", "pass": "FORWARD_DELT", "keywords": ["SPOT"]}]})");
    const RunResult bad = CompileStripLight(out, "", "--usage " + stale);
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("looks up pass 'FORWARD_DELT' of shader 'Test/StripLight', which has "
                           "no such pass; did you mean 'FORWARD_DELTA'?"),
              std::string::npos)
        << bad.err;
    EXPECT_NE(bad.err.find("[K4017]"), std::string::npos);
}

TEST(SceneStrip, APassOf2To40CombinationsIsPlannedFromItsRequests) {
    ScratchDir dir;
    std::string pragmas;
    for (int i = 0; i < 40; ++i)
        pragmas += "#pragma multi_compile _ KW" + std::to_string(i) + "\n";
    const std::string shader =
        dir.Write("Wide.shader",
                  "Shader \"Test/Wide\" { SubShader { Pass { CGPROGRAM\n#pragma vertex v\n"
                  "#pragma fragment f\n" +
                      pragmas +
                      "float4 v(float4 p : POSITION) : SV_POSITION { return p; }\n"
                      "float4 f() : SV_Target {\n#if KW7 && KW39\nreturn 1;\n#endif\n"
                      "return 0; }\nENDCG } } }\n");
    const std::string usage = dir.Write("usage.json", R"({"kiln_usage": 1, "lookups": [
              {"shader": "Test/Wide", "pass": "#1", "keywords": ["KW7", "KW39"]},
              {"shader": "Test/Wide", "pass": "#1", "keywords": []}]})");
    const std::string out = dir.path() + "/wide.kpack";
    // Unstripped, the product is refused; stripped, two variants are built.
    EXPECT_EQ(RunKiln("compile " + shader + " -o " + out + " --no-cache").exit_code, 1);
    const RunResult r =
        RunKiln("compile " + shader + " -o " + out + " --no-cache --usage " + usage + " --explain");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(VariantsByPass(out).at("#1"),
              (std::vector<std::string>{"(no keywords)", "KW7 KW39"}));
    EXPECT_NE(r.out.find("kept 2 of 1099511627776 keyword combinations"), std::string::npos)
        << r.out;
}

// kiln diff between the full and a stripped pack: per pass, what was added or removed, and a
// budget for CI.
TEST(SceneStrip, DiffCountsVariantsAndBytesPerPassWithABudget) {
    ScratchDir dir;
    const std::string full = dir.path() + "/full.kpack", sun = dir.path() + "/sun.kpack";
    ASSERT_EQ(CompileStripLight(full, "").exit_code, 0);
    ASSERT_EQ(CompileStripLight(sun, "sun.gltf").exit_code, 0);
    const RunResult grow = RunKiln("diff " + sun + " " + full);
    ASSERT_EQ(grow.exit_code, 0) << grow.err;
    EXPECT_NE(grow.out.find("shader \"Test/StripLight\" pass \"FORWARD_DELTA\": +3 variants, +"),
              std::string::npos)
        << grow.out;
    EXPECT_NE(grow.out.find("total: +6 variants, +"), std::string::npos) << grow.out;
    const RunResult json = RunKiln("diff --json " + full + " " + sun);
    ASSERT_EQ(json.exit_code, 0);
    const nlohmann::json doc = nlohmann::json::parse(json.out);
    uint64_t removed = 0;
    for (const auto& p : doc["passes"]) {
        EXPECT_LE(p["bytes"]["new"].get<uint64_t>(), p["bytes"]["old"].get<uint64_t>());
        removed += p["variants"]["old"].get<uint64_t>() - p["variants"]["new"].get<uint64_t>();
    }
    EXPECT_EQ(removed, 6u);
    // Over the budget: exit 1 with K0026; within it (or shrinking): exit 0.
    const RunResult over = RunKiln("diff --max-added-variants 5 " + sun + " " + full);
    EXPECT_EQ(over.exit_code, 1);
    EXPECT_NE(over.err.find("6 variants more than the old one, over the budget of 5"),
              std::string::npos)
        << over.err;
    EXPECT_NE(over.err.find("[K0026]"), std::string::npos);
    EXPECT_EQ(RunKiln("diff --max-added-variants 6 " + sun + " " + full).exit_code, 0);
    EXPECT_EQ(RunKiln("diff --max-added-bytes 0 " + full + " " + sun).exit_code, 0);
    EXPECT_EQ(RunKiln("diff --max-added-bytes 1000 " + sun + " " + full).exit_code, 1);
}

// kiln diff names the keyword sets a pass gained and lost (text and JSON): from the one-sun pack to
// the lamps pack (point lights past --pixel-lights 1 become vertex lights), the base pass trades
// its plain variant for VERTEXLIGHT_ON and the additive pass gains POINT. Past 16 sets a pass
// lists 16 and says how many more; --json lists every one.
TEST(SceneStrip, DiffNamesTheKeywordSetsAddedAndRemoved) {
    ScratchDir dir;
    const std::string sun = dir.path() + "/sun.kpack", lamps = dir.path() + "/lamps.kpack";
    ASSERT_EQ(CompileStripLight(sun, "sun.gltf").exit_code, 0);
    ASSERT_EQ(CompileStripLight(lamps, "lamps.gltf", "--pixel-lights 1").exit_code, 0);
    const RunResult text = RunKiln("diff " + sun + " " + lamps);
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("pass \"FORWARD\": 0 variants, "), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("  + VERTEXLIGHT_ON\n  - (no keywords)\n"), std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("pass \"FORWARD_DELTA\": +1 variants, "), std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("  + POINT\n"), std::string::npos) << text.out;
    const RunResult json = RunKiln("diff --json " + sun + " " + lamps);
    ASSERT_EQ(json.exit_code, 0);
    std::map<std::string, nlohmann::json> sets;
    const nlohmann::json doc = nlohmann::json::parse(json.out);
    for (const auto& p : doc["passes"])
        sets[p["pass"].get<std::string>()] = p["keyword_sets"];
    EXPECT_EQ(sets["FORWARD"]["added"], nlohmann::json::array({"VERTEXLIGHT_ON"}));
    EXPECT_EQ(sets["FORWARD"]["removed"], nlohmann::json::array({"(no keywords)"}));
    EXPECT_EQ(sets["FORWARD_DELTA"]["added"], nlohmann::json::array({"POINT"}));
    EXPECT_EQ(sets["FORWARD_DELTA"]["removed"], nlohmann::json::array());
    EXPECT_EQ(sets["DEFERRED"]["added"], nlohmann::json::array());

    // 32 keyword sets in one pass (each keyword changes the program): 16 listed, then the count.
    std::string pragmas, uses;
    for (const char* k : {"A", "B", "C", "D", "E"}) {
        pragmas += std::string("#pragma multi_compile _ KW_") + k + "\n";
        uses += std::string("#ifdef KW_") + k + "\nc += 0.1;\n#endif\n";
    }
    const std::string many = dir.Write(
        "Many.shader",
        "Shader \"Test/Many\" { SubShader { Pass { CGPROGRAM\n#pragma vertex v\n#pragma "
        "fragment f\n" +
            pragmas +
            "float4 v(float4 p : POSITION) : SV_POSITION { return p; }\nfloat4 f() : SV_Target {\n"
            "float c = 0;\n" +
            uses + "return c;\n}\nENDCG } } }\n");
    const std::string many_pack = dir.path() + "/many.kpack";
    ASSERT_EQ(RunKiln("compile " + many + " --no-cache -o " + many_pack).exit_code, 0);
    const RunResult capped = RunKiln("diff " + sun + " " + many_pack);
    ASSERT_EQ(capped.exit_code, 0) << capped.err;
    EXPECT_NE(capped.out.find("  ... 16 more added (--json lists every one)\n"), std::string::npos)
        << capped.out;
    EXPECT_NE(capped.out.find("  + KW_A KW_B KW_C KW_D KW_E\n"), std::string::npos) << capped.out;
}

// The shaders the demo scene's materials use, with the deferred light pass: a command line's list.
std::string DemoShaders() {
    std::string shaders;
    for (const char* s : {"Unlit", "Lambert", "LambertAmbient", "BlinnPhong", "BlinnPhongTextured",
                          "EnergyConserving", "Standard", "StandardMetallic", "MultiLight",
                          "Deferred", "internal/DeferredShading"}) {
        shaders += DataPath(std::string("../materials/") + s + ".shader") + " ";
    }
    return shaders;
}

// --path deferred plans the deferred path's lookups: the G-buffer passes of the objects that have
// one, the light pass's variants per light (a mask and a bounded draw for ranged lights), and the
// forward passes of the rest; the stripped pack then renders the demo scene deferred (and not
// forward, whose variants it left out).
TEST(SceneStrip, TheDeferredPathStripsToItsOwnLookups) {
    ScratchDir dir;
    const std::string out = dir.path() + "/deferred.kpack";
    const std::string shaders = DemoShaders();
    const std::string demo = DataPath("../scenes/demo/demo.gltf");
    const RunResult r = RunKiln("compile " + shaders + "--no-cache -o " + out + " --scene " + demo +
                                " --path deferred --verify-scene");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto kept = VariantsByPass(out);
    EXPECT_EQ(kept.at("DEFERRED").size(),
              3u);  // Kiln/Deferred; StandardMetallic with and without _EMISSION
    EXPECT_EQ(kept.at("LIGHT"), (std::vector<std::string>{"DIRECTIONAL"}));  // the sun
    EXPECT_EQ(kept.at("LIGHT_MASK").size(), 1u);
    EXPECT_EQ(kept.at("LIGHT_BOUNDED"), (std::vector<std::string>{"POINT", "SPOT"}));
    const RunResult deferred = RunKiln("render " + demo + " --pack " + out +
                                       " --path deferred --width 96 --height 54 --validation -o " +
                                       dir.path() + "/deferred.png");
    EXPECT_EQ(deferred.exit_code, 0) << deferred.err;
    const RunResult forward = RunKiln("render " + demo + " --pack " + out +
                                      " --width 96 --height 54 -o " + dir.path() + "/forward.png");
    EXPECT_EQ(forward.exit_code, 1);
    EXPECT_NE(forward.err.find("[K0006]"), std::string::npos) << forward.err;
}

// --shadows plans the shadows the deferred path draws (its light passes receive them, as Unity's):
// the light pass keeps one shadow variant per light type, the collector its SHADOWS_SOFT variant;
// the stripped pack renders the scene deferred with soft shadows, and not without shadows (whose
// light-pass variants it left out).
TEST(SceneStrip, DeferredShadowsStripToTheLightPassShadowVariants) {
    ScratchDir dir;
    const std::string out = dir.path() + "/deferred_shadows.kpack";
    const std::string shaders =
        DemoShaders() + DataPath("../materials/internal/ScreenSpaceShadows.shader") + " ";
    const std::string demo = DataPath("../scenes/demo/demo.gltf");
    const RunResult r = RunKiln("compile " + shaders + "--no-cache -o " + out + " --scene " + demo +
                                " --path deferred --shadows soft --verify-scene");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto kept = VariantsByPass(out);
    EXPECT_EQ(kept.at("LIGHT"), (std::vector<std::string>{"DIRECTIONAL SHADOWS_SCREEN"}));
    EXPECT_EQ(kept.at("LIGHT_BOUNDED"),
              (std::vector<std::string>{"SPOT SHADOWS_DEPTH SHADOWS_SOFT",
                                        "POINT SHADOWS_CUBE SHADOWS_SOFT"}));
    EXPECT_EQ(kept.at("#1"), (std::vector<std::string>{"SHADOWS_SOFT"}));  // the collector
    const std::string render = "render " + demo + " --pack " + out +
                               " --path deferred --width 96 --height 54 --validation -o " +
                               dir.path() + "/deferred.png";
    const RunResult shadowed = RunKiln(render + " --shadows soft");
    EXPECT_EQ(shadowed.exit_code, 0) << shadowed.err;
    EXPECT_NE(shadowed.out.find("shadow draws"), std::string::npos) << shadowed.out;
    const RunResult unshadowed = RunKiln(render);
    EXPECT_EQ(unshadowed.exit_code, 1);
    EXPECT_NE(unshadowed.err.find("[K0006]"), std::string::npos) << unshadowed.err;
}

TEST(SceneStrip, FlagsThatDoNotApplyAreRefused) {
    ScratchDir dir;
    const std::string out = dir.path() + "/x.kpack";
    for (const char* more : {"--all-features", "--keywords A", "--materials x.material"}) {
        const RunResult r = CompileStripLight(out, "sun.gltf", more);
        EXPECT_EQ(r.exit_code, 2) << more << ": " << r.err;
        EXPECT_NE(r.err.find("[K0003]"), std::string::npos) << r.err;
    }
    EXPECT_EQ(CompileStripLight(out, "", "--verify-scene").exit_code, 2);
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace kiln::test
