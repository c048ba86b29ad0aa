// The render-path interface (render/render_path.h) holds a third path that only implements it:
// tests/runtime/toy_path/toy_path.cpp, "toy" (unlit-only), linked into this test and into a toy
// kiln / kiln-render pair built from the unchanged tools/ mains. Rendering, planning (the dry
// run's lookups) and kiln compile --scene --path toy --verify-scene all walk its requests; the
// forward and deferred paths' own tests run unchanged beside it.
#include <filesystem>

#include "kiln/pack/pass_id.h"
#include "kiln/runtime/plan.h"
#include "render/render_path.h"
#include "runtime/runtime_fixture.h"
#include "support/test_support.h"

namespace kiln::test {

bool ToyPathRegistered();  // toy_path/toy_path.cpp

namespace {

const runtime::RenderPath kToy{"toy"};

std::string Unlit() {
    return std::string(KILN_SOURCE_DIR) + "/materials/Unlit.material";
}

std::string Lit() {
    return std::string(KILN_SOURCE_DIR) + "/materials/StandardMetallic.material";
}

double MeanLuminance(const runtime::LinearImage& image) {
    double sum = 0;
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
        sum += 0.2126 * image.rgba[i] + 0.7152 * image.rgba[i + 1] + 0.0722 * image.rgba[i + 2];
    }
    return sum / double(image.width * image.height);
}

TEST(ToyPath, IsRegisteredBesideTheBuiltInPaths) {
    ASSERT_TRUE(ToyPathRegistered());
    std::vector<std::string> names;
    for (const runtime::RenderPathInfo& p : runtime::RenderPaths()) {
        names.push_back(p.name);
        EXPECT_FALSE(p.summary.empty()) << p.name;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"forward", "deferred", "toy"}));
    // A name is registered once, in any case.
    class Again final : public runtime::PathRenderer {
      public:
        explicit Again(std::string name) : name_(std::move(name)) {}
        std::string_view Name() const override { return name_; }
        std::string_view Summary() const override { return "again"; }
        Result<std::unique_ptr<runtime::PathPlan>> Plan(const runtime::PlanInputs&) const override {
            return Error{DiagCode::kRenderFailed, "not planned"};
        }

      private:
        std::string name_;
    };
    EXPECT_FALSE(runtime::RegisterPathRenderer(std::make_unique<Again>("toy")));
    EXPECT_FALSE(runtime::RegisterPathRenderer(std::make_unique<Again>("Forward")));
    EXPECT_FALSE(runtime::RegisterPathRenderer(std::make_unique<Again>("")));
    EXPECT_EQ(runtime::RenderPaths().size(), 3u);
}

class ToyPathTest : public RuntimeTest {};

// An unlit material ignores lights: the toy path draws its scene exactly as the forward path does
// (the same variant of the same pass, the same uniforms it reads; 32-bit float targets compared
// with no tolerance). A lit material drawn by the toy path gets no light: darker than forward.
TEST_F(ToyPathTest, DrawsAnUnlitSceneAsTheForwardPathDoes) {
    runtime::FrameSettings settings;
    settings.width = 96;
    settings.height = 64;
    runtime::FrameStats forward_stats, toy_stats;
    const runtime::LinearImage forward = Render(SphereOnFloor(Unlit()), settings, &forward_stats);
    settings.path = kToy;
    const runtime::LinearImage toy = Render(SphereOnFloor(Unlit()), settings, &toy_stats);
    ASSERT_EQ(toy.rgba.size(), forward.rgba.size());
    EXPECT_TRUE(toy.rgba == forward.rgba) << "the toy path draws the unlit scene differently";
    EXPECT_GT(MeanLuminance(toy), 0.01);  // not an empty frame
    EXPECT_EQ(toy_stats.objects, 2u);
    EXPECT_EQ(toy_stats.path_counts, "2 unlit draws");
    EXPECT_EQ(toy_stats.base_passes + toy_stats.add_passes + toy_stats.gbuffer_draws, 0u);
    EXPECT_EQ(forward_stats.path_counts, "");

    runtime::FrameStats lit_stats;
    const runtime::LinearImage lit_toy = Render(SphereOnFloor(Lit()), settings, &lit_stats);
    settings.path = runtime::RenderPath::kForward;
    const runtime::LinearImage lit_forward = Render(SphereOnFloor(Lit()), settings);
    EXPECT_LT(MeanLuminance(lit_toy), 0.8 * MeanLuminance(lit_forward));
}

// PlanScene walks the toy path's requests: one lookup per object, the material's keywords only
// (no light keyword), asked by the toy path; the materials it used.
TEST_F(ToyPathTest, PlansTheLookupsItDraws) {
    runtime::FrameSettings settings;
    settings.path = kToy;
    DiagnosticList warnings;
    const runtime::Scene scene = SphereOnFloor(Unlit());
    const Result<runtime::ScenePlan> plan = runtime::PlanScene(
        {&renderer_.pack(0), &renderer_.pack(1)}, scene, settings, color_, warnings);
    ASSERT_TRUE(plan) << plan.error().message;
    EXPECT_EQ(plan.value().objects, 2u);
    EXPECT_EQ(plan.value().draws, 2u);
    EXPECT_TRUE(plan.value().missing.all().empty());
    ASSERT_EQ(plan.value().usage.lookups.size(), 1u);  // both objects share the material
    const pack::UsageEntry& lookup = plan.value().usage.lookups[0];
    EXPECT_EQ(lookup.shader, "Kiln/Unlit");
    EXPECT_EQ(lookup.count, 2u);
    ASSERT_FALSE(lookup.requested_by.empty());
    EXPECT_NE(lookup.requested_by[0].find("toy path, unlit"), std::string::npos);
    ASSERT_EQ(plan.value().usage.materials.size(), 1u);
    EXPECT_EQ(plan.value().usage.materials[0].shader, "Kiln/Unlit");

    // With shadows on, the forward path asks the lit shader's base pass for the sun's shadow
    // (SHADOWS_SCREEN) and looks its ShadowCaster pass up; the toy path, which draws no
    // shadows, does neither: each path plans exactly what it draws.
    settings.shadows = runtime::Shadows::kHard;
    for (const runtime::RenderPath& path : {kToy, runtime::RenderPath::kForward}) {
        settings.path = path;
        const Result<runtime::ScenePlan> lit =
            runtime::PlanScene({&renderer_.pack(0), &renderer_.pack(1)}, SphereOnFloor(Lit()),
                               settings, color_, warnings);
        ASSERT_TRUE(lit) << lit.error().message;
        bool screen = false, caster = false;
        size_t lookups = 0;
        for (const pack::UsageEntry& e : lit.value().usage.lookups) {
            lookups += e.pass == "FORWARD" ? 1 : 0;
            screen |= std::count(e.keywords.begin(), e.keywords.end(), "SHADOWS_SCREEN") > 0;
            caster |= e.pass == "ShadowCaster";
        }
        const bool forward = path == runtime::RenderPath::kForward;
        EXPECT_GT(lookups, 0u) << path.name;
        EXPECT_EQ(screen, forward) << path.name;
        EXPECT_EQ(caster, forward) << path.name;
    }
}

TEST_F(ToyPathTest, AnUnknownPathIsAnErrorNamingTheClosest) {
    runtime::FrameSettings settings;
    settings.path = runtime::RenderPath{"toi"};
    runtime::LinearImage image;
    runtime::FrameStats stats;
    const Status e = renderer_.Render(SphereOnFloor(Unlit()), settings, color_, image, stats);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, DiagCode::kBadScene);
    EXPECT_EQ(e.error().message,
              "unknown render path 'toi' (there are forward, deferred, toy); did you mean 'toy'?");
    DiagnosticList warnings;
    EXPECT_FALSE(runtime::PlanScene({&renderer_.pack(0)}, SphereOnFloor(Unlit()), settings, color_,
                                    warnings));
}

// The toy kiln / kiln-render pair (the unchanged tools/ mains, with the toy path linked into
// kiln-render) strips a pack to the toy path's lookups and verifies it; the stripped pack renders
// along the toy path and not along the forward path, whose light variants it left out. The
// installed kiln, without the toy path, refuses the name with the ones it has.
TEST(ToyPathCli, CompileSceneStripsToTheToyPathAndVerifies) {
    const std::string data = std::string(KILN_TEST_DATA_DIR) + "/strip/data/";
    const std::string dir = FreshTempDir("kiln_toy_path");
    const std::string pack = dir + "/toy.kpack";
    const std::string compile = "compile " + data + "StripLight.shader -I " + KILN_SOURCE_DIR +
                                "/materials -o " + pack + " --no-cache --scene " + data +
                                "lamps.gltf --verify-scene --explain --path ";
    const RunResult r = RunProgram(KILN_TOY_KILN, compile + "toy");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("toy path, unlit"), std::string::npos) << r.out;  // who asked
    {
        pack::MappedFile file;
        pack::Pack pk;
        ASSERT_TRUE(MapInto(pack, file));
        ASSERT_TRUE(OpenInto(file.bytes(), pk));
        std::map<std::string, std::vector<std::string>> kept;
        for (uint32_t p = 0; p < pk.Count(pack::SectionTag::kPasses); ++p) {
            const pack::PassRec rec = pk.Pass(p).value();
            auto& list = kept[pack::PassLabel(pk, p)];
            for (uint32_t v = rec.first_variant; v < rec.first_variant + rec.variant_count; ++v) {
                list.push_back(pack::JoinKeywords(
                    pk.KeywordsOf(p, pack::VariantKey(pk.Variant(v).value().key))));
            }
        }
        EXPECT_EQ(kept.at("FORWARD"), std::vector<std::string>{"(no keywords)"});
        EXPECT_TRUE(kept.at("FORWARD_DELTA").empty());
        EXPECT_TRUE(kept.at("DEFERRED").empty());
    }
    const std::string render = "render " + data + "lamps.gltf --pack " + pack +
                               " --width 48 --height 32 --validation -o " + dir +
                               "/toy.png --path ";
    const RunResult toy = RunProgram(KILN_TOY_KILN, render + "toy");
    EXPECT_EQ(toy.exit_code, 0) << toy.err;
    EXPECT_NE(toy.out.find("unlit draws"), std::string::npos) << toy.out;
    EXPECT_TRUE(std::filesystem::exists(dir + "/toy.png"));

    const RunResult forward = RunProgram(KILN_TOY_KILN, render + "forward");
    EXPECT_EQ(forward.exit_code, 1) << forward.err;
    EXPECT_NE(forward.err.find("[K0006]"), std::string::npos) << forward.err;

    const RunResult installed = RunKiln(compile + "toy");
    EXPECT_NE(installed.exit_code, 0);
    EXPECT_NE(installed.err.find("unknown render path 'toy' (there are forward, deferred)"),
              std::string::npos)
        << installed.err;
}

}  // namespace
}  // namespace kiln::test
