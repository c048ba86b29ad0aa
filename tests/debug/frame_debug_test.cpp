// The frame debugger as a person uses it: `kiln render --frame-debug DIR` on the demo scene, on
// both paths, writes a page that headless Chromium (Debian's chromium, installed by
// scripts/setup.sh) opens. The page lists every pass of the frame with its steps, every step's
// images load in the browser and are shown at their target's aspect ratio, steps are numbered
// one way (from 1: list, heading, counter, #step-N links, frame.json), a #step-N link opens that
// step, labels name material files relative to the scene, and the records say what each step
// drew.
#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

// The DOM of `page` after its load event, as headless Chromium serializes it; empty when Chromium
// is missing or fails. The window is narrow (headless Chromium's narrowest, 500 pixels), so the
// 320-pixel targets are shown smaller than their size, which is where an image could lose its
// aspect ratio.
// `budget_ms`: virtual time the page's asynchronous work (the texel readout's scripts and
// inflation) may take before the DOM is dumped.
std::string DumpDom(const std::string& page, const std::string& fragment = "", int budget_ms = 0) {
    const std::string command =
        "chromium --headless --no-sandbox --disable-gpu --window-size=400,800 " +
        (budget_ms > 0 ? "--virtual-time-budget=" + std::to_string(budget_ms) + " " : "") +
        "--dump-dom 'file://" + fs::absolute(page).string() + fragment + "' 2>/dev/null";
    std::string out;
    if (FILE* p = popen(command.c_str(), "r")) {
        char buffer[4096];
        size_t n;
        while ((n = fread(buffer, 1, sizeof buffer, p)) > 0) {
            out.append(buffer, n);
        }
        if (pclose(p) != 0) {
            out.clear();
        }
    }
    return out;
}

bool HaveChromium() {
    return std::system("command -v chromium >/dev/null 2>&1") == 0;
}

long Attribute(const std::string& dom, const std::string& name) {
    std::smatch m;
    if (std::regex_search(dom, m, std::regex(name + "=\"([0-9]+)\""))) {
        return std::stol(m[1]);
    }
    return -1;
}

struct Path {
    const char* name;
    std::vector<std::string> passes;  // the frame's passes, in order
};

class FrameDebugTest : public ::testing::TestWithParam<Path> {};

TEST_P(FrameDebugTest, ThePageListsEveryPassWithItsImagesInHeadlessChromium) {
    ASSERT_TRUE(HaveChromium())
        << "chromium is not installed (scripts/setup.sh installs Debian's chromium package)";
    const Path& path = GetParam();
    ScratchDir dir;
    const std::string out = dir.path() + "/debug";
    // The demo's materials, its textured sphere with an image file (a 3x2 PNG) for its albedo.
    fs::copy_file(DataPath("fuzz/corpus/image/png_3x2.png"), dir.path() + "/albedo.png");
    const std::string textured = dir.Write(
        "textured.material",
        R"({"kiln_material": 1, "shader": "Kiln/BlinnPhongTextured", "properties": {"_MainTex": "albedo.png"}})");
    nlohmann::json sidecar =
        nlohmann::json::parse(ReadFile(DataPath("../scenes/demo/demo.kiln.json")));
    for (auto& [name, file] : sidecar["materials"].items()) {
        file = name == "BlinnPhongTextured"
                   ? textured
                   : fs::absolute(DataPath("../scenes/demo/" + file.get<std::string>()))
                         .lexically_normal()
                         .string();
    }
    const std::string materials = dir.Write("demo.kiln.json", sidecar.dump());
    const RunResult r =
        RunKiln("render " + DataPath("../scenes/demo/demo.gltf") + " --materials " + materials +
                " --width 320 --height 180 --validation --path " + path.name + " -o " + dir.path() +
                "/frame.png --frame-debug " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find(out + "/index.html: "), std::string::npos) << r.out;

    // The records: every pass in order, each step's images on disk.
    const nlohmann::json frame = nlohmann::json::parse(ReadFile(out + "/frame.json"));
    std::vector<std::string> passes;
    size_t images = 0;
    bool additive = false, light_pass = false;
    size_t thumbnails = 0;
    for (const auto& step : frame["steps"]) {
        const std::string pass = step["pass"];
        if (passes.empty() || passes.back() != pass) {
            passes.push_back(pass);
        }
        EXPECT_FALSE(step["images"].empty()) << step.dump();
        for (const auto& image : step["images"]) {
            EXPECT_TRUE(fs::is_regular_file(out + "/" + image["file"].get<std::string>()))
                << image.dump();
            ++images;
        }
        if (step["draw"].get<int>() >= 0) {
            EXPECT_FALSE(step["shader"].get<std::string>().empty()) << step.dump();
            EXPECT_FALSE(step["state"].get<std::string>().empty()) << step.dump();
            EXPECT_TRUE(step["gpu_ms"].is_number()) << "lavapipe has timestamps: " << step.dump();
            // What the draw drew with: its mesh and counts, its uniform values by name.
            EXPECT_FALSE(step["mesh"].get<std::string>().empty()) << step.dump();
            EXPECT_GT(step["vertices"].get<int>(), 0) << step.dump();
            EXPECT_EQ(step["indices"].get<int>() % 3, 0) << step.dump();
            EXPECT_FALSE(step["values"].empty()) << step.dump();
            for (const auto& t : step["textures"]) {
                EXPECT_GT(t["width"].get<int>(), 0) << t.dump();
                EXPECT_FALSE(t["source"].get<std::string>().empty()) << t.dump();
                if (t["thumbnail"].is_string()) {
                    EXPECT_TRUE(fs::is_regular_file(out + "/" + t["thumbnail"].get<std::string>()))
                        << t.dump();
                    ++images;
                    ++thumbnails;
                }
            }
            if (step["object"].get<std::string>().find("Lambert.material") == 0) {
                // The material's colour as bound, and the sphere's mesh.
                EXPECT_TRUE(step["values"].contains("_Color")) << step.dump();
            }
            if (step["shader"] == "Hidden/Internal-DeferredShading") {
                EXPECT_EQ(step["mesh"], "the full-screen triangle");
                EXPECT_EQ(step["indices"], 3);
            }
        }
        additive |= step["light_mode"] == "ForwardAdd" &&
                    step["light"].get<std::string>().find("point light") == 0;
        light_pass |= step["shader"] == "Hidden/Internal-DeferredShading";
    }
    EXPECT_EQ(passes, path.passes);
    // The textured sphere binds an image file: its thumbnail is kept.
    EXPECT_GT(thumbnails, 0u);
    EXPECT_TRUE(additive) << "no additive pass of a point light recorded";
    EXPECT_EQ(light_pass, std::string(path.name) == "deferred");

    // The page in the browser: every pass listed with every step's images, all of them loaded.
    const std::string dom = DumpDom(out + "/index.html");
    ASSERT_FALSE(dom.empty()) << "headless chromium produced no DOM for " << out << "/index.html";
    EXPECT_EQ(Attribute(dom, "data-images"), long(images));
    EXPECT_EQ(Attribute(dom, "data-images-loaded"), long(images))
        << "images that did not load in the browser";
    for (const std::string& pass : path.passes) {
        EXPECT_NE(dom.find("data-pass=\"" + pass + "\"><h2>Pass " + pass + "</h2>"),
                  std::string::npos)
            << "pass " << pass << " not listed";
    }
    EXPECT_EQ(Attribute(dom, "data-images-in-proportion"), long(images))
        << "images shown at another aspect ratio than their target's: "
        << dom.substr(dom.find("data-images-out-of-proportion"), 300);
    // Without a link the page opens on the last step.
    EXPECT_EQ(Attribute(dom, "data-current"), long(frame["steps"].size()));
    // One numbering: frame.json's steps count from 1, as the page's ids and counter do.
    EXPECT_EQ(frame["steps"][0]["step"].get<int>(), 1);
    EXPECT_NE(dom.find("step " + std::to_string(frame["steps"].size()) + " of " +
                       std::to_string(frame["steps"].size())),
              std::string::npos);
    // Material files are named relative to the scene's folder, never by an absolute path.
    EXPECT_NE(dom.find("../../materials/Lambert.material on node 'Lambert'"), std::string::npos);
    EXPECT_EQ(dom.find(DataPath("../materials")), std::string::npos);
    size_t n = 1;
    for (const auto& step : frame["steps"]) {
        EXPECT_EQ(step["step"].get<size_t>(), n);
        EXPECT_EQ(step["object"].get<std::string>().find('/') == 0, false) << step.dump();
        const std::string id = "id=\"step-" + std::to_string(n++) + "\"";
        const size_t section = dom.find(id);
        ASSERT_NE(section, std::string::npos) << id;
        const size_t end = dom.find("</section>", section);
        for (const auto& image : step["images"]) {
            const size_t img =
                dom.find("src=\"" + image["file"].get<std::string>() + "\"", section);
            EXPECT_LT(img, end) << image["file"] << " is not shown in " << id;
        }
        for (const auto& t : step.value("textures", nlohmann::json::array())) {
            const size_t row =
                dom.find("<tr><td>" + t["name"].get<std::string>() + "</td>", section);
            EXPECT_LT(row, end) << t.dump() << " is not listed in " << id;
        }
        if (step["draw"].get<int>() >= 0) {
            EXPECT_LT(
                dom.find("Uniform values (" + std::to_string(step["values"].size()) + ")", section),
                end)
                << id;
        }
    }
}

// A #step-N link opens step N (the section shown, the others hidden, the list's link current).
TEST(FrameDebug, AStepLinkOpensThatStep) {
    ASSERT_TRUE(HaveChromium())
        << "chromium is not installed (scripts/setup.sh installs Debian's chromium package)";
    ScratchDir dir;
    const std::string out = dir.path() + "/debug";
    const RunResult r =
        RunKiln("render " + DataPath("../scenes/demo/demo.gltf") + " --width 96 --height 54 -o " +
                dir.path() + "/frame.png --frame-debug " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string dom = DumpDom(out + "/index.html", "#step-3");
    ASSERT_FALSE(dom.empty());
    EXPECT_EQ(Attribute(dom, "data-current"), 3);
    EXPECT_NE(dom.find("<section class=\"step\" id=\"step-3\""), std::string::npos) << dom;
    EXPECT_NE(dom.find("<section class=\"step hidden\" id=\"step-2\""), std::string::npos);
    EXPECT_NE(dom.find("class=\"current\"><span class=\"n\">3</span>"), std::string::npos);
    EXPECT_NE(dom.find("step 3 of "), std::string::npos);
    // The zoom (?zoom=2, or the page's select): every target's image at twice its size.
    const std::string zoomed = DumpDom(out + "/index.html", "?zoom=2#step-3");
    EXPECT_EQ(Attribute(zoomed, "data-zoom"), 2);
    EXPECT_GT(Attribute(zoomed, "data-zoomed-ok"), 0);
    EXPECT_EQ(Attribute(zoomed, "data-zoomed-ok"), Attribute(zoomed, "data-images"));
    // A link past the last step is ignored: the page opens on the last step.
    EXPECT_GT(Attribute(DumpDom(out + "/index.html", "#step-100000"), "data-current"), 3);
}

// The readout of what the target under the cursor holds at a texel (?probe=X,Y reads it for the
// current step's images as a hover does): on the demo's last step, the colour target's linear
// RGBA where the scene is (alpha 1: covered) and the bytes shown, which are the PNG's; the depth
// there below 1; at the top-left corner, sky, the colour's alpha 0 and the depth cleared.
TEST(FrameDebug, TheReadoutShowsATexelsLinearAndShownValues) {
    ASSERT_TRUE(HaveChromium())
        << "chromium is not installed (scripts/setup.sh installs Debian's chromium package)";
    ScratchDir dir;
    const std::string out = dir.path() + "/debug";
    const RunResult r =
        RunKiln("render " + DataPath("../scenes/demo/demo.gltf") + " --width 96 --height 54 -o " +
                dir.path() + "/frame.png --frame-debug " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // "texel X, Y of TARGET after step N: linear R G B A; shown r g b" / "...: depth D; shown".
    const std::regex readout(
        "<img class=\"target\" src=\"([^\"]+)\"[^>]*alt=\"([a-z]+) after "
        "step [0-9]+\"[^>]*data-readout=\"texel ([0-9]+), ([0-9]+) of [^:]+: "
        "([^;]+); shown ([0-9]+) ([0-9]+) ([0-9]+)\"");
    struct Probe {
        std::string png, linear;
        int shown[3];
    };
    auto probe = [&](int x, int y) {
        const std::string dom = DumpDom(
            out + "/index.html", "?probe=" + std::to_string(x) + "," + std::to_string(y), 10000);
        EXPECT_EQ(Attribute(dom, "data-probed"), 2) << dom.substr(0, 2000);  // colour, depth
        std::map<std::string, Probe> by_target;
        for (auto it = std::sregex_iterator(dom.begin(), dom.end(), readout);
             it != std::sregex_iterator(); ++it) {
            const std::smatch& m = *it;
            EXPECT_EQ(std::stoi(m[3]), x);
            EXPECT_EQ(std::stoi(m[4]), y);
            by_target[m[2]] = {m[1], m[5], {std::stoi(m[6]), std::stoi(m[7]), std::stoi(m[8])}};
        }
        return by_target;
    };
    // The bytes shown are the image's.
    auto png_bytes = [&](const std::string& png, int x, int y, int* rgb) {
        int w = 0, h = 0, n = 0;
        unsigned char* p = stbi_load((out + "/" + png).c_str(), &w, &h, &n, 3);
        ASSERT_NE(p, nullptr) << png;
        for (int c = 0; c < 3; ++c)
            rgb[c] = p[(y * w + x) * 3 + c];
        stbi_image_free(p);
    };
    std::map<std::string, Probe> centre = probe(48, 30);
    ASSERT_EQ(centre.count("color"), 1u);
    ASSERT_EQ(centre.count("depth"), 1u);
    std::istringstream linear(centre["color"].linear.substr(centre["color"].linear.find(' ')));
    float rgba[4] = {-1, -1, -1, -1};
    linear >> rgba[0] >> rgba[1] >> rgba[2] >> rgba[3];
    EXPECT_EQ(centre["color"].linear.rfind("linear ", 0), 0u) << centre["color"].linear;
    EXPECT_GT(rgba[0] + rgba[1] + rgba[2], 0.0f);
    EXPECT_EQ(rgba[3], 1.0f);  // covered
    int rgb[3];
    png_bytes(centre["color"].png, 48, 30, rgb);
    EXPECT_EQ(std::vector<int>(rgb, rgb + 3),
              std::vector<int>(centre["color"].shown, centre["color"].shown + 3));
    const std::string depth = centre["depth"].linear;
    ASSERT_EQ(depth.rfind("depth ", 0), 0u) << depth;
    EXPECT_LT(std::stof(depth.substr(6)), 1.0f);
    std::map<std::string, Probe> corner = probe(0, 0);
    EXPECT_EQ(corner["depth"].linear, "depth 1 (cleared)");
    EXPECT_NE(corner["color"].linear.find(" 0"), std::string::npos);
    EXPECT_EQ(corner["color"].linear.substr(corner["color"].linear.rfind(' ')), " 0");  // alpha
}

// The captured frame is the frame rendered: with --shadows soft --msaa 4 the shadow passes (each
// map at its own size, a point light's cube face by face) and the collector appear as steps, the
// forward pass shows its colour resolved, and the final image is the one drawn without
// --frame-debug (32-bit float EXR files compared byte for byte), with 0 validation messages.
TEST(FrameDebug, ShadowPassesAndTheMsaaResolveAreSteps) {
    ScratchDir dir;
    const std::string out = dir.path() + "/debug";
    const std::string render = "render " + DataPath("../scenes/demo/demo.gltf") +
                               " --width 96 --height 54 --shadows soft --shadow-resolution 64 "
                               "--msaa 4 --validation -o " +
                               dir.path() + "/frame.png --exr ";
    const RunResult r = RunKiln(render + dir.path() + "/captured.exr --frame-debug " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("MSAA is off"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("shadows are off"), std::string::npos) << r.err;
    const RunResult plain = RunKiln(render + dir.path() + "/plain.exr");
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(ReadFile(dir.path() + "/captured.exr"), ReadFile(dir.path() + "/plain.exr"));

    const nlohmann::json frame = nlohmann::json::parse(ReadFile(out + "/frame.json"));
    std::vector<std::string> passes;
    std::set<std::string> faces;
    for (const auto& step : frame["steps"]) {
        if (passes.empty() || passes.back() != step["pass"]) {
            passes.push_back(step["pass"]);
        }
        for (const auto& image : step["images"]) {
            const std::string target = image["target"];
            if (target.find("shadow map: directional") == 0 ||
                target.find("shadow map: spot") == 0) {
                EXPECT_EQ(image["file"].get<std::string>().empty(), false);
            }
            if (target.find("shadow map: point light 'Blue point' (face ") == 0) {
                faces.insert(target);
            }
        }
    }
    const std::vector<std::string> expected = {"shadows: directional light 'Sun'",
                                               "camera depth",
                                               "screen-space shadows: directional light 'Sun'",
                                               "shadows: spot light 'Pink spot'",
                                               "shadows: point light 'Blue point' +X",
                                               "shadows: point light 'Blue point' -X",
                                               "shadows: point light 'Blue point' +Y",
                                               "shadows: point light 'Blue point' -Y",
                                               "shadows: point light 'Blue point' +Z",
                                               "shadows: point light 'Blue point' -Z",
                                               "forward"};
    EXPECT_EQ(passes, expected);
    EXPECT_EQ(faces.size(), 6u);  // each face read back after the pass that drew it
    // A map at its own size (64; a cube face half that), the forward pass's colour resolved.
    for (const auto& step : frame["steps"]) {
        for (const auto& image : step["images"]) {
            const std::string file = out + "/" + image["file"].get<std::string>();
            const std::string png = ReadFile(file);
            ASSERT_GE(png.size(), 24u) << file;
            const uint32_t width = uint32_t(uint8_t(png[16])) << 24 |
                                   uint32_t(uint8_t(png[17])) << 16 |
                                   uint32_t(uint8_t(png[18])) << 8 | uint32_t(uint8_t(png[19]));
            const std::string target = image["target"];
            const uint32_t want = target.find("shadow map: point") == 0 ? 32u
                                  : target.find("shadow map:") == 0     ? 64u
                                                                        : 96u;
            EXPECT_EQ(width, want) << target;
        }
    }
    const auto& last = frame["steps"].back()["images"];
    ASSERT_EQ(last.size(), 1u);  // the multisampled attachments are shown through the resolve
    EXPECT_EQ(last[0]["target"], "color (resolved)");
}

INSTANTIATE_TEST_SUITE_P(Paths,
                         FrameDebugTest,
                         ::testing::Values(Path{"forward", {"forward"}},
                                           Path{"deferred", {"gbuffer", "lighting", "forward"}}),
                         [](const auto& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace kiln::test
