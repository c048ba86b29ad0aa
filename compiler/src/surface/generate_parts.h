// The parts of a generated pass's tail (surface/generate.h): the interpolators, the v2f_surf
// struct and vert_surf (generate_vertex.cpp), frag_surf (generate_fragment.cpp).
#ifndef KILN_SURFACE_GENERATE_PARTS_H_
#define KILN_SURFACE_GENERATE_PARTS_H_

#include <string>
#include <vector>

#include "surface/generate.h"

namespace kiln::surface {

struct Interpolators {
    std::vector<std::string> members;        // the v2f_surf struct's lines
    std::vector<const InputMember*> uvs;     // uv_<Texture> members: pack_<name>
    std::vector<const InputMember*> custom;  // filled by the vertex: function: custom_<name>
    bool world = false;       // worldPos and the normal (tSpace0..2 in tangent space)
    bool screen_pos = false;  // screenPos
    bool color = false;       // the vertex colour
    bool facing = false;      // a VFACE member: frag_surf takes SV_IsFrontFace
    bool ambient = false;     // forward base and deferred: lmap and sh
    bool lighting = false;    // forward: UNITY_LIGHTING_COORDS
    bool fog = false;         // UNITY_FOG_COORDS
    int next = 0;             // the next free TEXCOORD

    std::string Next() { return "TEXCOORD" + std::to_string(next++); }
};

// Whether the pass applies fog (multi_compile_fog and UNITY_APPLY_FOG): not with nofog, and not
// with a finalcolor: function, which applies it itself (as Unity's terrain shaders do).
bool AppliesFog(const SurfaceShader& s, PassKind kind);

Interpolators PlanInterpolators(const SurfaceShader& s, PassKind kind);
std::string V2fStruct(const Interpolators& interp);
std::string VertexProgram(const SurfaceShader& s, PassKind kind, const Interpolators& interp);
std::string FragmentProgram(const SurfaceShader& s, PassKind kind, const Interpolators& interp);

// `code` (whole lines) under the `#if` lines the member is declared under.
inline std::string Guarded(const InputMember& m, const std::string& code) {
    std::string out;
    for (const std::string& c : m.conditions)
        out += c + "\n";
    out += code;
    for (size_t i = 0; i < m.conditions.size(); ++i)
        out += "#endif\n";
    return out;
}

// The interpolator name of an Input member.
inline std::string PackName(const InputMember& m) {
    return (m.kind == InputKind::kTexcoord ? "pack_" : "custom_") + m.name;
}

}  // namespace kiln::surface

#endif  // KILN_SURFACE_GENERATE_PARTS_H_
