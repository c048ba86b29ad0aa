// Scenes the renderer draws, free of Vulkan: meshes with every vertex stream filled, a flattened
// node hierarchy, cameras, punctual lights and glTF materials. LoadGltf fills one from a .gltf
// or .glb file (tinygltf); an optional sidecar assigns Kiln material instances by material name.
#ifndef KILN_RUNTIME_SCENE_H_
#define KILN_RUNTIME_SCENE_H_

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/vertex.h"
#include "kiln/result.h"

namespace kiln::runtime {

// The interleaved vertex the pipelines read (kiln/pack/vertex.h).
using MeshVertex = pack::MeshVertex;

struct Primitive {
    std::vector<MeshVertex> vertices;
    std::vector<uint32_t> indices;  // triangle list (glTF strips and fans converted at load)
    int material = -1;              // -1: glTF's default material
    bool has_tangents = false;      // from the file (else generated when there are UVs)
    bool has_colors = false;
    // Local (object-space) bounds, set once by ComputeBounds when the scene is loaded; min > max
    // when they are not set, and the renderer then computes them from the vertices each frame.
    glm::vec3 bounds_min{std::numeric_limits<float>::max()};
    glm::vec3 bounds_max{-std::numeric_limits<float>::max()};
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
};

struct SceneImage {
    std::string name;
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;
};

// A sampler's wrap mode on one axis (glTF's wrapS / wrapT).
enum class TextureWrap { kRepeat, kClampToEdge, kMirroredRepeat };

struct TextureRef {
    int image = -1;    // -1: none
    int texcoord = 0;  // the TEXCOORD_n set (0 or 1; KHR_texture_transform's texCoord wins)
    float scale = 1;   // normalTexture.scale / occlusionTexture.strength
    TextureWrap wrap_s = TextureWrap::kRepeat, wrap_t = TextureWrap::kRepeat;
    bool nearest = false;
    // KHR_texture_transform: uv' = offset + R(rotation) (uv_scale * uv), R rotating
    // counter-clockwise in UV space, [[cos, sin], [-sin, cos]] (the extension's matrix).
    glm::vec2 offset{0.0f}, uv_scale{1.0f};
    float rotation = 0;
};

enum class AlphaMode { kOpaque, kMask, kBlend };

// A glTF metallic-roughness material; all factors linear.
struct SceneMaterial {
    std::string name;
    glm::vec4 base_color{1.0f};
    float metallic = 1, roughness = 1;
    glm::vec3 emissive{0.0f};  // times KHR_materials_emissive_strength
    TextureRef base_color_texture, metallic_roughness_texture, normal_texture, occlusion_texture,
        emissive_texture;
    AlphaMode alpha_mode = AlphaMode::kOpaque;
    float alpha_cutoff = 0.5f;
    bool double_sided = false;  // back faces drawn, lit with the normal turned towards them
    bool unlit = false;         // KHR_materials_unlit: drawn with Kiln/Unlit
};

enum class LightType { kDirectional, kPoint, kSpot };

// Unity's per-light Render Mode: kImportant lights are always per pixel, kNotImportant ones never
// (per vertex or in SH); kAuto lights are ranked (docs/runtime.md, "Light modes").
enum class LightImportance { kAuto, kImportant, kNotImportant };

struct Light {
    std::string name;
    LightType type = LightType::kPoint;
    glm::vec3 color{1.0f};                          // linear
    float intensity = 1;                            // lux (directional) or candela (point, spot)
    float range = 0;                                // 0: unlimited
    float inner_cone = 0, outer_cone = 0.7853982f;  // radians from the axis
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};               // world, unit: where the light shines
    LightImportance importance = LightImportance::kAuto;  // the sidecar's "lights"
};

// The light colour Unity's shader convention expects (_LightColor0, unity_LightColor) for a light
// of glTF intensity: lux for directional lights, candela (at 1 m) for point and spot lights.
// Unity's shaders leave out the Lambertian 1/pi, so the colour is irradiance / pi: a 1-lux white
// light on a white Lambertian surface facing it shades to 1/pi (docs/runtime.md).
glm::vec3 ShaderLightColor(const Light& light);

struct Camera {
    std::string name;
    bool perspective = true;
    float yfov = 0.8f, aspect = 0;  // aspect 0: the image's
    float znear = 0.05f, zfar = 0;  // zfar 0: infinite
    float xmag = 1, ymag = 1;       // orthographic half extents
    glm::mat4 world{1.0f};          // camera to world; looks down -Z, +Y up
};

enum class AmbientMode { kFlat, kTrilight, kSky };

// A sky for the ambient light: an equirectangular image of linear radiance (row 0 straight up,
// the centre column looking down -z, +x three quarters across; reference::EquirectDirection),
// and what the renderer reads of it, derived once when it is made: its SH projection, its mean
// radiance, and its mean over the upper cap, the horizon band and the lower cap (y > 0.5,
// |y| <= 0.5, y < -0.5) and over each cube face (+x, -x, +y, -y, +z, -z).
struct Sky {
    std::string name;  // the image file, or "procedural"
    uint32_t width = 0, height = 0;
    std::vector<float> rgb;
    std::array<glm::dvec3, 9> sh{};  // reference::SH9 coefficients
    glm::vec3 mean{0.0f}, up{0.0f}, horizon{0.0f}, down{0.0f};
    std::array<glm::vec3, 6> faces{};
};

// Kiln's procedural sky: `zenith` straight up, blending into `horizon` as the direction nears
// the horizon (weight y^(1/2) above it) and into `ground` just below it (weight (-y)^(1/2)),
// rendered into a 256 x 128 image. No sun disc: the sun is the scene's directional light.
std::shared_ptr<const Sky> ProceduralSky(const glm::vec3& zenith,
                                         const glm::vec3& horizon,
                                         const glm::vec3& ground);
// An equirectangular HDR image (Radiance .hdr, or any format stb_image reads; 8-bit images are
// decoded from sRGB) as a sky, radiance x `scale`. Errors name the file.
Result<std::shared_ptr<const Sky>> LoadSky(const std::string& path, float scale = 1.0f);
// A sky of an image already in memory (width x height linear RGB), with its derived values.
std::shared_ptr<const Sky> MakeSky(std::string name,
                                   uint32_t width,
                                   uint32_t height,
                                   std::vector<float> rgb);

struct Instance {
    uint32_t mesh = 0;
    glm::mat4 world{1.0f};
    std::string node;
};

struct Scene {
    std::string path;  // the file it came from
    // Nonzero (NewSceneId(), set by LoadGltf): the renderer keeps the scene's vertex and index
    // buffers, images and material instances on the device between frames and re-uses them while
    // it renders scenes with this id. A scene with an id must not change: after editing one, give
    // it a new id. 0: everything is uploaded again for each frame.
    uint64_t id = 0;
    std::vector<Mesh> meshes;
    std::vector<SceneImage> images;
    std::vector<SceneMaterial> materials;
    std::vector<Instance> instances;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    // The ambient light as Unity's Environment Lighting gives it: kFlat, one linear colour
    // (`ambient`); kTrilight, a gradient from `ambient` (sky, straight up) through
    // `ambient_equator` (the horizon) to `ambient_ground` (straight down); kSky, `sky` (a
    // procedural sky or an HDR image). It fills unity_AmbientSky/Equator/Ground, the SH probe
    // (its projection) and the reflection cube.
    AmbientMode ambient_mode = AmbientMode::kFlat;
    glm::vec3 ambient{0.05f};
    glm::vec3 ambient_equator{0.05f}, ambient_ground{0.05f};
    std::shared_ptr<const Sky> sky;  // kSky
    // The scene said what its ambient is (its sidecar's "ambient"). kiln render gives a scene
    // that says nothing Unity's default environment, the procedural sky.
    bool ambient_given = false;
    // glTF material name -> .material file (absolute or relative to the working directory).
    std::map<std::string, std::string> material_files;
};

// Loads a .gltf or .glb. Recoverable problems (an invalid light, a missing image) are dropped
// with a warning added to `diags` (K0013, K0016, K0017; the file is the scene); anything that
// leaves no usable scene is an error (K0007). An extension the file requires and Kiln does not
// support is an error naming it (K0030); each optional feature Kiln ignores (an unsupported
// extension it uses, skins, animations, morph targets, points and lines) one warning (K0016).
Result<Scene> LoadGltf(const std::string& path, DiagnosticList& diags);

// Reads a material sidecar: {"kiln_materials": 1, "materials": {"<glTF material>": "x.material"},
// "ambient": [r, g, b]}; paths relative to the sidecar. LoadGltf reads "<scene>.kiln.json"
// beside the scene by itself when present.
Status LoadMaterialSidecar(const std::string& path, Scene& scene);

// Fills tangents from positions, normals and UV0 (per-triangle UV derivatives accumulated per
// vertex, Gram-Schmidt against the normal, handedness from the bitangent).
void GenerateTangents(Primitive& primitive);

// Sets a primitive's local bounds from its vertices (min > max when it has none).
void ComputeBounds(Primitive& primitive);

// A process-wide unique, nonzero scene id.
uint64_t NewSceneId();

// World-space bounds of every instance: (min, max); an empty scene gives a unit box.
std::pair<glm::vec3, glm::vec3> SceneBounds(const Scene& scene);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_SCENE_H_
