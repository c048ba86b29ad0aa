// The Khronos conformance samples (../shared/gltf-samples), each rendered on lavapipe and checked
// in the region the sample is about, through a front orthographic camera whose pixel of every
// world point the test computes. Where the check is a colour count, the test also renders the
// scene with the feature taken away (the way a loader or renderer that drops it would draw it)
// and shows that the same check fails on that image.
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <filesystem>
#include <functional>

#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

std::string SamplePath(const std::string& name) {
    return std::string(KILN_SHARED_DIR) + "/gltf-samples/" + name + "/glTF/" + name + ".gltf";
}

#define LOAD_SAMPLE_OR_SKIP(name, scene, warnings)                                             \
    if (!fs::exists(SamplePath(name))) {                                                       \
        GTEST_SKIP() << SamplePath(name) << " is absent (../shared not checked out): skipped"; \
    }                                                                                          \
    ASSERT_TRUE(LoadInto(SamplePath(name), scene, warnings))

// An orthographic camera looking down -z at the scene's x-y extent (5% margin); pixels are
// square, the image `width` wide.
struct FrontView {
    glm::vec2 center{0.0f}, half{1.0f};
    uint32_t width = 0, height = 0;

    glm::vec2 Pixel(const glm::vec3& world) const {
        const glm::vec2 ndc = (glm::vec2(world) - center) / half;
        return {(ndc.x * 0.5f + 0.5f) * float(width), (0.5f - ndc.y * 0.5f) * float(height)};
    }
};

FrontView LookFromFront(runtime::Scene& scene, uint32_t width) {
    const auto [lo, hi] = runtime::SceneBounds(scene);
    FrontView v;
    v.center = glm::vec2(lo + hi) * 0.5f;
    v.half = glm::vec2(hi - lo) * 0.5f * 1.05f;
    v.width = width;
    v.height = std::max(1u, uint32_t(float(width) * v.half.y / v.half.x + 0.5f));
    runtime::Camera cam;
    cam.name = "front";
    cam.perspective = false;
    cam.xmag = v.half.x;
    cam.ymag = v.half.y;
    cam.znear = 0.01f;
    cam.zfar = (hi.z - lo.z) + 2.0f;
    cam.world = glm::translate(glm::mat4(1.0f), glm::vec3(v.center, hi.z + 1.0f));
    scene.cameras = {cam};
    return v;
}

struct Rect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) x [y0, y1)
    size_t Area() const { return size_t(std::max(0, x1 - x0)) * size_t(std::max(0, y1 - y0)); }
};

const runtime::Instance* ByMesh(const runtime::Scene& scene, const std::string& mesh) {
    for (const runtime::Instance& inst : scene.instances) {
        if (scene.meshes[inst.mesh].name == mesh) {
            return &inst;
        }
    }
    return nullptr;
}

const runtime::Instance* ByNode(const runtime::Scene& scene, const std::string& node) {
    for (const runtime::Instance& inst : scene.instances) {
        if (inst.node == node) {
            return &inst;
        }
    }
    return nullptr;
}

// The instance's world bounds on screen, shrunk by `inset` of its size on each side.
Rect ScreenRect(const runtime::Scene& scene,
                const runtime::Instance& inst,
                const FrontView& view,
                float inset = 0.1f) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const runtime::Primitive& p : scene.meshes[inst.mesh].primitives) {
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 local((corner & 1) ? p.bounds_max.x : p.bounds_min.x,
                                  (corner & 2) ? p.bounds_max.y : p.bounds_min.y,
                                  (corner & 4) ? p.bounds_max.z : p.bounds_min.z);
            const glm::vec2 px = view.Pixel(glm::vec3(inst.world * glm::vec4(local, 1)));
            lo = glm::min(lo, px);
            hi = glm::max(hi, px);
        }
    }
    const glm::vec2 pad = (hi - lo) * inset;
    return {int(lo.x + pad.x), int(lo.y + pad.y), int(hi.x - pad.x), int(hi.y - pad.y)};
}

using Predicate = std::function<bool(const glm::vec4&)>;

glm::vec4 At(const runtime::LinearImage& image, int x, int y) {
    return glm::make_vec4(&image.rgba[(size_t(y) * image.width + size_t(x)) * 4]);
}

size_t Count(const runtime::LinearImage& image, const Rect& r, const Predicate& is) {
    size_t n = 0;
    for (int y = std::max(0, r.y0); y < std::min(int(image.height), r.y1); ++y) {
        for (int x = std::max(0, r.x0); x < std::min(int(image.width), r.x1); ++x) {
            n += is(At(image, x, y)) ? 1 : 0;
        }
    }
    return n;
}

Rect Whole(const runtime::LinearImage& image) {
    return {0, 0, int(image.width), int(image.height)};
}

// Hue classes of lit linear colours: one channel well above the other two, or (a secondary
// colour: cyan, magenta, yellow) two well above the third.
bool Mostly(const glm::vec4& c, int channel) {
    const float v = c[channel], a = c[(channel + 1) % 3], b = c[(channel + 2) % 3];
    return v > 0.05f && a < 0.35f * v && b < 0.35f * v;
}
bool Red(const glm::vec4& c) {
    return Mostly(c, 0);
}
bool Green(const glm::vec4& c) {
    return Mostly(c, 1);
}
bool Secondary(const glm::vec4& c) {
    for (int low = 0; low < 3; ++low) {
        const float a = c[(low + 1) % 3], b = c[(low + 2) % 3];
        if (std::min(a, b) > 0.05f && c[low] < 0.2f * std::min(a, b) &&
            std::max(a, b) < 2.0f * std::min(a, b)) {
            return true;
        }
    }
    return false;
}

// What an unlit scene looks like from `view`, drawn on the CPU: every triangle of every instance
// rasterized at pixel centres (nearest z wins), its base-colour texture sampled at the nearest
// texel through the map's UV set, KHR_texture_transform and wrap modes, decoded from sRGB, times
// the base colour; a MASK material's fragments below its cutoff discarded (BLEND is drawn as
// opaque: compare only where no blended object is). Pixels no triangle covers keep alpha 0.
runtime::LinearImage ExpectedUnlit(const runtime::Scene& scene, const FrontView& view) {
    runtime::LinearImage out;
    out.width = view.width;
    out.height = view.height;
    out.rgba.assign(size_t(out.width) * out.height * 4, 0.0f);
    std::vector<float> depth(size_t(out.width) * out.height, -1e30f);
    auto wrap = [](float t, runtime::TextureWrap mode) {
        switch (mode) {
            case runtime::TextureWrap::kClampToEdge:
                return std::clamp(t, 0.0f, 1.0f);
            case runtime::TextureWrap::kMirroredRepeat: {
                const float m = t - 2.0f * std::floor(t * 0.5f);  // [0, 2)
                return m <= 1.0f ? m : 2.0f - m;
            }
            case runtime::TextureWrap::kRepeat:
                break;
        }
        return t - std::floor(t);
    };
    for (const runtime::Instance& inst : scene.instances) {
        for (const runtime::Primitive& p : scene.meshes[inst.mesh].primitives) {
            const runtime::SceneMaterial& m = scene.materials[size_t(p.material)];
            const runtime::TextureRef& ref = m.base_color_texture;
            const runtime::SceneImage* img =
                ref.image >= 0 ? &scene.images[size_t(ref.image)] : nullptr;
            auto shade = [&](glm::vec2 uv) {
                glm::vec4 c = m.base_color;
                if (!img) {
                    return c;
                }
                uv *= ref.uv_scale;
                const float cs = std::cos(ref.rotation), sn = std::sin(ref.rotation);
                uv = glm::vec2(cs * uv.x + sn * uv.y, cs * uv.y - sn * uv.x) + ref.offset;
                const uint32_t tx =
                    std::min(img->width - 1, uint32_t(wrap(uv.x, ref.wrap_s) * float(img->width)));
                const uint32_t ty = std::min(img->height - 1,
                                             uint32_t(wrap(uv.y, ref.wrap_t) * float(img->height)));
                const uint8_t* t = &img->rgba8[(size_t(ty) * img->width + tx) * 4];
                for (int k = 0; k < 3; ++k) {
                    c[k] *= float(SrgbToLinear(t[k] / 255.0));
                }
                c.a *= float(t[3]) / 255.0f;
                return c;
            };
            for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
                glm::vec2 px[3], uv[3];
                float z[3];
                for (int k = 0; k < 3; ++k) {
                    const runtime::MeshVertex& v = p.vertices[p.indices[t + size_t(k)]];
                    const glm::vec3 w(inst.world * glm::vec4(glm::make_vec3(v.position), 1));
                    px[k] = view.Pixel(w);
                    z[k] = w.z;
                    uv[k] = ref.texcoord == 1 ? glm::make_vec2(v.uv1) : glm::make_vec2(v.uv0);
                }
                const float area = (px[1].x - px[0].x) * (px[2].y - px[0].y) -
                                   (px[2].x - px[0].x) * (px[1].y - px[0].y);
                if (std::abs(area) < 1e-6f) {
                    continue;
                }
                const glm::vec2 lo = glm::min(px[0], glm::min(px[1], px[2]));
                const glm::vec2 hi = glm::max(px[0], glm::max(px[1], px[2]));
                for (int y = std::max(0, int(lo.y)); y < std::min(int(out.height), int(hi.y) + 1);
                     ++y) {
                    for (int x = std::max(0, int(lo.x));
                         x < std::min(int(out.width), int(hi.x) + 1); ++x) {
                        const glm::vec2 c(float(x) + 0.5f, float(y) + 0.5f);
                        auto edge = [&](int a, int b) {
                            return ((px[b].x - px[a].x) * (c.y - px[a].y) -
                                    (c.x - px[a].x) * (px[b].y - px[a].y)) /
                                   area;
                        };
                        const float b0 = edge(1, 2), b1 = edge(2, 0), b2 = edge(0, 1);
                        if (b0 < 0 || b1 < 0 || b2 < 0) {
                            continue;
                        }
                        const float zc = b0 * z[0] + b1 * z[1] + b2 * z[2];
                        const size_t i = size_t(y) * out.width + size_t(x);
                        if (zc <= depth[i]) {
                            continue;
                        }
                        const glm::vec4 col = shade(b0 * uv[0] + b1 * uv[1] + b2 * uv[2]);
                        if (m.alpha_mode == runtime::AlphaMode::kMask && col.a < m.alpha_cutoff) {
                            continue;
                        }
                        depth[i] = zc;
                        std::copy(&col[0], &col[0] + 4, &out.rgba[i * 4]);
                        out.rgba[i * 4 + 3] = 1.0f;
                    }
                }
            }
        }
    }
    return out;
}

// Of the pixels of `r` both images cover, the fraction whose colours agree within `tolerance`.
double Agreement(const runtime::LinearImage& a,
                 const runtime::LinearImage& b,
                 const Rect& r,
                 float tolerance) {
    size_t both = 0, same = 0;
    for (int y = std::max(0, r.y0); y < std::min(int(a.height), r.y1); ++y) {
        for (int x = std::max(0, r.x0); x < std::min(int(a.width), r.x1); ++x) {
            const glm::vec4 ca = At(a, x, y), cb = At(b, x, y);
            if (ca.a < 0.99f || cb.a < 0.99f) {
                continue;
            }
            ++both;
            same += glm::all(glm::lessThanEqual(glm::abs(glm::vec3(ca) - glm::vec3(cb)),
                                                glm::vec3(tolerance)))
                        ? 1
                        : 0;
        }
    }
    return both ? double(same) / double(both) : 0.0;
}

class GltfConformanceTest : public RuntimeTest {
  protected:
    runtime::LinearImage RenderFront(runtime::Scene& scene, uint32_t width, FrontView& view) {
        view = LookFromFront(scene, width);
        runtime::FrameSettings settings;
        settings.width = view.width;
        settings.height = view.height;
        scene.id = runtime::NewSceneId();  // the test edits scenes between frames
        runtime::LinearImage image = Render(scene, settings);
        KeepImage(image);  // KILN_TEST_IMAGES=<folder>: each render kept, to look at
        return image;
    }
};

// VertexColorTest: the test row's checks are white on cyan, magenta and yellow crosses; times
// the vertex colours red, green and blue the crosses vanish and the checks take the colours.
TEST_F(GltfConformanceTest, VertexColorTestMultipliesTheBaseColourByColor0) {
    runtime::Scene scene;
    DiagnosticList warnings;
    LOAD_SAMPLE_OR_SKIP("VertexColorTest", scene, warnings);
    FrontView view;
    const runtime::LinearImage image = RenderFront(scene, 384, view);
    const Rect all = Whole(image);
    EXPECT_EQ(Count(image, all, Secondary), 0u) << "a cyan, magenta or yellow cross shows";
    EXPECT_GT(Count(image, all, Red), all.Area() / 200);
    EXPECT_GT(Count(image, all, Green), all.Area() / 200);

    // Without COLOR_0 the crosses show.
    for (runtime::Mesh& mesh : scene.meshes) {
        for (runtime::Primitive& p : mesh.primitives) {
            for (runtime::MeshVertex& v : p.vertices) {
                v.color[0] = v.color[1] = v.color[2] = v.color[3] = 1.0f;
            }
        }
    }
    const runtime::LinearImage dropped = RenderFront(scene, 384, view);
    EXPECT_GT(Count(dropped, all, Secondary), all.Area() / 200);
}

// TextureSettingsTest: each test cell shows a green check (or, for clamp, a green bar) where
// its sampler, face culling and back-face lighting are right, and a red cross where not.
TEST_F(GltfConformanceTest, TextureSettingsTestShowsEveryCellsCheck) {
    runtime::Scene scene;
    DiagnosticList warnings;
    LOAD_SAMPLE_OR_SKIP("TextureSettingsTest", scene, warnings);
    const std::vector<std::string> cells = {
        "SingleSidedMesh",    "DoubleSidedMesh",    "TextureClampMeshS",  "TextureClampMeshT",
        "TextureRepeatMeshS", "TextureRepeatMeshT", "TextureMirrorMeshS", "TextureMirrorMeshT"};
    FrontView view;
    const runtime::LinearImage image = RenderFront(scene, 512, view);
    auto mean = [&](const runtime::LinearImage& img, const Rect& r) {
        double sum = 0;
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) {
                const glm::vec4 c = At(img, x, y);
                sum += double(c.r + c.g + c.b) / 3.0;
            }
        }
        return sum / double(std::max<size_t>(1, r.Area()));
    };
    std::map<std::string, Rect> rects;
    for (const std::string& cell : cells) {
        const runtime::Instance* inst = ByMesh(scene, cell);
        ASSERT_NE(inst, nullptr) << cell;
        const Rect r = rects[cell] = ScreenRect(scene, *inst, view, 0.05f);
        EXPECT_GT(r.Area(), 100u) << cell;
        EXPECT_LT(Count(image, r, Red), r.Area() / 100) << cell << ": a red cross shows";
        EXPECT_GT(Count(image, r, Green), r.Area() / 25) << cell << ": no green check";
    }
    // The double-sided cell is seen from its back: lit as its front would be (the same mean
    // brightness as the single-sided cell within 10%), not from behind (about a fifth of it).
    const double front = mean(image, rects["SingleSidedMesh"]);
    const double back = mean(image, rects["DoubleSidedMesh"]);
    EXPECT_NEAR(back / front, 1.0, 0.1) << "back " << back << ", front " << front;

    // Dropping a sampler's wrap mode (both axes repeat) brings the crosses back.
    for (runtime::SceneMaterial& m : scene.materials) {
        m.base_color_texture.wrap_s = m.base_color_texture.wrap_t = runtime::TextureWrap::kRepeat;
    }
    const runtime::LinearImage dropped = RenderFront(scene, 512, view);
    size_t crossed = 0;
    for (const char* cell :
         {"TextureClampMeshS", "TextureClampMeshT", "TextureMirrorMeshS", "TextureMirrorMeshT"}) {
        crossed += Count(dropped, rects[cell], Red) >= rects[cell].Area() / 100 ? 1 : 0;
    }
    EXPECT_EQ(crossed, 4u);
}

// NegativeScaleTest: a panel mirrored by a negative scale shows its front (a green check), as
// the positively scaled one does; with the winding kept its front would be culled.
TEST_F(GltfConformanceTest, NegativeScaleTestFlipsTheWindingOfMirroredNodes) {
    runtime::Scene scene;
    DiagnosticList warnings;
    LOAD_SAMPLE_OR_SKIP("NegativeScaleTest", scene, warnings);
    FrontView view;
    const runtime::LinearImage image = RenderFront(scene, 512, view);
    for (const char* node : {"PositiveScaleTest", "NegativeScaleFront"}) {
        const runtime::Instance* inst = ByNode(scene, node);
        ASSERT_NE(inst, nullptr) << node;
        const Rect r = ScreenRect(scene, *inst, view);
        EXPECT_LT(Count(image, r, Red), r.Area() / 100) << node << ": a red cross shows";
        EXPECT_GT(Count(image, r, Green), r.Area() / 25) << node << ": no green check";
    }
}

// UnlitTest: KHR_materials_unlit draws the base colour as it is, whatever the light.
TEST_F(GltfConformanceTest, UnlitTestDrawsTheBaseColourUnlit) {
    runtime::Scene scene;
    DiagnosticList warnings;
    LOAD_SAMPLE_OR_SKIP("UnlitTest", scene, warnings);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_TRUE(scene.materials[0].unlit);
    FrontView view;
    const runtime::LinearImage image = RenderFront(scene, 256, view);
    for (const runtime::Instance& inst : scene.instances) {
        const Rect r = ScreenRect(scene, inst, view, 0.3f);
        const glm::vec4 base =
            scene.materials[size_t(scene.meshes[inst.mesh].primitives[0].material)].base_color;
        const size_t exact = Count(image, r, [&](const glm::vec4& c) {
            return glm::all(
                glm::lessThan(glm::abs(glm::vec3(c) - glm::vec3(base)), glm::vec3(0.01f)));
        });
        EXPECT_EQ(exact, r.Area()) << inst.node;
    }
}

// MeshPrimitiveModes: triangle strips and fans are converted at load and drawn; points and
// lines are skipped with one warning per mode.
TEST_F(GltfConformanceTest, MeshPrimitiveModesDrawsStripsAndFansAndNamesWhatItSkips) {
    runtime::Scene scene;
    DiagnosticList warnings;
    LOAD_SAMPLE_OR_SKIP("MeshPrimitiveModes", scene, warnings);
    size_t skipped = 0;
    for (const Diagnostic& d : warnings.all()) {
        skipped += d.code == DiagCode::kSceneContentIgnored &&
                           d.message.find("Kiln draws triangles only") != std::string::npos
                       ? 1
                       : 0;
    }
    EXPECT_EQ(skipped, 4u);  // points, lines, line loops, line strips
    ASSERT_EQ(scene.meshes.size(), 7u);
    // The same hexagon three ways: 6 triangles, a strip of 6 vertices (4 triangles), a fan of 8
    // (6 triangles around the centre); converted right, each covers the hexagon's area.
    auto area = [&](size_t mesh) {
        const runtime::Primitive& p = scene.meshes[mesh].primitives.at(0);
        double sum = 0;
        for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            const glm::vec3 a = glm::make_vec3(p.vertices[p.indices[t]].position);
            const glm::vec3 b = glm::make_vec3(p.vertices[p.indices[t + 1]].position);
            const glm::vec3 c = glm::make_vec3(p.vertices[p.indices[t + 2]].position);
            sum += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
        }
        return sum;
    };
    const size_t triangles[] = {6, 4, 6};
    for (size_t mesh : {4u, 5u, 6u}) {
        ASSERT_EQ(scene.meshes[mesh].primitives.size(), 1u) << scene.meshes[mesh].name;
        EXPECT_EQ(scene.meshes[mesh].primitives[0].indices.size(), triangles[mesh - 4] * 3)
            << scene.meshes[mesh].name;
        EXPECT_NEAR(area(mesh), area(4), 1e-3 * area(4)) << scene.meshes[mesh].name;
    }
    FrontView view;
    const runtime::LinearImage image = RenderFront(scene, 384, view);
    for (size_t mesh : {4u, 5u, 6u}) {
        const runtime::Instance* inst = ByMesh(scene, scene.meshes[mesh].name);
        ASSERT_NE(inst, nullptr);
        const Rect r = ScreenRect(scene, *inst, view, 0.25f);  // inside the hexagon
        EXPECT_EQ(Count(image, r, [](const glm::vec4& c) { return c.a > 0.99f; }), r.Area())
            << scene.meshes[mesh].name << " is not covered";
    }
}

// MultiUVTest: the emissive map reads TEXCOORD_1 and shows the glTF logo; read through
// TEXCOORD_0 it shows "Multiple UVs not supported in this viewer" in white.
TEST_F(GltfConformanceTest, MultiUvTestReadsTheEmissiveMapThroughTexcoord1) {
    runtime::Scene scene;
    DiagnosticList warnings;
    LOAD_SAMPLE_OR_SKIP("MultiUVTest", scene, warnings);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].emissive_texture.texcoord, 1);
    EXPECT_EQ(scene.materials[0].base_color_texture.texcoord, 0);
    runtime::FrameSettings settings;  // the file's camera
    settings.width = 480;
    settings.height = 270;
    // White emissive text over the lit pastel base colours: every channel past 0.7 (no lit base
    // colour gets there under the default light); the logo's green emission: green at least
    // 0.2 above red and blue. At 480 x 270 the text covers about 600 pixels, the logos 1100.
    const Predicate white = [](const glm::vec4& c) { return std::min({c.r, c.g, c.b}) > 0.7f; };
    const Predicate logo = [](const glm::vec4& c) { return c.g > c.r + 0.2f && c.g > c.b + 0.2f; };
    const runtime::LinearImage image = Render(scene, settings);
    const Rect all = Whole(image);
    EXPECT_EQ(Count(image, all, white), 0u) << "the 'not supported' text shows";
    EXPECT_GT(Count(image, all, logo), 300u) << "no glTF logo";

    scene.materials[0].emissive_texture.texcoord = 0;
    scene.id = runtime::NewSceneId();
    const runtime::LinearImage dropped = Render(scene, settings);
    EXPECT_GT(Count(dropped, all, white), 150u);
    EXPECT_EQ(Count(dropped, all, logo), 0u);
}

// World-space bounds of an instance's primitives.
std::pair<glm::vec3, glm::vec3> WorldBounds(const runtime::Scene& scene,
                                            const runtime::Instance& inst) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const runtime::Primitive& p : scene.meshes[inst.mesh].primitives) {
        for (const runtime::MeshVertex& v : p.vertices) {
            const glm::vec3 w(inst.world * glm::vec4(glm::make_vec3(v.position), 1));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    }
    return {lo, hi};
}

// OrientationTest: six arrows, placed by quaternions and by matrices, each pointing into its
// target socket. Every arrow's tip (the vertex farthest from the origin) lies inside its
// target's bounds; with the rotations inverted (a quaternion read as its conjugate, a matrix
// transposed) none does.
TEST(GltfOrientation, EveryArrowPointsIntoItsTarget) {
    runtime::Scene scene;
    DiagnosticList warnings;
    LOAD_SAMPLE_OR_SKIP("OrientationTest", scene, warnings);
    auto tip_inside = [&](const runtime::Instance& arrow, const runtime::Instance& target,
                          bool inverted) {
        glm::mat4 world = arrow.world;
        if (inverted) {  // the same position, the rotation the other way
            const glm::vec4 t = world[3];
            world = glm::transpose(glm::mat4(glm::mat3(world)));
            world[3] = t;
        }
        glm::vec3 tip(0.0f);
        for (const runtime::Primitive& p : scene.meshes[arrow.mesh].primitives) {
            for (const runtime::MeshVertex& v : p.vertices) {
                const glm::vec3 w(world * glm::vec4(glm::make_vec3(v.position), 1));
                tip = glm::length(w) > glm::length(tip) ? w : tip;
            }
        }
        const auto [lo, hi] = WorldBounds(scene, target);
        return glm::all(glm::greaterThanEqual(tip, lo - 0.05f)) &&
               glm::all(glm::lessThanEqual(tip, hi + 0.05f));
    };
    for (const char* axis : {"X1", "X2", "Y1", "Y2", "Z1", "Z2"}) {
        const runtime::Instance* arrow = ByNode(scene, std::string("Arrow") + axis);
        const runtime::Instance* target = ByNode(scene, std::string("Target") + axis);
        ASSERT_NE(arrow, nullptr) << axis;
        ASSERT_NE(target, nullptr) << axis;
        EXPECT_TRUE(tip_inside(*arrow, *target, false)) << "Arrow" << axis << " misses";
        EXPECT_FALSE(tip_inside(*arrow, *target, true)) << "Arrow" << axis;
    }
}

// TextureTransformTest: offset, rotation, scale and all three (KHR_texture_transform) on clamped
// textures. Drawn unlit, every plane matches the CPU's nearest-texel drawing in nearly every
// pixel (the GPU filters bilinearly with mipmaps: texel edges differ, hence 90% within 0.1);
// without the transforms it does not.
TEST_F(GltfConformanceTest, TextureTransformTestMatchesTheCpuTransformOfEachPlane) {
    runtime::Scene scene;
    DiagnosticList warnings;
    LOAD_SAMPLE_OR_SKIP("TextureTransformTest", scene, warnings);
    ASSERT_EQ(scene.materials.size(), 9u);
    EXPECT_FLOAT_EQ(scene.materials[0].base_color_texture.offset.x, 0.5f);
    EXPECT_FLOAT_EQ(scene.materials[3].base_color_texture.rotation, 0.39269908f);
    EXPECT_FLOAT_EQ(scene.materials[4].base_color_texture.uv_scale.y, 1.5f);
    EXPECT_EQ(scene.materials[0].base_color_texture.wrap_s, runtime::TextureWrap::kClampToEdge);
    for (runtime::SceneMaterial& m : scene.materials) {
        m.unlit = true;
    }
    FrontView view;
    const runtime::LinearImage image = RenderFront(scene, 640, view);
    const runtime::LinearImage expected = ExpectedUnlit(scene, view);
    EXPECT_GT(Agreement(image, expected, Whole(image), 0.1f), 0.9);

    // Each transform on its own: with it taken away the plane no longer matches.
    for (size_t i = 0; i < 6; ++i) {
        runtime::Scene plain = scene;
        runtime::TextureRef& ref = plain.materials[i].base_color_texture;
        ref.offset = glm::vec2(0.0f);
        ref.uv_scale = glm::vec2(1.0f);
        ref.rotation = 0.0f;
        const runtime::LinearImage without = RenderFront(plain, 640, view);
        const runtime::Instance* inst = ByMesh(plain, plain.materials[i].name);
        ASSERT_NE(inst, nullptr) << plain.materials[i].name;
        const Rect r = ScreenRect(plain, *inst, view, 0.3f);
        size_t changed = 0;
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) {
                changed += glm::any(glm::greaterThan(
                               glm::abs(glm::vec3(At(without, x, y)) - glm::vec3(At(image, x, y))),
                               glm::vec3(0.1f)))
                               ? 1
                               : 0;
            }
        }
        EXPECT_GT(changed, r.Area() / 10) << plain.materials[i].name << ": no visible effect";
    }
}

// AlphaBlendModeTest: the same half-transparent texture on planes with alphaMode OPAQUE and MASK
// at cutoffs 0.25, 0.5 (the default) and 0.75, in front of a bed. Drawn unlit with the bed pure
// red (and without the decals on the floor), where each plane shows the bed must agree with the
// CPU's alpha-tested drawing in 95% of the plane's pixels (filtering moves the cut edge by a
// texel or so); with the cutoffs exchanged, or the alpha test dropped, it does not (below 85%).
TEST_F(GltfConformanceTest, AlphaBlendModeTestCutsEachPlaneAtItsCutoff) {
    runtime::Scene scene;
    DiagnosticList warnings;
    LOAD_SAMPLE_OR_SKIP("AlphaBlendModeTest", scene, warnings);
    for (runtime::SceneMaterial& m : scene.materials) {
        m.unlit = true;
    }
    ASSERT_EQ(scene.materials[0].name, "MatBed");
    scene.materials[0].base_color = glm::vec4(1, 0, 0, 1);
    scene.materials[0].base_color_texture.image = -1;
    std::erase_if(scene.instances,
                  [](const runtime::Instance& i) { return i.node.rfind("Decal", 0) == 0; });
    const Predicate bed = [](const glm::vec4& c) {
        return c.a > 0.99f && c.r > 0.9f && c.g < 0.1f && c.b < 0.1f;
    };
    const std::vector<std::string> masks = {"TestCutoff25", "TestCutoffDefault", "TestCutoff75"};
    // The fraction of the plane's pixels where the render and the CPU agree on whether the bed
    // shows through.
    auto agreement = [&](runtime::Scene& drawn, const runtime::Scene& meant,
                         const std::string& node) {
        FrontView view;
        const runtime::LinearImage image = RenderFront(drawn, 640, view);
        const runtime::LinearImage expected = ExpectedUnlit(meant, view);
        const runtime::Instance* inst = ByNode(meant, node);
        EXPECT_NE(inst, nullptr) << node;
        if (!inst) {
            return 0.0;
        }
        const Rect r = ScreenRect(meant, *inst, view, 0.02f);
        size_t same = 0;
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) {
                same += bed(At(image, x, y)) == bed(At(expected, x, y)) ? 1 : 0;
            }
        }
        return double(same) / double(std::max<size_t>(1, r.Area()));
    };
    runtime::Scene meant = scene;
    for (const std::string& node : masks) {
        EXPECT_GT(agreement(scene, meant, node), 0.95) << node;
    }
    EXPECT_GT(agreement(scene, meant, "TestOpaque"), 0.95);

    runtime::Scene swapped = scene;  // 0.25 <-> 0.75
    ASSERT_EQ(meant.materials[2].name, "MatCutoff25");
    ASSERT_EQ(meant.materials[3].name, "MatCutoff75");
    std::swap(swapped.materials[2].alpha_cutoff, swapped.materials[3].alpha_cutoff);
    EXPECT_LT(agreement(swapped, meant, "TestCutoff25"), 0.85);
    EXPECT_LT(agreement(swapped, meant, "TestCutoff75"), 0.85);
    runtime::Scene opaque = scene;
    for (runtime::SceneMaterial& m : opaque.materials) {
        if (m.alpha_mode == runtime::AlphaMode::kMask) {
            m.alpha_mode = runtime::AlphaMode::kOpaque;
        }
    }
    for (const std::string& node : masks) {
        EXPECT_LT(agreement(opaque, meant, node), 0.85) << node;
    }
}

}  // namespace
}  // namespace kiln::test
