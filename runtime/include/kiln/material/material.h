// Material instances: the `.material` JSON format (docs/material-format.md), its parser and its
// validation against a shader's Properties and keywords in a compiled pack. Shared by the `kiln`
// CLI (build-time checks) and the runtime (loading). Never throws, never prints: problems are
// added to a DiagnosticList with stable codes (K6xxx, docs/diagnostics.md).
#ifndef KILN_MATERIAL_MATERIAL_H_
#define KILN_MATERIAL_MATERIAL_H_

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/names.h"
#include "kiln/pack/reader.h"

namespace kiln::material {

inline constexpr int kFormatVersion = 1;
// The largest .material or .kiln.json file read (a FIFO or device is refused before reading).
inline constexpr uint64_t kMaxFileBytes = uint64_t{16} << 20;

// Positions in a .material file: byte offset, 1-based line and column.
using TextPos = SourceLoc;

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
    std::string file;  // the path diagnostics name (ParseMaterial's `file`)
    int version = kFormatVersion;
    std::string shader;
    TextPos shader_pos;
    std::vector<PropertyValue> properties;
    std::vector<Keyword> keywords;
    std::vector<RenderStateOverride> render_state;
};

// Parses a .material file; `file` is the path its diagnostics name. Returns false when an error
// was added to `diags`; `out` then still holds every well-formed part (so validation can report
// more than the first problem), unless the text is not JSON at all (K6001, and `out.shader` is
// empty). A diagnostic's "did you mean" or list of allowed values is its note.
bool ParseMaterial(std::string_view text,
                   const std::string& file,
                   Material& out,
                   DiagnosticList& diags);

// Checks `m` against the shader of its name in `pack`: every property exists and has a value of
// its type within its Range, every keyword is declared (and not two of one set), render-state
// overrides are valid. `material_dir`, when not empty, is where texture paths are looked up.
// Returns false when an error was added to `diags` (which name `m.file`).
bool ValidateMaterial(const Material& m,
                      const pack::Pack& pack,
                      const std::string& material_dir,
                      DiagnosticList& diags);

// The keywords `m` enables on `shader` of `pack`: its "keywords" plus those its values of
// [Toggle]/[ToggleOff]/[KeywordEnum] properties enable (kiln/pack/property_keywords.h; a property
// the material does not set contributes through its default), as in Unity. Sorted, unique.
std::vector<std::string> EnabledKeywords(const Material& m,
                                         const pack::Pack& pack,
                                         uint32_t shader);

using pack::ClosestName;  // kiln/pack/names.h

}  // namespace kiln::material

#endif  // KILN_MATERIAL_MATERIAL_H_
