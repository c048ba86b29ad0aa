// A scene's material sidecar, "<scene>.kiln.json": which .material file each glTF material of the
// scene uses, and the scene's ambient light.
//   {"kiln_materials": 1, "materials": {"<glTF material>": "x.material"}, "ambient": [r, g, b],
//    "description": "..."}
// "ambient" is one linear colour, or Unity's gradient:
//   {"sky": [r, g, b], "equator": [r, g, b], "ground": [r, g, b]}.
// "lights" sets Unity's per-light Render Mode by KHR_lights_punctual light name:
//   {"<light>": "auto" | "important" | "not-important"}.
// Read by `kiln compile --materials` (to build the variants a scene's materials need) and by the
// runtime's scene loader; here, in kiln_material, so that the compiler reads it without the
// renderer (docs/install.md).
#ifndef KILN_MATERIAL_SIDECAR_H_
#define KILN_MATERIAL_SIDECAR_H_

#include <array>
#include <map>
#include <string>

#include "kiln/result.h"

namespace kiln::material {

struct MaterialSidecar {
    // glTF material name -> .material path, relative to the sidecar's folder resolved.
    std::map<std::string, std::string> materials;
    bool has_ambient = false;
    bool trilight = false;           // ambient is the sky colour of a gradient
    std::array<float, 3> ambient{};  // linear RGB
    std::array<float, 3> equator{}, ground{};
    // light name -> "auto", "important" or "not-important", with the value's position.
    std::map<std::string, std::pair<std::string, std::string>> light_modes;  // (mode, "line:col")
};

// Reads and checks a sidecar. Errors are K0001 (cannot read it) or K0007 with
// "path:line:col: what" (not JSON, a field of the wrong type, an unknown field).
Result<MaterialSidecar> ReadMaterialSidecar(const std::string& path);

}  // namespace kiln::material

#endif  // KILN_MATERIAL_SIDECAR_H_
