// LoadGltf: tinygltf model -> Scene. Accessors of any component type are read with bounds checks
// (tinygltf checks buffer views against buffers; we check every element against its view), the
// node tree is flattened into instances, and KHR_lights_punctual lights are validated here
// because tinygltf 2.7 accepts unknown types and leaves defaults unset.
#include "kiln/runtime/scene.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>

#include "scene/accessors.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_input.h"
#include "scene/gltf_material.h"
#include "scene/node_tree.h"

namespace kiln::runtime {
namespace {

constexpr float kPi = 3.14159265358979f;

const char* ModeName(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS:
            return "points";
        case TINYGLTF_MODE_LINE:
            return "lines";
        case TINYGLTF_MODE_LINE_LOOP:
            return "line loops";
        case TINYGLTF_MODE_LINE_STRIP:
            return "line strips";
        default:
            return "an unknown mode";
    }
}

// A triangle strip or fan's indices as a triangle list (glTF 2.0, 3.7.2.1: strip triangle i is
// {v_i, v_i+(1+i%2), v_i+(2-i%2)}, keeping every triangle's winding; fan triangle i is
// {v_i+1, v_i+2, v_0}).
std::vector<uint32_t> TriangleList(int mode, const std::vector<uint32_t>& in) {
    std::vector<uint32_t> out;
    if (in.size() < 3) {
        return out;
    }
    out.reserve((in.size() - 2) * 3);
    for (size_t i = 0; i + 2 < in.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
            out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
        } else {
            out.insert(out.end(), {in[i], in[i + 1 + i % 2], in[i + 2 - i % 2]});
        }
    }
    return out;
}

// Errors and warnings name `path` and `where` ("mesh M primitive P"). A primitive of points or
// lines is skipped and counted in `skipped` by mode (warned about once per mode by the caller).
Status ReadPrimitive(const tinygltf::Model& m,
                     const tinygltf::Primitive& p,
                     const std::string& path,
                     const std::string& where,
                     Primitive& out,
                     std::map<int, size_t>& skipped,
                     DiagnosticList& diags) {
    const std::string at = path + ": " + where;
    const bool strip = p.mode == TINYGLTF_MODE_TRIANGLE_STRIP;
    const bool fan = p.mode == TINYGLTF_MODE_TRIANGLE_FAN;
    if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES && !strip && !fan) {
        ++skipped[p.mode];
        return {};
    }
    auto attr = [&](const char* name) {
        auto it = p.attributes.find(name);
        return it == p.attributes.end() ? -1 : it->second;
    };
    std::vector<float> pos, nrm, uv0, uv1, tan, col;
    if (attr("POSITION") < 0) {
        return Error{DiagCode::kBadScene, at + ": no POSITION attribute"};
    }
    if (Status read = ReadAccessor(m, attr("POSITION"), 3, pos); !read.ok()) {
        return Error{DiagCode::kBadScene, at + ": " + read.error().message};
    }
    const size_t n = pos.size() / 3;
    auto optional = [&](const char* name, int comps, std::vector<float>& v) -> bool {
        if (attr(name) < 0) {
            return false;
        }
        const Status read = ReadAccessor(m, attr(name), comps, v);
        if (!read.ok() || v.size() != n * size_t(comps)) {
            diags.Warning(DiagCode::kSceneContentIgnored, path, kNoPosition,
                          where + ": attribute " + name + " ignored: " +
                              (read.ok() ? "count differs from POSITION" : read.error().message));
            v.clear();
            return false;
        }
        return true;
    };
    const bool has_normals = optional("NORMAL", 3, nrm);
    const bool has_uv0 = optional("TEXCOORD_0", 2, uv0);
    const bool has_uv1 = optional("TEXCOORD_1", 2, uv1);
    out.has_tangents = optional("TANGENT", 4, tan);
    out.has_colors = false;
    if (attr("COLOR_0") >= 0) {
        const int color = attr("COLOR_0");
        const int comps = size_t(color) < m.accessors.size() &&
                                  m.accessors[size_t(color)].type == TINYGLTF_TYPE_VEC3
                              ? 3
                              : 4;  // a bad index is reported by ReadAccessor
        out.has_colors = optional("COLOR_0", comps, col);
        if (out.has_colors && comps == 3) {
            std::vector<float> rgba(n * 4);
            for (size_t i = 0; i < n; ++i) {
                rgba[i * 4 + 0] = col[i * 3 + 0];
                rgba[i * 4 + 1] = col[i * 3 + 1];
                rgba[i * 4 + 2] = col[i * 3 + 2];
                rgba[i * 4 + 3] = 1.0f;
            }
            col = std::move(rgba);
        }
    }
    out.vertices.resize(n);
    for (size_t i = 0; i < n; ++i) {
        MeshVertex& v = out.vertices[i];
        std::memset(&v, 0, sizeof v);
        std::memcpy(v.position, &pos[i * 3], 12);
        if (has_normals) {
            std::memcpy(v.normal, &nrm[i * 3], 12);
        }
        if (has_uv0) {
            std::memcpy(v.uv0, &uv0[i * 2], 8);
        }
        if (has_uv1) {
            std::memcpy(v.uv1, &uv1[i * 2], 8);
        }
        if (out.has_tangents) {
            std::memcpy(v.tangent, &tan[i * 4], 16);
        } else {
            v.tangent[0] = 1.0f;
            v.tangent[3] = 1.0f;
        }
        for (int c = 0; c < 4; ++c) {
            v.color[c] = out.has_colors ? col[i * 4 + size_t(c)] : 1.0f;
        }
    }
    if (p.indices >= 0) {
        if (Status read = ReadIndices(m, p.indices, out.indices); !read.ok()) {
            return Error{DiagCode::kBadScene, at + ": " + read.error().message};
        }
    } else {
        out.indices.resize(n);
        for (size_t i = 0; i < n; ++i) {
            out.indices[i] = uint32_t(i);
        }
    }
    if (strip || fan) {
        out.indices = TriangleList(p.mode, out.indices);
    }
    out.indices.resize(out.indices.size() / 3 * 3);
    for (uint32_t& index : out.indices) {
        if (index >= n) {
            return Error{DiagCode::kBadScene, at + ": index " + std::to_string(index) +
                                                  " is past the " + std::to_string(n) +
                                                  " vertices"};
        }
    }
    if (!has_normals) {  // flat normals are what glTF asks for; smooth per-vertex is close
        for (size_t t = 0; t + 2 < out.indices.size(); t += 3) {
            MeshVertex* v[3] = {&out.vertices[out.indices[t]], &out.vertices[out.indices[t + 1]],
                                &out.vertices[out.indices[t + 2]]};
            const glm::vec3 a = glm::make_vec3(v[0]->position), b = glm::make_vec3(v[1]->position),
                            c = glm::make_vec3(v[2]->position);
            const glm::vec3 fn = glm::cross(b - a, c - a);
            for (MeshVertex* x : v) {
                for (int k = 0; k < 3; ++k) {
                    x->normal[k] += fn[k];
                }
            }
        }
        for (MeshVertex& v : out.vertices) {
            glm::vec3 nn = glm::make_vec3(v.normal);
            const float len = glm::length(nn);
            nn = len > 1e-20f ? nn / len : glm::vec3(0, 0, 1);
            std::memcpy(v.normal, &nn[0], 12);
        }
    }
    out.material = p.material >= 0 && size_t(p.material) < m.materials.size() ? p.material : -1;
    if (!out.has_tangents && has_uv0) {
        GenerateTangents(out);
    }
    return {};
}

// Checks one KHR_lights_punctual light; empty when valid.
std::string CheckLight(const tinygltf::Light& l) {
    if (l.type != "directional" && l.type != "point" && l.type != "spot") {
        return "unknown light type '" + l.type + "' (expected directional, point or spot)";
    }
    if (!l.color.empty() && l.color.size() != 3) {
        return "color has " + std::to_string(l.color.size()) + " components, expected 3";
    }
    for (double c : l.color) {
        if (!std::isfinite(c) || c < 0) {
            return "color components must be finite and >= 0";
        }
    }
    if (!std::isfinite(l.intensity) || l.intensity < 0) {
        return "intensity must be finite and >= 0";
    }
    if (l.range < 0 || !std::isfinite(l.range)) {
        return "range must be > 0 when given";
    }
    if (l.type == "spot") {
        const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
        if (!(inner >= 0 && inner < outer && outer <= kPi / 2 + 1e-6)) {
            return "spot cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2 "
                   "(got " +
                   std::to_string(inner) + ", " + std::to_string(outer) + ")";
        }
    }
    return {};
}

glm::mat4 LocalMatrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) {
            m[i / 4][i % 4] = float(n.matrix[size_t(i)]);
        }
        return m;
    }
    glm::mat4 m(1.0f);
    if (n.translation.size() == 3) {
        m = glm::translate(m, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
    }
    if (n.rotation.size() == 4) {
        m *= glm::mat4_cast(glm::normalize(glm::quat(float(n.rotation[3]), float(n.rotation[0]),
                                                     float(n.rotation[1]), float(n.rotation[2]))));
    }
    if (n.scale.size() == 3) {
        m = glm::scale(m, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
    }
    return m;
}

}  // namespace

Result<Scene> LoadGltf(const std::string& path, DiagnosticList& diags) {
    tinygltf::Model model;
    std::string warn;
    std::map<int, std::string> image_errors;
    const Status loaded = LoadGltfModel(path, model, warn, image_errors);
    for (const std::string& line : MessageLines(warn)) {
        diags.Warning(DiagCode::kGltfWarning, path, kNoPosition, line);
    }
    if (!loaded.ok()) {
        return loaded.error();
    }
    Scene scene;
    scene.id = NewSceneId();
    scene.path = path;
    for (size_t i = 0; i < model.images.size(); ++i) {
        const tinygltf::Image& img = model.images[i];
        SceneImage si;
        si.name = img.name.empty() ? img.uri : img.name;
        if (img.width > 0 && img.height > 0 && img.component == 4 && img.bits == 8 &&
            img.image.size() == size_t(img.width) * size_t(img.height) * 4) {
            si.width = uint32_t(img.width);
            si.height = uint32_t(img.height);
            si.rgba8 = img.image;
        } else if (auto why = image_errors.find(int(i)); why != image_errors.end()) {
            diags.Warning(DiagCode::kTextureFallback, path, kNoPosition,
                          why->second + "; the default texture is used instead");
        } else {
            diags.Warning(DiagCode::kTextureFallback, path, kNoPosition,
                          "image '" + si.name + "' could not be decoded as 8-bit RGBA; the " +
                              "default texture is used instead");
        }
        scene.images.push_back(std::move(si));
    }
    WarnIgnoredFeatures(model, path, diags);
    for (size_t i = 0; i < model.materials.size(); ++i) {
        scene.materials.push_back(ReadGltfMaterial(model, i, path, diags));
    }
    std::map<int, size_t> skipped;  // primitives of points and lines, by mode
    for (size_t mi = 0; mi < model.meshes.size(); ++mi) {
        Mesh mesh;
        mesh.name = model.meshes[mi].name;
        for (size_t pi = 0; pi < model.meshes[mi].primitives.size(); ++pi) {
            Primitive prim;
            const std::string where =
                "mesh " + std::to_string(mi) + " primitive " + std::to_string(pi);
            if (Status read = ReadPrimitive(model, model.meshes[mi].primitives[pi], path, where,
                                            prim, skipped, diags);
                !read.ok()) {
                return read.error();
            }
            if (!prim.indices.empty()) {
                ComputeBounds(prim);
                mesh.primitives.push_back(std::move(prim));
            }
        }
        scene.meshes.push_back(std::move(mesh));
    }
    for (const auto& [mode, count] : skipped) {
        diags.Warning(DiagCode::kSceneContentIgnored, path, kNoPosition,
                      std::to_string(count) + " primitive(s) of " + ModeName(mode) + " (mode " +
                          std::to_string(mode) + ") skipped: Kiln draws triangles only");
    }
    // Lights: validated once; nodes refer to them by index.
    std::vector<std::string> light_problem(model.lights.size());
    for (size_t i = 0; i < model.lights.size(); ++i) {
        light_problem[i] = CheckLight(model.lights[i]);
        if (!light_problem[i].empty()) {
            diags.Warning(DiagCode::kSceneContentIgnored, path, kNoPosition,
                          "light " + std::to_string(i) + " '" + model.lights[i].name +
                              "' rejected: " + light_problem[i]);
        }
    }
    // One node of the walk (node_tree.h checked the hierarchy), at its world transform.
    auto add = [&](int index, const glm::mat4& world) {
        const tinygltf::Node& node = model.nodes[size_t(index)];
        if (node.mesh >= 0 && size_t(node.mesh) < scene.meshes.size()) {
            scene.instances.push_back({uint32_t(node.mesh), world, node.name});
        }
        if (node.camera >= 0 && size_t(node.camera) < model.cameras.size()) {
            const tinygltf::Camera& gc = model.cameras[size_t(node.camera)];
            Camera cam;
            cam.name = gc.name.empty() ? node.name : gc.name;
            cam.perspective = gc.type != "orthographic";
            if (cam.perspective) {
                cam.yfov = float(gc.perspective.yfov);
                cam.aspect = float(gc.perspective.aspectRatio);
                cam.znear = float(gc.perspective.znear);
                cam.zfar = float(gc.perspective.zfar);
            } else {
                cam.xmag = float(gc.orthographic.xmag);
                cam.ymag = float(gc.orthographic.ymag);
                cam.znear = float(gc.orthographic.znear);
                cam.zfar = float(gc.orthographic.zfar);
            }
            cam.world = world;
            scene.cameras.push_back(cam);
        }
        if (auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end()) {
            const tinygltf::Value& li = it->second.Get("light");
            const int light = li.IsInt() ? li.GetNumberAsInt() : -1;
            if (light < 0 || size_t(light) >= model.lights.size()) {
                diags.Warning(DiagCode::kSceneContentIgnored, path, kNoPosition,
                              "node '" + node.name + "' refers to light " + std::to_string(light) +
                                  ", which does not exist; ignored");
            } else if (light_problem[size_t(light)].empty()) {
                const tinygltf::Light& gl = model.lights[size_t(light)];
                Light l;
                l.name = gl.name.empty() ? node.name : gl.name;
                l.type = gl.type == "directional" ? LightType::kDirectional
                         : gl.type == "spot"      ? LightType::kSpot
                                                  : LightType::kPoint;
                if (gl.color.size() == 3) {
                    l.color = glm::vec3(gl.color[0], gl.color[1], gl.color[2]);
                }
                l.intensity = float(gl.intensity);
                l.range = l.type == LightType::kDirectional ? 0.0f : float(gl.range);
                l.inner_cone = float(gl.spot.innerConeAngle);
                l.outer_cone = float(gl.spot.outerConeAngle);
                l.position = glm::vec3(world[3]);
                l.direction = glm::normalize(glm::vec3(world * glm::vec4(0, 0, -1, 0)));
                if (!std::isfinite(l.direction.x)) {
                    l.direction = glm::vec3(0, 0, -1);
                }
                scene.lights.push_back(l);
            }
        }
    };
    const std::vector<int>* roots = nullptr;  // no scenes: every parentless node
    if (model.defaultScene >= 0 && size_t(model.defaultScene) >= model.scenes.size()) {
        return Error{DiagCode::kBadScene, path + ": the default scene " +
                                              std::to_string(model.defaultScene) +
                                              " does not exist (the file has " +
                                              std::to_string(model.scenes.size()) + " scenes)"};
    }
    if (model.defaultScene >= 0) {
        roots = &model.scenes[size_t(model.defaultScene)].nodes;
    } else if (!model.scenes.empty()) {
        roots = &model.scenes[0].nodes;
    }
    std::vector<NodeVisit> order;
    if (Status walked = WalkNodeTree(model, path, roots, order); !walked.ok())
        return walked.error();
    std::vector<glm::mat4> world(model.nodes.size(), glm::mat4(1.0f));
    for (const NodeVisit& v : order) {
        const glm::mat4 parent = v.parent < 0 ? glm::mat4(1.0f) : world[size_t(v.parent)];
        world[size_t(v.node)] = parent * LocalMatrix(model.nodes[size_t(v.node)]);
        add(v.node, world[size_t(v.node)]);
    }
    const std::filesystem::path sidecar =
        std::filesystem::path(path).replace_extension(".kiln.json");
    std::error_code ec;
    if (std::filesystem::exists(sidecar, ec)) {
        if (Status read = LoadMaterialSidecar(sidecar.string(), scene); !read.ok()) {
            return read.error();
        }
    }
    return scene;
}

glm::vec3 ShaderLightColor(const Light& light) {
    return light.color * (light.intensity / kPi);
}

std::pair<glm::vec3, glm::vec3> SceneBounds(const Scene& scene) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const Instance& inst : scene.instances) {
        for (const Primitive& p : scene.meshes[inst.mesh].primitives) {
            for (const MeshVertex& v : p.vertices) {
                const glm::vec3 w =
                    glm::vec3(inst.world * glm::vec4(glm::make_vec3(v.position), 1));
                lo = glm::min(lo, w);
                hi = glm::max(hi, w);
            }
        }
    }
    if (lo.x > hi.x) {
        return {glm::vec3(-0.5f), glm::vec3(0.5f)};
    }
    return {lo, hi};
}

}  // namespace kiln::runtime
