// The ShaderLab AST. Every node carries the SourceRange it was parsed from. Literal render-state
// values are stored in their canonical spelling (e.g. "LEqual" for "lequal"); later stages lower
// them to enums. The JSON form of this tree is documented in docs/ast-json.md.
#ifndef KILN_SHADERLAB_AST_H_
#define KILN_SHADERLAB_AST_H_

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "kiln/pack/format.h"
#include "kiln/source.h"

namespace kiln::shaderlab {

// A render-state argument: a literal ("Back", 255) or a property reference ("[_Cull]").
struct StateValue {
    enum class Kind { kLiteral, kNumber, kPropertyRef };
    Kind kind = Kind::kLiteral;
    std::string text;   // canonical literal, the number as written, or the property name
    double number = 0;  // kNumber only
    SourceRange range;
};

// Cull, ZTest, ZWrite, ZClip, AlphaToMask, Conservative.
struct SimpleState {
    SourceRange range;  // the whole command
    StateValue value;
};

struct OffsetState {
    SourceRange range;
    StateValue factor;
    StateValue units;
};

struct BlendState {
    SourceRange range;
    int target = -1;  // render target index, -1 = all targets
    bool off = false;
    StateValue src, dst;  // unset when off
    std::optional<StateValue> src_alpha, dst_alpha;
};

struct BlendOpState {
    SourceRange range;
    int target = -1;
    StateValue op;
    std::optional<StateValue> op_alpha;
};

struct ColorMaskState {
    SourceRange range;
    int target = -1;
    StateValue mask;  // "RGBA", "RB", "0" (nothing) or a property reference
};

struct StencilEntry {
    std::string
        key;  // canonical: Ref, ReadMask, WriteMask, Comp, Pass, Fail, ZFail, CompFront, ...
    StateValue value;
    SourceRange range;
};

struct StencilState {
    SourceRange range;
    std::vector<StencilEntry> entries;
};

// Render state as written at one level (Category, SubShader or Pass). Inner levels inherit what
// they do not set; that resolution happens after parsing.
struct RenderState {
    std::optional<SimpleState> cull, ztest, zwrite, zclip, alpha_to_mask, conservative;
    std::optional<OffsetState> offset;
    std::vector<BlendState> blend;
    std::vector<BlendOpState> blend_op;
    std::vector<ColorMaskState> color_mask;
    std::optional<StencilState> stencil;
};

// Legacy fixed-function ShaderLab (Lighting, Material, Color, SetTexture, ...). Unity turns a
// pass without a program into vertex and fragment programs from these settings; so does Kiln
// (hlsl/fixed_function.h). Inner levels inherit what they do not set, as render state does.
struct FixedValue {
    std::vector<double> numbers;  // a colour (4, alpha 1 when omitted) or a single number
    std::string property;         // set for a [property] reference
    SourceRange range;
};

// One `combine` expression of a SetTexture stage: `src`, `src1 * src2`, `src1 + src2`,
// `src1 - src2`, `src1 +- src2`, `src1 lerp (src2) src3`, `src1 * src2 + src3` (also with
// `+-` and `-`), then `Double` or `Quad`.
struct CombineSource {
    std::string name;  // previous, primary, texture, constant (lower-case)
    bool one_minus = false;
    bool alpha = false;  // `texture alpha`: the source's alpha in every channel
};
enum class CombineOp {
    kNone,
    kMultiply,
    kAdd,
    kSubtract,
    kAddSigned,
    kLerp,
    kMultiplyAdd,
    kMultiplyAddSigned,
    kMultiplySubtract
};
struct Combiner {
    CombineOp op = CombineOp::kNone;
    std::vector<CombineSource> sources;  // 1, 2 or 3
    int scale = 1;                       // Double: 2, Quad: 4
};

struct TextureStage {
    SourceRange range;
    std::string texture;  // the [property] it samples
    std::optional<FixedValue> constant_color;
    Combiner color;                 // default: `combine texture * previous`
    std::optional<Combiner> alpha;  // after the comma; default: the colour expression's alpha
};

struct FixedFunction {
    std::optional<bool> lighting, separate_specular;
    std::optional<std::string> color_material;  // AmbientAndDiffuse or Emission
    std::optional<FixedValue> color;            // `Color`: the primary colour when unlit
    std::optional<FixedValue> diffuse, ambient, specular, emission, shininess;  // `Material`
    std::optional<std::string> alpha_test;  // comparison (Greater, ...); "Off" disables it
    std::optional<FixedValue> alpha_ref;
    std::vector<TextureStage> stages;                           // SetTexture (Pass level only)
    std::vector<std::pair<std::string, std::string>> bindings;  // BindChannels: source, target
    bool any = false;  // some fixed-function command was given
};

struct Tag {
    std::string key;
    std::string value;
    SourceRange range;
};

struct PragmaArg {
    std::string text;
    SourceRange range;
};

// A `#pragma name args...` line found in a program block (comments already skipped).
struct Pragma {
    std::string name;
    std::vector<PragmaArg> args;
    SourceRange range;
};

enum class ProgramKind {
    kCgProgram,
    kCgInclude,
    kHlslProgram,
    kHlslInclude,
    kGlslProgram,
    kGlslInclude
};

struct ProgramBlock {
    ProgramKind kind = ProgramKind::kCgProgram;
    SourceRange range;     // from the opening marker to the end of the closing marker
    SourceLoc body_begin;  // first byte after the opening marker: `text` starts here
    std::string text;      // verbatim body
    std::vector<Pragma> pragmas;
    // "" for a block of the shader's file; else the generated text it comes from (a surface
    // shader's generated pass, driver/surface_passes.h), which `#line` names.
    std::string file;
};

bool IsIncludeBlock(ProgramKind kind);
const char* ProgramKindName(ProgramKind kind);  // "CGPROGRAM", ...

// The property types are the pack format's (kiln/pack/format.h): one enum, one set of names.
using PropertyType = pack::PropertyType;
using pack::PropertyTypeName;  // "Color", "2D", ...
inline bool IsTextureType(PropertyType type) {
    return pack::IsTextureProperty(type);
}

struct Attribute {
    std::string name;
    std::vector<std::string> args;  // comma-separated arguments, trimmed
    std::string raw_args;           // the text between the parentheses, verbatim
    bool has_parens = false;
    SourceRange range;
};

struct Property {
    SourceRange range;
    std::string name;
    SourceRange name_range;
    std::string display_name;
    PropertyType type = PropertyType::kFloat;
    SourceRange type_range;
    double range_min = 0, range_max = 0;  // kRange only
    std::vector<double> default_value;    // 4 components for Color/Vector, 1 for numbers
    std::string default_texture;          // textures: "white", "bump", ...
    SourceRange default_range;
    std::vector<Attribute> attributes;
};

struct Pass {
    SourceRange range;
    std::string name;
    std::vector<Tag> tags;
    std::optional<int> lod;  // Unity accepts LOD in a Pass too; it overrides the SubShader's
    RenderState state;
    FixedFunction fixed;
    std::vector<ProgramBlock> programs;  // CGPROGRAM/HLSLPROGRAM and *INCLUDE, in source order
    // Generated from a surface shader (driver/surface_passes.h): `programs` holds every block the
    // pass compiles, in order (its header, the CGINCLUDE blocks, the shader's program, its tail).
    bool surface = false;
};

struct UsePass {
    SourceRange range;
    std::string target;  // "Shader/PASSNAME"
};

struct GrabPass {
    SourceRange range;
    std::string texture_name;  // empty: _GrabTexture
    std::string name;
    std::vector<Tag> tags;
};

using PassEntry = std::variant<Pass, UsePass, GrabPass>;

struct SubShader {
    SourceRange range;
    std::vector<Tag> tags;
    std::optional<int> lod;
    RenderState state;
    FixedFunction fixed;
    std::vector<ProgramBlock> programs;
    std::vector<PassEntry> passes;
};

struct Category;
using SubShaderEntry = std::variant<SubShader, std::unique_ptr<Category>>;

// `Category { state... SubShader { } ... }`: state and tags inherited by the subshaders inside.
struct Category {
    SourceRange range;
    std::vector<Tag> tags;
    std::optional<int> lod;
    RenderState state;
    FixedFunction fixed;
    std::vector<ProgramBlock> programs;
    std::vector<SubShaderEntry> children;
};

struct Fallback {
    SourceRange range;
    bool off = false;
    std::string name;
};

struct Dependency {
    SourceRange range;
    std::string key;
    std::string value;
};

struct Shader {
    SourceRange range;
    std::string name;
    SourceRange name_range;
    std::optional<SourceRange> properties_range;
    std::vector<Property> properties;
    // True when a property declaration failed to parse: references to undeclared properties are
    // then not reported, since the name may be the one that failed.
    bool properties_incomplete = false;
    std::vector<ProgramBlock> programs;  // Shader-level CGINCLUDE/HLSLINCLUDE
    std::vector<SubShaderEntry> subshaders;
    std::optional<Fallback> fallback;
    std::optional<std::string> custom_editor;
    std::vector<Dependency> dependencies;
};

}  // namespace kiln::shaderlab

#endif  // KILN_SHADERLAB_AST_H_
