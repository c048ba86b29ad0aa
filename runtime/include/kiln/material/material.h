// Material instances: the `.material` JSON format (docs/material-format.md), its parser and its
// validation against a shader's Properties and keywords in a compiled pack. Shared by the `kiln`
// CLI (build-time checks) and the runtime (loading). Never throws, never prints: problems are
// returned as MaterialIssue with stable codes (K6xxx, docs/diagnostics.md).
#ifndef KILN_MATERIAL_MATERIAL_H_
#define KILN_MATERIAL_MATERIAL_H_

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/pack/names.h"
#include "kiln/pack/reader.h"

namespace kiln::material {

inline constexpr int kFormatVersion = 1;

struct TextPos {
    uint32_t offset = 0;  // byte offset into the file
    uint32_t line = 1;
    uint32_t column = 1;
};

enum class IssueSeverity : uint8_t { kWarning, kError };

// Stable codes, printed as K<number>.
enum class IssueCode : uint16_t {
    kJsonSyntax = 6001,           // not valid JSON
    kUnknownField = 6002,         // a field the format does not have
    kFieldType = 6003,            // a field with the wrong JSON type
    kUnsupportedVersion = 6004,   // "kiln_material" is not a version this build reads
    kMissingField = 6005,         // "shader" absent
    kUnknownShader = 6006,        // no shader of that name in the pack
    kUnknownProperty = 6007,      // not in the shader's Properties
    kPropertyValueType = 6008,    // value does not fit the property's type
    kOutOfRange = 6009,           // Range(min, max) property outside its range
    kUnknownKeyword = 6010,       // keyword no pass of the shader declares
    kConflictingKeywords = 6011,  // two keywords of one set
    kEngineKeyword = 6012,        // warning: a multi_compile keyword the renderer chooses
    kRenderState = 6013,          // unknown render-state field or value
    kTextureNotFound = 6014,      // warning: texture file missing beside the material
    kDuplicate = 6015,            // the same property or keyword twice
    kKeywordContradictsProperty = 6016,  // warning: a listed keyword its [Toggle] property turns off
};

struct MaterialIssue {
    IssueSeverity severity = IssueSeverity::kError;
    IssueCode code = IssueCode::kJsonSyntax;
    TextPos pos;
    std::string message;  // lower-case, one sentence, no trailing period
    std::string note;     // optional: "did you mean '_Color'", the allowed values, ...
};

// A property value as written: numbers (1 for scalars, 2-4 for vectors and colours) or a
// texture (path relative to the .material file, tiling scale and offset).
struct PropertyValue {
    enum class Kind { kNumbers, kTexture };
    std::string name;
    TextPos pos;  // of the key
    Kind kind = Kind::kNumbers;
    std::vector<double> numbers;
    std::string texture;  // empty: the shader's default texture
    std::array<double, 2> scale{1.0, 1.0};
    std::array<double, 2> offset{0.0, 0.0};
};

struct Keyword {
    std::string name;
    TextPos pos;
};

// One render-state override; values are canonical ShaderLab spellings ("Off", "LEqual", "One").
struct RenderStateOverride {
    std::string field;  // "Cull", "ZWrite", "ZTest", "Blend", "ColorMask"
    std::vector<std::string> values;
    TextPos pos;
};

struct Material {
    int version = kFormatVersion;
    std::string shader;
    TextPos shader_pos;
    std::vector<PropertyValue> properties;
    std::vector<Keyword> keywords;
    std::vector<RenderStateOverride> render_state;
};

// Parses a .material file. Returns false when an error was added to `issues`; `out` then still
// holds every well-formed part (so validation can report more than the first problem), unless
// the text is not JSON at all (an IssueCode::kJsonSyntax issue).
bool ParseMaterial(std::string_view text, Material& out, std::vector<MaterialIssue>& issues);

// Checks `m` against the shader of its name in `pack`: every property exists and has a value of
// its type within its Range, every keyword is declared (and not two of one set), render-state
// overrides are valid. `material_dir`, when not empty, is where texture paths are looked up.
// Returns false when an error was added.
bool ValidateMaterial(const Material& m,
                      const pack::Pack& pack,
                      const std::string& material_dir,
                      std::vector<MaterialIssue>& issues);

// The keywords `m` enables on `shader` of `pack`: its "keywords" plus those its values of
// [Toggle]/[ToggleOff]/[KeywordEnum] properties enable (kiln/pack/property_keywords.h; a property
// the material does not set contributes through its default), as in Unity. Sorted, unique.
std::vector<std::string> EnabledKeywords(const Material& m,
                                         const pack::Pack& pack,
                                         uint32_t shader);

using pack::ClosestName;  // kiln/pack/names.h

}  // namespace kiln::material

#endif  // KILN_MATERIAL_MATERIAL_H_
