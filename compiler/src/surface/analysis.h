// What the pass generator needs to know about a surface shader beyond its directive (issue 39):
// its Input struct, its lighting model's functions and output struct, whether the surface
// function writes a per-pixel normal (then Unity's generator works in tangent space: Input's
// viewDir is in tangent space and INTERNAL_DATA carries the tangent frame), and the vertex
// function's input struct and whether it fills custom Input members. Read from the program's
// text with the files it includes (surface/input_struct.h, surface/lighting_model.h).
#ifndef KILN_SURFACE_ANALYSIS_H_
#define KILN_SURFACE_ANALYSIS_H_

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "surface/directive.h"
#include "surface/input_struct.h"
#include "surface/lighting_model.h"

namespace kiln::surface {

// The vertex input struct (appdata_full unless a vertex: function takes another), by the members
// the generated vertex program may read.
struct VertexInput {
    std::string type = "appdata_full";
    std::set<std::string> members;  // vertex, normal, tangent, texcoord, texcoord1, ..., color
    // The `#if` lines a member is declared under (surface/input_struct.h, ConditionsAt).
    std::map<std::string, std::vector<std::string>> conditions;
    bool instance_id = true;  // has UNITY_VERTEX_INPUT_INSTANCE_ID

    bool Has(const std::string& member) const { return members.count(member) > 0; }
};

struct SurfaceShader {
    SurfaceDirective directive;
    InputStruct input;
    LightingModel model;
    std::string output_type;     // SurfaceOutput, SurfaceOutputStandard, ... (the model's)
    std::string output_param;    // the surface function's second parameter's name
    bool tangent_space = false;  // the surface function writes o.Normal
    VertexInput vertex_input;
    bool vertex_fills_input = false;  // vertex:func(inout v, out Input o)
    // Identifiers of the text, for the _ST vectors the generated code declares only when the
    // shader does not.
    std::set<std::string> identifiers;
    // The shader declares LOD_FADE_CROSSFADE itself (`dithercrossfade` then adds no keyword set).
    bool declares_crossfade = false;

    // Built-in and custom models with a physically based output (UnityPBSLighting.cginc).
    bool PhysicallyBasedOutput() const;
};

// Why a surface shader cannot be generated: which function or struct is missing.
struct SurfaceProblem {
    std::string message;
};

// Reads `text` (the surface program with what it includes before it) for `directive`.
std::optional<SurfaceShader> AnalyzeSurface(std::string_view text,
                                            const SurfaceDirective& directive,
                                            SurfaceProblem& problem);

// The built-in models' functions (Lighting.cginc and UnityPBSLighting.cginc, as in every Unity
// release since 5.0 and in Kiln's layer); an empty model for other names.
LightingModel BuiltinLightingModel(std::string_view name);

}  // namespace kiln::surface

#endif  // KILN_SURFACE_ANALYSIS_H_
