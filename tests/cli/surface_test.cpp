// Surface shaders (`#pragma surface`) end to end: the passes Kiln generates compile, draw as their
// hand-written equivalent on both render paths, light as a custom lighting function says, cast
// and receive shadows, pass `kiln test`, and report mistakes at the user's lines (or, in
// generated code, with a note naming the pass). Renders run on lavapipe with the validation layer
// on; images are compared pixel by pixel as 8-bit sRGB.
#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <filesystem>
#include <functional>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

const char* const kDemoMaterials[] = {"Unlit",
                                      "Lambert",
                                      "LambertAmbient",
                                      "BlinnPhong",
                                      "BlinnPhongTextured",
                                      "EnergyConserving",
                                      "Standard",
                                      "StandardMetallic",
                                      "MultiLight",
                                      "Deferred",
                                      "Floor"};

struct Image {
    int w = 0, h = 0;
    std::vector<unsigned char> rgb;
    const unsigned char* At(int i) const { return &rgb[size_t(i) * 3]; }
};

Image Load(const std::string& png) {
    Image img;
    int n = 0;
    unsigned char* p = stbi_load(png.c_str(), &img.w, &img.h, &n, 3);
    if (p) {
        img.rgb.assign(p, p + size_t(img.w) * img.h * 3);
        stbi_image_free(p);
    }
    return img;
}

// The demo scene (tests/../scenes/demo: ten spheres on a floor, a sun, a point and a spot light)
// with every glTF material drawn by `shader` (or by the one `pick` names for a material).
std::string DemoSidecar(const std::string& dir,
                        const std::function<std::string(const std::string&)>& pick) {
    std::set<std::string> written;
    std::string sidecar = R"({"kiln_materials": 1, "ambient": [0.05, 0.055, 0.07], "materials": {)";
    bool first = true;
    for (const char* m : kDemoMaterials) {
        const std::string shader = pick(m);
        std::string file = shader;
        for (char& c : file)
            c = c == '/' || c == ' ' ? '_' : c;
        file = dir + "/" + file + ".material";
        if (written.insert(file).second) {
            WriteFile(file, R"({"kiln_material": 1, "shader": ")" + shader +
                                R"(", "properties": {"_Color": [0.8, 0.8, 0.8, 1]}})");
        }
        sidecar += std::string(first ? "" : ", ") + "\"" + m + "\": \"" + file + "\"";
        first = false;
    }
    WriteFile(dir + "/demo.kiln.json", sidecar + "}}");
    return dir + "/demo.kiln.json";
}

std::string Demo() {
    return DataPath("../scenes/demo/demo.gltf");
}

// Renders the demo scene with the sidecar; expects success and no validation message.
void Render(const std::string& packs,
            const std::string& sidecar,
            const std::string& png,
            const std::string& options) {
    const RunResult r =
        RunKiln("render " + Demo() + " --pack " + packs + " --materials " + sidecar +
                " --validation --width 192 --height 108 -o " + png + " " + options);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("validation messages: 0"), std::string::npos) << r.out;
}

// A Lambert surface shader and the same lighting written by hand: on the forward path the
// generated FORWARD/FORWARD_DELTA passes compute exactly what the hand-written ones do, so the
// images must be identical (tolerance 0: same functions, same interpolators, same order of
// operations). On the deferred path the surface shader goes through the G-buffer and Kiln's
// deferred lighting (Unity's Internal-DeferredShading: its BRDF at smoothness 0 and black
// specular, whose diffuse term is Lambert's) while the hand-written one, without a Deferred pass,
// is drawn forward after it: at most 2 of 255 per channel apart (the G-buffer's 8-bit albedo and
// 10-bit normal).
TEST(Surface, ALambertSurfaceShaderRendersAsItsHandWrittenEquivalentOnBothPaths) {
    const std::string dir = FreshTempDir("surface_lambert");
    const std::string pack = dir + "/l.kpack";
    RunResult r = RunKiln("compile " + DataPath("data/surface/lambert.shader") + " " +
                          DataPath("data/surface/hand_lambert.shader") + " -o " + pack);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = RunKiln("info " + pack);
    for (const char* pass :
         {"\"FORWARD\" (LightMode ForwardBase)", "\"FORWARD_DELTA\" (LightMode ForwardAdd)",
          "\"DEFERRED\" (LightMode Deferred)", "\"Meta\" (LightMode Meta)"})
        EXPECT_NE(r.out.find(pass), std::string::npos) << pass << "\n" << r.out;
    EXPECT_EQ(r.out.find("ShadowCaster"), std::string::npos) << "no addshadow, no vertex:";
    const std::string packs = pack + " " + KILN_MATERIALS_PACK;
    for (const std::string path : {"forward", "deferred"}) {
        const std::string surface_png = dir + "/surface-" + path + ".png";
        const std::string hand_png = dir + "/hand-" + path + ".png";
        Render(packs, DemoSidecar(dir, [](const std::string&) { return "Test/SurfaceLambert"; }),
               surface_png, "--path " + path);
        Render(packs, DemoSidecar(dir, [](const std::string&) { return "Test/HandLambert"; }),
               hand_png, "--path " + path);
        const Image a = Load(surface_png), b = Load(hand_png);
        ASSERT_EQ(a.rgb.size(), b.rgb.size());
        ASSERT_FALSE(a.rgb.empty());
        int worst = 0;
        size_t lit = 0;
        for (size_t i = 0; i < a.rgb.size(); ++i) {
            worst = std::max(worst, std::abs(int(a.rgb[i]) - int(b.rgb[i])));
            lit += a.rgb[i] > 40;
        }
        EXPECT_LE(worst, path == "forward" ? 0 : 2) << path;
        EXPECT_GT(lit, a.rgb.size() / 4) << path << ": the scene is lit";
    }
}

// A custom `Lighting<Name>` function with view direction and a _GI function: every pixel drawn is
// the pure red or pure blue the function returns (no ambient, additive light or fog is added), and
// both bands appear on the spheres and the floor lit by the sun.
TEST(Surface, ACustomToonRampLightsAsItsFunctionSays) {
    const std::string dir = FreshTempDir("surface_toon");
    const std::string pack = dir + "/t.kpack";
    RunResult r = RunKiln("compile " + DataPath("data/surface/toon.shader") + " -o " + pack);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string png = dir + "/toon.png";
    Render(pack, DemoSidecar(dir, [](const std::string&) { return "Test/SurfaceToon"; }), png, "");
    const Image img = Load(png);
    ASSERT_FALSE(img.rgb.empty());
    size_t red = 0, blue = 0, other = 0;
    const unsigned char* background = img.At(0);  // the top-left corner shows no object
    for (int i = 0; i < img.w * img.h; ++i) {
        const unsigned char* p = img.At(i);
        if (p[0] == 255 && p[1] == 0 && p[2] == 0)
            ++red;
        else if (p[0] == 0 && p[1] == 0 && p[2] == 255)
            ++blue;
        else if (!std::equal(p, p + 3, background))
            ++other;
    }
    EXPECT_GT(red, 1000u);
    EXPECT_GT(blue, 300u);
    EXPECT_EQ(other, 0u) << "pixels neither band nor background";
}

// Mistakes: an error in the shader's own code is reported at its line of the .shader; one in
// generated code names the generated file with a note on the pass and the directive; a missing
// surface function and a misspelled option name what is wrong. --emit-generated writes the
// generated shader, which compiles on its own.
TEST(Surface, MistakesAreReportedWhereTheyAreAndTheGeneratedCodeCanBeRead) {
    const std::string dir = FreshTempDir("surface_mistakes");
    const std::string head =
        "Shader \"Test/M\" {\n"                                  // 1
        "  Properties { _Cutoff (\"C\", Range(0, 1)) = 0.5 }\n"  // 2
        "  SubShader {\n"                                        // 3
        "    CGPROGRAM\n";                                       // 4
    const std::string input = "    struct Input { float2 uv_MainTex; };\n";
    const std::string tail = "    ENDCG\n  }\n}\n";
    // Line 7: a user error inside surf.
    WriteFile(dir + "/user.shader", head + "    #pragma surface surf Lambert\n" + input +
                                        "    void surf(Input IN, inout SurfaceOutput o) {\n"
                                        "        o.Albedo = undefined_name;\n    }\n" +
                                        tail);
    RunResult r = RunKiln("compile " + dir + "/user.shader -o " + dir + "/u.kpack");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("user.shader:8:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("undefined_name"), std::string::npos) << r.err;
    // The cutoff is a texture: the generated clip() fails, in generated code.
    WriteFile(
        dir + "/gen.shader",
        head + "    #pragma surface surf Lambert alphatest:_Cutoff\n    sampler2D _Cutoff;\n" +
            input + "    void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 1; }\n" + tail);
    r = RunKiln("compile " + dir + "/gen.shader -o " + dir + "/g.kpack --emit-generated " + dir +
                "/generated");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("gen.shader (generated):"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("gen.shader:5:5: note: in the code generated for pass FORWARD of this "
                         "surface shader"),
              std::string::npos)
        << r.err;
    const std::string generated = ReadFile(dir + "/generated/gen.generated.shader");
    EXPECT_NE(generated.find("Name \"FORWARD_DELTA\""), std::string::npos) << generated;
    EXPECT_NE(generated.find("clip(o.Alpha - _Cutoff);"), std::string::npos) << generated;
    // A correct shader's generated file compiles on its own.
    r = RunKiln("compile " + DataPath("data/surface/lambert.shader") + " -o " + dir +
                "/l.kpack --emit-generated " + dir + "/generated");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = RunKiln("compile " + dir + "/generated/lambert.generated.shader -o " + dir + "/l2.kpack");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // No surface function; a misspelled option.
    WriteFile(dir + "/nosurf.shader", head + "    #pragma surface surff Lambert\n" + input +
                                          "    void surf(Input IN, inout SurfaceOutput o) {}\n" +
                                          tail);
    r = RunKiln("compile " + dir + "/nosurf.shader -o " + dir + "/n.kpack");
    EXPECT_NE(r.err.find("nosurf.shader:5:5: error: cannot generate the passes of this surface "
                         "shader: surface function 'surff' is not defined [K3008]"),
              std::string::npos)
        << r.err;
    WriteFile(dir + "/typo.shader",
              head + "    #pragma surface surf Lambert fullforwardshadow\n" + input +
                  "    void surf(Input IN, inout SurfaceOutput o) {}\n" + tail);
    r = RunKiln("compile " + dir + "/typo.shader -o " + dir + "/t.kpack");
    EXPECT_NE(r.err.find("fullforwardshadows"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("[K4016]"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/t.kpack"));
}

const char* const kUnityCorpus = KILN_SHARED_DIR "/unity-builtin-2022.3/Shaders";

// Unity's Legacy Diffuse, Bumped Diffuse and Bumped Specular (surface shaders without addshadow:
// they cast shadows through their Fallback's ShadowCaster, Legacy Shaders/VertexLit, found beside
// them) and a Standard surface shader with addshadow and a vertex: function, compiled against
// Kiln's layer and against Unity's CGIncludes, draw the demo scene and the OrientationTest sample
// with hard shadows and no validation message. The spheres' shadows darken the floor (drawn by
// Legacy Diffuse, which receives them): more than 150 floor pixels are at least 20 of 255 darker
// than without shadows (223 with Unity's CGIncludes, 316 with Kiln's layer at 192x108: the sun's
// shadows; the floor's ForwardAdd has no shadows without fullforwardshadows, as in Unity).
TEST(Surface, UnitysLegacySurfaceShadersAndAStandardOneRenderWithShadows) {
    const std::string extra = std::string(kUnityCorpus) + "/DefaultResourcesExtra";
    if (!fs::is_directory(extra))
        GTEST_SKIP() << extra << " is absent (../shared not checked out)";
    const std::string dir = FreshTempDir("surface_legacy");
    for (const std::string mode : {"kiln", "unity"}) {
        const std::string pack = dir + "/" + mode + ".kpack";
        RunResult r =
            RunKiln("compile '" + extra + "/Normal-Diffuse.shader' '" + extra +
                    "/Normal-Bumped.shader' '" + extra + "/Normal-BumpSpec.shader' " +
                    DataPath("data/surface/standard.shader") + " -o " + pack +
                    (mode == "unity" ? " -I '" + std::string(kUnityCorpus) + "/CGIncludes'"
                                     : std::string()));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        r = RunKiln("info " + pack);
        // Diffuse casts through VertexLit's pass; the Standard one through its generated pass.
        size_t casters = 0;
        for (size_t at = r.out.find("(LightMode ShadowCaster)"); at != std::string::npos;
             at = r.out.find("(LightMode ShadowCaster)", at + 1))
            ++casters;
        EXPECT_EQ(casters, 4u) << r.out;
        const std::string shaders[] = {"Legacy Shaders/Diffuse", "Legacy Shaders/Bumped Diffuse",
                                       "Legacy Shaders/Bumped Specular", "Test/SurfaceStandard"};
        size_t next = 0;
        const std::string sidecar = DemoSidecar(dir, [&](const std::string& m) {
            return m == "Floor" ? shaders[0] : shaders[next++ % 4];
        });
        const std::string lit = dir + "/" + mode + "-off.png", shadowed = dir + "/" + mode + ".png";
        const std::string packs = pack + " " + KILN_MATERIALS_PACK;  // screen-space shadows
        Render(packs, sidecar, lit, "--shadows off");
        Render(packs, sidecar, shadowed, "--shadows hard");
        const Image a = Load(lit), b = Load(shadowed);
        ASSERT_EQ(a.rgb.size(), b.rgb.size());
        size_t darker = 0;
        for (int i = 0; i < a.w * a.h; ++i) {
            int d = 0;
            for (int c = 0; c < 3; ++c)
                d += int(a.At(i)[c]) - int(b.At(i)[c]);
            darker += d >= 60;
        }
        EXPECT_GT(darker, 150u) << mode << ": shadows on the floor";
        std::cout << mode << ": " << darker << " pixels darker with shadows\n";
        // A Khronos sample, its materials drawn by each shader in turn.
        const std::string sample = std::string(KILN_SHARED_DIR) +
                                   "/gltf-samples/OrientationTest/glTF/OrientationTest.gltf";
        std::string side = R"({"kiln_materials": 1, "materials": {)";
        const char* names[] = {"BaseMaterial", "MatX1", "MatX2", "MatY1",
                               "MatY2",        "MatZ1", "MatZ2"};
        for (size_t i = 0; i < 7; ++i) {
            std::string file = shaders[i % 4];
            for (char& c : file)
                c = c == '/' || c == ' ' ? '_' : c;
            side += std::string(i ? ", " : "") + "\"" + names[i] + "\": \"" + dir + "/" + file +
                    ".material\"";
        }
        WriteFile(dir + "/orientation.kiln.json", side + "}}");
        r = RunKiln("render " + sample + " --pack " + packs + " --materials " + dir +
                    "/orientation.kiln.json --validation --shadows hard --width 160 --height 120 "
                    "-o " +
                    dir + "/" + mode + "-orientation.png");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.out.find("validation messages: 0"), std::string::npos) << r.out;
    }
}

}  // namespace
}  // namespace kiln::test
