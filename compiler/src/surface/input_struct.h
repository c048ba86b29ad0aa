// A surface shader's Input struct (Unity manual, "Surface Shader input structure"): the type of
// the surface function's first parameter, its members classified by the names and semantics
// Unity's generator fills: uv_<Texture> (uv2_, uv3_, uv4_: other UV sets), viewDir, worldPos,
// worldNormal, worldRefl, screenPos, a member with semantic COLOR (the vertex colour), VFACE, the
// INTERNAL_DATA marker (per-pixel normals: WorldNormalVector, WorldReflectionVector) and custom
// members a vertex: function fills. Only what a shader reads is generated (issue 39).
#ifndef KILN_SURFACE_INPUT_STRUCT_H_
#define KILN_SURFACE_INPUT_STRUCT_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kiln::surface {

enum class InputKind {
    kTexcoord,
    kViewDir,
    kWorldPos,
    kWorldNormal,
    kWorldRefl,
    kScreenPos,
    kColor,
    kFacing,
    kCustom,
};

// "uv_<texture>", "viewDir", ...: how the manual names each kind.
const char* InputKindName(InputKind kind);

struct InputMember {
    std::string type, name, semantic;  // semantic without the colon, "" when none
    size_t offset = 0;                 // of the name, in the text searched
    InputKind kind = InputKind::kCustom;
    std::string texture;  // kTexcoord: the texture whose _ST transforms it (uv_MainTex: _MainTex)
    // semantic "FOG": UNITY_FOG_COORDS(n) in the struct, read as `float1 fogCoord` (it exists only
    // with fog on).
    int uv_set = 0;  // kTexcoord: 0 for uv_, 1 for uv2_, 2 for uv3_, 3 for uv4_
    // The `#if` lines inside the struct the member is declared under, outermost first (an
    // `#else` branch as the negated condition): generated code that reads it goes under them too.
    std::vector<std::string> conditions;
};

struct InputStruct {
    std::string name;   // the struct's name ("Input" by convention)
    size_t offset = 0;  // of its name, in the text searched
    std::vector<InputMember> members;
    bool internal_data = false;  // INTERNAL_DATA: world normals per pixel from the tangent frame

    bool Reads(InputKind kind) const;
};

// The conditional directives inside a struct (from its `{` at `from`) open at `at`: `#ifdef X`,
// `#ifndef X`, `#if E`, an `#else` branch as the negated condition, an `#elif` as its own.
std::vector<std::string> ConditionsAt(std::string_view text, size_t from, size_t at);

// Those lines as one `#if` expression: "defined(X) && !defined(Y) && (E)"; "1" for none.
std::string ConditionExpression(const std::vector<std::string>& conditions);

// The Input struct of `surface_function` in `text` (a program's text with what it includes before
// it); nullopt when the function or its first parameter's struct is not in `text`.
std::optional<InputStruct> FindInputStruct(std::string_view text,
                                           std::string_view surface_function);

}  // namespace kiln::surface

#endif  // KILN_SURFACE_INPUT_STRUCT_H_
