// One name per pass (kiln/pack/pass_id.h): `kiln variants --json`, `kiln info --json`, the
// variant selector's missing-variant error, the usage log and Pack::FindPass all use it. And the
// selector with its usage file, which need only kiln::pack.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "kiln/pack/pass_id.h"
#include "kiln/pack/reader.h"
#include "kiln/pack/variant_selector.h"
#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

const char* kProgram =
    "      CGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n%s\n"
    "float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
    "float4 frag() : SV_Target { return 1; }\n      ENDCG\n";

std::string Program(const std::string& pragmas = "") {
    std::string p = kProgram;
    return p.replace(p.find("%s"), 2, pragmas);
}

// A named pass, a LightMode-tagged one, one with neither, and a second SubShader.
std::string PassesShader() {
    return "Shader \"Bridge/Passes\" {\n  SubShader {\n"
           "    Pass { Name \"Main\"\n" +
           Program("#pragma shader_feature _ FOO") +
           "    }\n"
           "    Pass { Tags { \"LightMode\" = \"ForwardAdd\" }\n" +
           Program() +
           "    }\n"
           "    Pass {\n" +
           Program() +
           "    }\n  }\n"
           "  SubShader { Pass {\n" +
           Program() + "  } }\n}\n";
}

const std::vector<std::string> kExpected = {"SubShader 1/Main", "SubShader 1/ForwardAdd",
                                            "SubShader 1/#3", "SubShader 2/#1"};

TEST(PassIdentity, OneNameEverywhere) {
    test::ScratchDir dir;
    const std::string shader = dir.Write("passes.shader", PassesShader());
    const std::string pack_path = dir.path() + "/passes.kpack";
    ASSERT_EQ(test::RunKiln("compile " + shader + " -o " + pack_path).exit_code, 0);

    // kiln variants --json
    const test::RunResult variants = test::RunKiln("variants --json " + shader);
    ASSERT_EQ(variants.exit_code, 0) << variants.err;
    std::vector<std::string> from_variants;
    const nlohmann::json variants_doc = nlohmann::json::parse(variants.out);
    for (const auto& p : variants_doc["passes"])
        from_variants.push_back(p["pass"].get<std::string>());
    EXPECT_EQ(from_variants, kExpected);

    // kiln info --json
    const test::RunResult info = test::RunKiln("info --json " + pack_path);
    ASSERT_EQ(info.exit_code, 0) << info.err;
    std::vector<std::string> from_info;
    const nlohmann::json info_doc = nlohmann::json::parse(info.out);
    for (const auto& p : info_doc["shaders"][0]["passes"])
        from_info.push_back(p["pass"].get<std::string>());
    EXPECT_EQ(from_info, kExpected);

    // The pack's own PassLabel, and FindPass by it.
    pack::MappedFile file;
    pack::Pack pk;
    ASSERT_TRUE(kiln::test::MapInto(pack_path, file));
    ASSERT_TRUE(kiln::test::OpenInto(file.bytes(), pk));
    for (uint32_t i = 0; i < kExpected.size(); ++i) {
        EXPECT_EQ(pack::PassLabel(pk, i), kExpected[i]);
        EXPECT_EQ(pk.FindPass(0, kExpected[i]), std::optional<uint32_t>(i));
    }

    // The missing-variant error and the usage log.
    pack::VariantSelector selector(pk, pack::MissingVariantPolicy::kError);
    const Result<pack::VariantChoice> missing = selector.Select(0, {"FOO"});
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("pass '" + kExpected[0] + "'"), std::string::npos)
        << missing.error().message;
    ASSERT_TRUE(selector.Select(3, {}).ok());
    const Result<pack::UsageLog> usage =
        pack::ParseUsageFile(pack::UsageFileText({pack::UsageOf({&selector}), {}}));
    ASSERT_TRUE(usage.ok()) << usage.error().message;
    ASSERT_EQ(usage.value().lookups.size(), 2u);
    EXPECT_EQ(usage.value().lookups[0].pass, kExpected[0]);
    EXPECT_FALSE(usage.value().lookups[0].found);
    EXPECT_EQ(usage.value().lookups[1].pass, kExpected[3]);
    EXPECT_EQ(pk.FindPass(0, usage.value().lookups[1].pass), std::optional<uint32_t>(3));

    // `kiln extract --pass` takes the same name.
    EXPECT_EQ(test::RunKiln("extract " + pack_path + " --shader Bridge/Passes --pass \"" +
                            kExpected[3] + "\" --stage frag -o " + dir.path() + "/f.spv")
                  .exit_code,
              0);
}

TEST(PassIdentity, OneSubShaderHasNoPrefix) {
    EXPECT_EQ(pack::PassId({"FORWARD", "ForwardBase", 0, 0, false}), "FORWARD");
    EXPECT_EQ(pack::PassId({"", "ForwardBase", 0, 0, false}), "ForwardBase");
    EXPECT_EQ(pack::PassId({"", "", 0, 1, false}), "#2");
    EXPECT_EQ(pack::PassId({"", "", 1, 0, true}), "SubShader 2/#1");
}

TEST(UsageFile, RejectsWhatIsNotOne) {
    EXPECT_FALSE(pack::ParseUsageFile("[]").ok());
    EXPECT_FALSE(pack::ParseUsageFile("{\"kiln_usage\": 2, \"lookups\": []}").ok());
    EXPECT_FALSE(pack::ParseUsageFile("{\"kiln_usage\": 1}").ok());
    EXPECT_FALSE(
        pack::ParseUsageFile("{\"kiln_usage\": 1, \"lookups\": [{\"shader\": \"a\", \"pass\": 1, "
                             "\"keywords\": []}]}")
            .ok());
    EXPECT_FALSE(pack::ParseUsageFile("{\"kiln_usage\": 1, \"lookups\": [], \"materials\": "
                                      "[{\"material\": \"m\"}]}")
                     .ok());
    EXPECT_FALSE(pack::ParseUsageFile("{\"kiln_usage\": 1, \"lookups\": [{\"shader\": \"a\", "
                                      "\"pass\": \"p\", \"keywords\": [], \"requested_by\": "
                                      "\"x\"}]}")
                     .ok());
    const auto ok = pack::ParseUsageFile("{\"kiln_usage\": 1, \"lookups\": []}");
    ASSERT_TRUE(ok.ok());
    EXPECT_TRUE(ok.value().lookups.empty());
}

TEST(UsageFile, KeepsWhoAskedAndTheMaterials) {
    pack::UsageLog log;
    pack::UsageEntry e{"S", "FORWARD", {"POINT"}, 3, true, {}, 0};
    for (const char* who : {"m on node 'a': point light 'l'", "m on node 'a': point light 'l'",
                            "m on node 'b': point light 'l'"}) {
        pack::AddRequester(e.requested_by, e.requesters, who);  // the same reason is kept once
    }
    log.lookups.push_back(e);
    log.materials.push_back({"m", "S"});
    const auto back = pack::ParseUsageFile(pack::UsageFileText(log));
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back.value().lookups.size(), 1u);
    EXPECT_EQ(back.value().lookups[0].requested_by,
              (std::vector<std::string>{"m on node 'a': point light 'l'",
                                        "m on node 'b': point light 'l'"}));
    EXPECT_EQ(back.value().lookups[0].requesters, 3u);
    EXPECT_EQ(back.value().lookups[0].keywords, std::vector<std::string>{"POINT"});
    EXPECT_EQ(back.value().materials, log.materials);
}

// Every truncated prefix of a usage file is an error with a message, never a crash.
TEST(UsageFile, EveryTruncatedPrefixIsRejectedCleanly) {
    pack::UsageLog log;
    log.lookups.push_back(
        {"S", "FORWARD", {"POINT", "_NORMALMAP"}, 3, false, {"m on node 'a'"}, 1});
    log.materials.push_back({"m", "S"});
    const std::string text = pack::UsageFileText(log);
    for (size_t n = 0; n < text.size(); ++n) {
        const auto read = pack::ParseUsageFile(std::string_view(text).substr(0, n));
        if (!read.ok()) {
            EXPECT_FALSE(read.error().message.empty()) << n;
        }
    }
    EXPECT_TRUE(pack::ParseUsageFile(text).ok());
}

TEST(VariantSelection, MissingVariantErrorNamesShaderPassKeywordsAndClosest) {
    pack::MappedFile file;
    pack::Pack pack;
    ASSERT_TRUE(kiln::test::MapInto(KILN_STRIPPED_PACK, file));
    ASSERT_TRUE(kiln::test::OpenInto(file.bytes(), pack));
    const uint32_t shader = *pack.FindShader("Kiln/StandardMetallic");
    const uint32_t pass = *pack.FindPass(shader, "ForwardBase");
    pack::VariantSelector strict(pack, pack::MissingVariantPolicy::kError);
    const auto missing = strict.Select(pass, {"_NORMALMAP", "_EMISSION"});
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().message,
              "shader 'Kiln/StandardMetallic' pass 'FORWARD' has no variant for keywords "
              "'_NORMALMAP _EMISSION' (stripped or never compiled); closest present: "
              "'_NORMALMAP', '(no keywords)', 'SHADOWS_SCREEN _NORMALMAP'");
    const auto found = strict.Select(pass, {"_NORMALMAP"});
    ASSERT_TRUE(found.ok());
    EXPECT_TRUE(found.value().exact);

    pack::VariantSelector lenient(pack, pack::MissingVariantPolicy::kClosest);
    const auto closest = lenient.Select(pass, {"_NORMALMAP", "_EMISSION"});
    ASSERT_TRUE(closest.ok());
    EXPECT_FALSE(closest.value().exact);
    EXPECT_EQ(
        pack.KeywordsOf(pass, pack::VariantKey(pack.Variant(closest.value().variant).value().key)),
        std::vector<std::string>{"_NORMALMAP"});
    EXPECT_NE(closest.value().warning.find("using the closest, '_NORMALMAP'"), std::string::npos);
    EXPECT_FALSE(strict.Select(100000, {}).ok());  // out of range: an error, not a crash

    test::ScratchDir dir;
    const std::string usage = dir.path() + "/usage.json";
    ASSERT_TRUE(pack::WriteUsageFile(usage, {pack::UsageOf({&strict, &lenient}), {}}).ok());
    std::ifstream in(usage);
    const nlohmann::json doc = nlohmann::json::parse(in);
    EXPECT_EQ(doc["kiln_usage"], 1);
    ASSERT_EQ(doc["lookups"].size(), 3u);  // strict: missing + found; lenient: missing
    EXPECT_EQ(doc["lookups"][0]["shader"], "Kiln/StandardMetallic");
    EXPECT_EQ(doc["lookups"][0]["pass"], "FORWARD");
}

}  // namespace
}  // namespace kiln
