// Geometry and tessellation stages (#pragma geometry, hull, domain) end to end: compiled into the
// pack, drawn by `kiln test` and by `kiln render` on lavapipe with the validation layer on. Each
// shader colours its pixels with a value only its extra stage computes (barycentric weights, the
// domain location), so a render without that stage could not produce the colours checked.
#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

const fs::path kBox = fs::path(KILN_SHARED_DIR) / "gltf-samples" / "Box" / "glTF" / "Box.gltf";

// Distinct colours among the pixels that are not the background (the top-left pixel's colour).
size_t LitColours(const std::string& png_path) {
    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load(png_path.c_str(), &w, &h, &n, 3);
    if (!pixels)
        return 0;
    std::set<uint32_t> colours;
    for (int i = 0; i < w * h; ++i) {
        const unsigned char* p = pixels + 3 * i;
        if (p[0] == pixels[0] && p[1] == pixels[1] && p[2] == pixels[2])
            continue;
        colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
    }
    stbi_image_free(pixels);
    return colours.size();
}

// Renders the Box sample at 160x120 with `shader` on its material, the validation layer on;
// expects success and no validation message.
void RenderBox(const std::string& dir,
               const std::string& pack,
               const std::string& shader,
               const std::string& png,
               const std::string& options = "") {
    WriteFile(dir + "/m.material",
              R"({"kiln_material": 1, "shader": ")" + shader + R"(", "properties": {}})");
    WriteFile(dir + "/box.kiln.json",
              R"({"kiln_materials": 1, "materials": {"Red": ")" + dir + R"(/m.material"}})");
    const RunResult r =
        RunKiln("render " + kBox.string() + " --pack " + pack + " --materials " + dir +
                "/box.kiln.json --validation --width 160 --height 120 -o " + png + " " + options);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("validation messages: 0"), std::string::npos) << r.out;
}

class StagesTest : public ::testing::TestWithParam<const char*> {};

TEST_P(StagesTest, CompileIntoThePackAndDrawWithoutValidationMessages) {
    const std::string dir = FreshTempDir(std::string("stages_") + GetParam());
    const std::string shader = DataPath(std::string("data/stages/") + GetParam() + ".shader");
    const std::string pack = dir + "/out.kpack";
    RunResult r = RunKiln("compile " + shader + " -o " + pack);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");

    r = RunKiln("info --json " + pack);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const bool geometry = std::string(GetParam()) == "geometry";
    const std::vector<std::string> fields =
        geometry ? std::vector<std::string>{"\"geometry_module\""}
                 : std::vector<std::string>{"\"hull_module\"", "\"domain_module\""};
    for (const std::string& field : fields)
        EXPECT_NE(r.out.find(field), std::string::npos) << field << " in " << r.out;
    EXPECT_NE(r.out.find(geometry ? "\"stage\": \"geometry\"" : "\"stage\": \"domain\""),
              std::string::npos)
        << "each module's stage by name: " << r.out;

    // kiln extract and kiln show reach every stage of the variant, and name the stages it has
    // when asked for one it lacks.
    const std::string shader_name = geometry ? "Test/Geometry" : "Test/Tessellation";
    const std::string extra = geometry ? "geometry" : "domain";
    r = RunKiln("extract " + pack + " --shader " + shader_name + " --pass ForwardBase --stage " +
                extra + " -o " + dir + "/extra.spv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(ReadFile(dir + "/extra.spv").substr(0, 4), std::string("\x03\x02\x23\x07", 4));
    r = RunKiln("show " + pack + " --shader " + shader_name + " --pass ForwardBase --stage " +
                extra + " --spirv");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(
        r.out.find(geometry ? "OpEntryPoint Geometry" : "OpEntryPoint TessellationEvaluation"),
        std::string::npos);
    r = RunKiln("extract " + pack + " --shader " + shader_name + " --pass ForwardBase --stage " +
                (geometry ? "hull" : "geometry") + " -o " + dir + "/none.spv");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find(geometry ? "the variant has no hull stage (it has vertex, fragment, "
                                    "geometry) [K0006]"
                                  : "the variant has no geometry stage (it has vertex, fragment, "
                                    "hull, domain) [K0006]"),
              std::string::npos)
        << r.err;

    // kiln test draws every variant with the validation layer on; a message fails the variant.
    r = RunKiln("test " + pack + " --keep-failures " + dir + "/failures");
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE((r.out + r.err).find("0 failures"), std::string::npos) << r.out << r.err;

    if (!fs::exists(kBox))
        GTEST_SKIP() << kBox << " is absent (../shared not checked out): render skipped";
    const std::string png = dir + "/box.png";
    RenderBox(dir, pack, geometry ? "Test/Geometry" : "Test/Tessellation", png);
    // Three visible faces of one flat colour each would be three colours; interpolated weights
    // give thousands (measured on lavapipe at 160x120: geometry 1,982, tessellation 5,883).
    EXPECT_GT(LitColours(png), 200u);
}

INSTANTIATE_TEST_SUITE_P(Stages, StagesTest, ::testing::Values("geometry", "tessellation"));

TEST(Stages, AHullWithoutADomainIsAnErrorNamingTheMissingPragma) {
    const std::string dir = FreshTempDir("stages_hull");
    WriteFile(dir + "/h.shader", R"(Shader "T/H" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex v
    #pragma hull h
    #pragma fragment f
    float4 v(float4 p : POSITION) : SV_POSITION { return p; }
    float4 f() : SV_Target { return 1; }
    ENDCG
} } })");
    const RunResult r = RunKiln("compile " + dir + "/h.shader -o " + dir + "/h.kpack");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("h.shader:4:18: error: tessellation needs both stages: program has "
                         "'#pragma hull' but no '#pragma domain' [K4003]"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir + "/h.kpack"));
}

// Pixels of exactly colour (r, g, b).
size_t PixelsOf(const std::string& png_path, unsigned char r, unsigned char g, unsigned char b) {
    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load(png_path.c_str(), &w, &h, &n, 3);
    if (!pixels)
        return 0;
    size_t count = 0;
    for (int i = 0; i < w * h; ++i) {
        const unsigned char* p = pixels + 3 * i;
        count += p[0] == r && p[1] == g && p[2] == b;
    }
    stbi_image_free(pixels);
    return count;
}

// UsePass copies another shader's pass into the pack: here from a .shader beside the using one
// (not itself compiled); the copied pass draws (a green shell around the orange box).
TEST(Stages, UsePassCopiesTheNamedPassWhichDraws) {
    const std::string dir = FreshTempDir("stages_usepass");
    const std::string pack = dir + "/out.kpack";
    RunResult r =
        RunKiln("compile " + DataPath("data/usepass/uses_outline.shader") + " -o " + pack);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = RunKiln("info " + pack);
    EXPECT_NE(r.out.find("Shader \"Test/UsesOutline\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("pass \"Outline\" (LightMode Always)"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("Test/Outlined"), std::string::npos) << "only the using shader is packed";
    r = RunKiln("test " + pack + " --keep-failures " + dir + "/failures");
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    if (!fs::exists(kBox))
        GTEST_SKIP() << kBox << " is absent (../shared not checked out): render skipped";
    const std::string png = dir + "/box.png";
    RenderBox(dir, pack, "Test/UsesOutline", png);
    EXPECT_GT(PixelsOf(png, 0, 255, 0), 50u) << "the used pass's green shell";
    EXPECT_GT(PixelsOf(png, 255, 188, 0), 1000u) << "the own pass's orange (0.5 in sRGB)";
}

// GrabPass: the pack records it in its place (no variants), and the runtime copies the colour
// drawn so far into _GrabTexture between the passes around it. Test/GrabInvert draws the box red,
// grabs, then draws 1 - the grabbed colour: cyan where the copy holds the red, anything else where
// it is missing, stale or mirrored. On the forward path, with MSAA (the copy reads the resolved
// target) and on the deferred path (drawn after the G-buffer), 0 validation messages each.
TEST(Stages, GrabPassCopiesTheColourDrawnSoFarBeforeTheNextPass) {
    const std::string dir = FreshTempDir("stages_grabpass");
    const std::string pack = dir + "/out.kpack";
    RunResult r = RunKiln("compile " + DataPath("data/grabpass/invert.shader") + " -o " + pack);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    r = RunKiln("info " + pack);
    EXPECT_NE(r.out.find("  pass \"RED\": 1 variants\n"
                         "  pass \"#2\": GrabPass into _GrabTexture\n"
                         "  pass \"INVERT\": 1 variants\n"),
              std::string::npos)
        << r.out;
    r = RunKiln("test " + pack + " --keep-failures " + dir + "/failures");
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    if (!fs::exists(kBox))
        GTEST_SKIP() << kBox << " is absent (../shared not checked out): render skipped";
    for (const std::string options : {"", "--msaa 4", "--path deferred"}) {
        const std::string png = dir + "/box.png";
        RenderBox(dir, pack, "Test/GrabInvert", png, options);
        // Exact colours: the copy is sampled at texel centres (nearest and bilinear agree), and
        // both passes cover the same pixels (same vertex program, ZTest LEqual).
        EXPECT_GT(PixelsOf(png, 0, 255, 255), 1000u) << options << ": the inverted red";
        EXPECT_EQ(PixelsOf(png, 255, 0, 0), 0u) << options << ": red left uncovered";
        EXPECT_EQ(PixelsOf(png, 255, 255, 255), 0u) << options << ": inverted background";
    }
}

// A named GrabPass is copied once per frame, by the first object that has it; `GrabPass { }` is
// copied before every object (Unity's documented behaviour). Two boxes of the demo scene use each
// shader; the frame debugger records every copy as a step of its own.
TEST(Stages, ANamedGrabPassIsCopiedOncePerFrameAndAnUnnamedOnePerObject) {
    const std::string demo = DataPath("../scenes/demo/demo.gltf");
    const std::string dir = FreshTempDir("stages_grab_count");
    const std::string pack = dir + "/out.kpack";
    WriteFile(dir + "/red.shader", R"(Shader "Test/Red" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex v
    #pragma fragment f
    #include "UnityCG.cginc"
    float4 v(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
    float4 f() : SV_Target { return float4(1, 0, 0, 1); }
    ENDCG
} } })");
    RunResult r =
        RunKiln("compile " + DataPath("data/grabpass/named.shader") + " " +
                DataPath("data/grabpass/each.shader") + " " + dir + "/red.shader -o " + pack);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const auto& [shader, copies, step] :
         {std::tuple{"Test/GrabNamed", 1, "\"color -> grab _Behind\""},
          std::tuple{"Test/GrabEach", 2, "\"color -> grab _GrabTexture\""}}) {
        WriteFile(dir + "/grab.material", std::string(R"({"kiln_material": 1, "shader": ")") +
                                              shader + R"(", "properties": {}})");
        WriteFile(dir + "/opaque.material",
                  R"({"kiln_material": 1, "shader": "Test/Red", "properties": {}})");
        std::string sidecar = R"({"kiln_materials": 1, "materials": {)";
        for (const char* m : {"Unlit", "Lambert", "LambertAmbient", "BlinnPhong",
                              "BlinnPhongTextured", "EnergyConserving", "Standard",
                              "StandardMetallic", "MultiLight", "Deferred", "Floor"}) {
            const bool grab = std::string(m) == "Lambert" || std::string(m) == "Standard";
            sidecar += std::string(m == std::string("Unlit") ? "" : ", ") + "\"" + m + "\": \"" +
                       dir + (grab ? "/grab.material\"" : "/opaque.material\"");
        }
        WriteFile(dir + "/demo.kiln.json", sidecar + "}}");
        r = RunKiln("render " + demo + " --pack " + pack + " --materials " + dir +
                    "/demo.kiln.json --validation --width 96 --height 54 -o " + dir +
                    "/demo.png --frame-debug " + dir + "/debug");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.out.find("validation messages: 0"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find(std::to_string(copies) + " GrabPass cop"), std::string::npos)
            << shader << ": " << r.out;
        const std::string page = ReadFile(dir + "/debug/frame.json");
        size_t found = 0;
        for (size_t at = page.find(step); at != std::string::npos; at = page.find(step, at + 1))
            ++found;
        EXPECT_EQ(found, size_t(copies)) << shader;
    }
}

// A GrabPass tagged with a LightMode the forward path does not draw as a base pass is no step of
// the object's passes: no copy, and no variant looked up for it.
TEST(Stages, AGrabPassOutsideTheBasePassesIsNotCopied) {
    if (!fs::exists(kBox))
        GTEST_SKIP() << kBox << " is absent (../shared not checked out)";
    const std::string dir = FreshTempDir("stages_grab_tagged");
    WriteFile(dir + "/g.shader", R"(Shader "Test/GrabTagged" { SubShader {
    GrabPass { Tags { "LightMode" = "Deferred" } }
    Pass {
        CGPROGRAM
        #pragma vertex v
        #pragma fragment f
        #include "UnityCG.cginc"
        float4 v(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
        float4 f() : SV_Target { return float4(0, 0, 1, 1); }
        ENDCG
    }
} })");
    const RunResult r = RunKiln("compile " + dir + "/g.shader -o " + dir + "/g.kpack");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string png = dir + "/box.png";
    // On the deferred path the object, which has no Deferred pass to draw, is drawn forward.
    RenderBox(dir, dir + "/g.kpack", "Test/GrabTagged", png, "--path deferred");
    EXPECT_GT(PixelsOf(png, 0, 0, 255), 1000u);
}

TEST(Stages, AUsePassOfNoSuchPassNamesTheClosestOne) {
    const std::string dir = FreshTempDir("stages_usepass_typo");
    std::string text = ReadFile(DataPath("data/usepass/uses_outline.shader"));
    text.replace(text.find("OUTLINE"), 7, "OUTLNE");
    WriteFile(dir + "/typo.shader", text);
    const RunResult r =
        RunKiln("compile " + dir + "/typo.shader " + DataPath("data/usepass/outlined.shader") +
                " -o " + dir + "/out.kpack");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("error: UsePass names pass \"OUTLNE\" of shader \"Test/Outlined\", "
                         "which has no pass of that Name; did you mean 'Outline'? [K3015]"),
              std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace kiln::test
