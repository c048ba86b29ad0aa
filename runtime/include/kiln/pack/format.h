// The variant pack format, shared by the writer (compiler) and the reader (runtime). The byte
// layout is specified in docs/pack-format.md; this header is its single definition in code.
//
// A pack is a 32-byte header, a section table, then 8-byte-aligned sections. Every section but
// STRS and SPRV is an array of fixed-size records; each record type below has its encoded size
// beside it and is written field by field, little-endian, in declaration order (EncodeRecord /
// DecodeRecord in records.h). Strings are StrRefs into STRS; indices refer to records of other
// sections and are checked by the reader before any use.
#ifndef KILN_PACK_FORMAT_H_
#define KILN_PACK_FORMAT_H_

#include <array>
#include <cstdint>
#include <string_view>

namespace kiln::pack {

inline constexpr std::array<char, 4> kMagic = {'K', 'P', 'A', 'K'};
inline constexpr uint16_t kFormatMajor = 1;  // readers reject another major
inline constexpr uint16_t kFormatMinor =
    4;  // additions readers may ignore (1: KALI, 2: VSTG, 3: GRAB, 4: SUMS)
inline constexpr uint32_t kHeaderSize = 32;
inline constexpr uint32_t kSectionEntrySize = 24;
inline constexpr uint32_t kSectionAlignment = 8;
inline constexpr uint32_t kMaxSections = 64;

constexpr uint32_t FourCC(char a, char b, char c, char d) {
    return uint32_t(uint8_t(a)) | uint32_t(uint8_t(b)) << 8 | uint32_t(uint8_t(c)) << 16 |
           uint32_t(uint8_t(d)) << 24;
}

enum class SectionTag : uint32_t {
    kStrings = FourCC('S', 'T', 'R', 'S'),      // raw bytes
    kMeta = FourCC('M', 'E', 'T', 'A'),         // MetaRec x1
    kShaders = FourCC('S', 'H', 'D', 'R'),      // ShaderRec
    kProperties = FourCC('P', 'R', 'O', 'P'),   // PropertyRec
    kAttributes = FourCC('A', 'T', 'T', 'R'),   // AttributeRec
    kPasses = FourCC('P', 'A', 'S', 'S'),       // PassRec
    kTags = FourCC('T', 'A', 'G', 'S'),         // TagRec
    kStates = FourCC('R', 'S', 'T', 'A'),       // StateRec
    kKeywordSets = FourCC('K', 'S', 'E', 'T'),  // KeywordSetRec
    kKeywords = FourCC('K', 'W', 'R', 'D'),     // StrRef
    kVariants = FourCC('V', 'A', 'R', 'I'),     // VariantRec, sorted by (pass, key)
    kModules = FourCC('M', 'O', 'D', 'L'),      // ModuleRec
    kSpirv = FourCC('S', 'P', 'R', 'V'),        // raw SPIR-V words, each module 4-aligned
    kInterface = FourCC('I', 'O', 'V', 'R'),    // InterfaceVarRec
    kBlocks = FourCC('B', 'L', 'C', 'K'),       // BlockRec
    kMembers = FourCC('M', 'E', 'M', 'B'),      // MemberRec
    kResources = FourCC('R', 'S', 'R', 'C'),    // ResourceRec
    // Optional (format 1.1): keyword aliases, KeywordAliasRec sorted by (keyword_set, from).
    kKeywordAliases = FourCC('K', 'A', 'L', 'I'),
    // Optional (format 1.2): the geometry and tessellation modules of variants that have them,
    // VariantStagesRec; VariantRec::stages is 1 + an index into it. A reader of format 1.1
    // refuses these packs (their modules have a stage it does not know), never draws without them.
    kVariantStages = FourCC('V', 'S', 'T', 'G'),
    // Optional (format 1.3): the texture of each GrabPass (a pass flagged kPassGrab), GrabRec
    // sorted by pass. A reader of format 1.2 sees a pass without variants, which it never draws.
    kGrabPasses = FourCC('G', 'R', 'A', 'B'),
    // Optional (format 1.4): SectionSumRec, one per section but SPRV (each module's hash is in
    // MODL) and SUMS, and one (tag TABL) for the header and the section table, so a reader can
    // check each section when it first reads it instead of the whole file at open. A reader of
    // format 1.3 skips it and checks the whole-file checksum, which still covers everything.
    kSums = FourCC('S', 'U', 'M', 'S'),
};

// SectionSumRec::tag of the sum over the header (its checksum field read as zero) and the
// section table.
inline constexpr uint32_t kTableSumTag = FourCC('T', 'A', 'B', 'L');

struct SectionSumRec {  // 16 bytes
    uint32_t tag = 0;   // a section's tag, or kTableSumTag
    uint32_t reserved = 0;
    uint64_t sum = 0;  // XXH64 (seed 0) of the section's bytes
};

struct Header {  // 32 bytes
    std::array<char, 4> magic = kMagic;
    uint16_t format_major = kFormatMajor;
    uint16_t format_minor = kFormatMinor;
    uint32_t header_size = kHeaderSize;
    uint32_t section_count = 0;
    uint64_t file_size = 0;
    uint64_t checksum = 0;  // XXH64 (seed 0) of the whole file with this field zeroed
};
inline constexpr uint32_t kChecksumOffset = 24;

struct SectionEntry {  // 24 bytes
    uint32_t tag = 0;
    uint32_t record_count = 0;  // records (0 for STRS and SPRV)
    uint64_t offset = 0;        // from the start of the file, 8-aligned
    uint64_t size = 0;          // bytes
};

struct StrRef {  // 8 bytes: a UTF-8 string in STRS, not NUL-terminated
    uint32_t offset = 0;
    uint32_t length = 0;
};

// How `half` and `fixed` compile (kiln compile --precision, docs/unity-compat.md): kFull as 32-bit
// float (Unity's desktop targets), kRelaxed as min16float (RelaxedPrecision: the driver may use 16
// bits, as Unity's Vulkan back end emits them), kHalf as min16float whose arithmetic SPIRV-Tools
// then converts to binary16 (Float16 capability; the device needs shaderFloat16).
enum class Precision : uint32_t { kFull, kRelaxed, kHalf };

// MetaRec::flags: how the pack was compiled.
enum MetaFlags : uint32_t {
    kMetaDebugInfo = 1u << 0,         // -g: debug info kept
    kMetaRelaxedPrecision = 1u << 1,  // --precision relaxed: half is min16float (RelaxedPrecision)
    // --precision half: half arithmetic is binary16 (Float16 capability; needs shaderFloat16)
    kMetaHalfPrecision = 1u << 2,
};

inline const char* PrecisionName(Precision p) {  // as --precision spells it
    return p == Precision::kHalf ? "half" : p == Precision::kRelaxed ? "relaxed" : "full";
}

// The inverse of PrecisionName; kFull for any other name (the CLI admits only the three).
inline Precision PrecisionFromName(std::string_view name) {
    for (Precision p : {Precision::kHalf, Precision::kRelaxed}) {
        if (name == PrecisionName(p))
            return p;
    }
    return Precision::kFull;
}

inline Precision PrecisionOf(uint32_t meta_flags) {
    return (meta_flags & kMetaHalfPrecision)      ? Precision::kHalf
           : (meta_flags & kMetaRelaxedPrecision) ? Precision::kRelaxed
                                                  : Precision::kFull;
}

struct MetaRec {             // 24 bytes
    StrRef producer;         // "kiln 0.2.0; glslang 12.0.0; SPIRV-Tools v2023.1; SPIRV-Cross"
    uint32_t opt_level = 0;  // 0 = -O0, 1 = -O, 2 = -Os
    uint32_t flags = 0;      // MetaFlags
    uint32_t variant_count = 0;
    uint32_t module_count = 0;
};

struct ShaderRec {  // 32 bytes
    StrRef name;
    uint32_t first_property = 0, property_count = 0;
    uint32_t first_pass = 0, pass_count = 0;
    StrRef fallback;  // empty: none
};

enum class PropertyType : uint32_t {
    kColor,
    kVector,
    kFloat,
    kInt,
    kInteger,
    kRange,
    kTexture2D,
    kTexture3D,
    kCube,
    kTexture2DArray,
    kCubeArray,
    kTextureAny,  // `Any`: a texture of whatever dimension the shader declares
};

// ShaderLab's spelling of a property type: "Color", "Range", "2D", ...
constexpr const char* PropertyTypeName(PropertyType type) {
    switch (type) {
        case PropertyType::kColor:
            return "Color";
        case PropertyType::kVector:
            return "Vector";
        case PropertyType::kFloat:
            return "Float";
        case PropertyType::kInt:
            return "Int";
        case PropertyType::kInteger:
            return "Integer";
        case PropertyType::kRange:
            return "Range";
        case PropertyType::kTexture2D:
            return "2D";
        case PropertyType::kTexture3D:
            return "3D";
        case PropertyType::kCube:
            return "Cube";
        case PropertyType::kTexture2DArray:
            return "2DArray";
        case PropertyType::kCubeArray:
            return "CubeArray";
        case PropertyType::kTextureAny:
            return "Any";
    }
    return "Float";
}

constexpr bool IsTextureProperty(PropertyType type) {
    return type == PropertyType::kTexture2D || type == PropertyType::kTexture3D ||
           type == PropertyType::kCube || type == PropertyType::kTexture2DArray ||
           type == PropertyType::kCubeArray || type == PropertyType::kTextureAny;
}

struct PropertyRec {  // 64 bytes
    StrRef name;
    StrRef display_name;
    uint32_t type = 0;  // PropertyType
    uint32_t first_attribute = 0, attribute_count = 0;
    float range_min = 0, range_max = 0;
    std::array<float, 4> default_value{};
    StrRef texture_default;  // "white", "black", "gray", "bump", ... (textures only)
    uint32_t reserved = 0;
};

struct AttributeRec {  // 16 bytes: [Name(args)]
    StrRef name;
    StrRef args;  // raw text between the parentheses
};

enum PassFlags : uint32_t {
    kPassOnlyRenderers = 1u << 0,     // `#pragma only_renderers` present
    kPassExcludeRenderers = 1u << 1,  // `#pragma exclude_renderers` present
    // A GrabPass: no program, no keyword sets and no variants; the runtime copies the colour
    // target into a texture (its GrabRec) where the pass stands in the object's passes.
    kPassGrab = 1u << 2,
};

struct GrabRec {        // 16 bytes
    uint32_t pass = 0;  // a pass flagged kPassGrab
    // `GrabPass { "_Name" }`: grabbed once per frame, by the first object drawing the pass, into
    // _Name. Empty: `GrabPass { }`, grabbed before every object's draw into _GrabTexture.
    StrRef texture;
    uint32_t reserved = 0;
};

struct PassRec {  // 56 bytes
    StrRef name;  // Name "..." (empty when unnamed)
    uint32_t shader = 0;
    uint32_t subshader = 0;  // index of its SubShader within the shader
    uint32_t lod = 0;
    uint32_t first_tag = 0, tag_count = 0;  // pass tags, then inherited SubShader tags
    uint32_t first_state = 0, state_count = 0;
    uint32_t first_keyword_set = 0, keyword_set_count = 0;
    uint32_t first_variant = 0, variant_count = 0;
    uint32_t flags = 0;  // PassFlags
};

struct TagRec {  // 16 bytes
    StrRef key;
    StrRef value;
};

// One resolved render-state setting of a pass (Category, SubShader and Pass levels merged).
enum class StateField : uint32_t {
    kCull,
    kZTest,
    kZWrite,
    kZClip,
    kAlphaToMask,
    kConservative,
    kOffsetFactor,
    kOffsetUnits,
    kBlendOff,
    kBlendSrc,
    kBlendDst,
    kBlendSrcAlpha,
    kBlendDstAlpha,
    kBlendOp,
    kBlendOpAlpha,
    kColorMask,
    kStencilRef,
    kStencilReadMask,
    kStencilWriteMask,
    kStencilCompFront,
    kStencilPassFront,
    kStencilFailFront,
    kStencilZFailFront,
    kStencilCompBack,
    kStencilPassBack,
    kStencilFailBack,
    kStencilZFailBack,
};
inline constexpr uint32_t kStateFieldCount = 27;

enum class StateKind : uint32_t { kLiteral, kNumber, kPropertyRef };

struct StateRec {         // 24 bytes
    uint32_t field = 0;   // StateField
    int32_t target = -1;  // render target for Blend/BlendOp/ColorMask; -1 = all
    uint32_t kind = 0;    // StateKind
    float number = 0;     // kNumber
    StrRef text;          // canonical literal ("LEqual") or property name
};

enum class KeywordSetKind : uint32_t { kMultiCompile, kShaderFeature };
enum KeywordSetFlags : uint32_t {
    kKeywordSetLocal = 1u << 0,
    kKeywordSetVertexOnly = 1u << 1,
    kKeywordSetFragmentOnly = 1u << 2,
};

struct KeywordSetRec {                              // 24 bytes
    uint32_t kind = 0;                              // KeywordSetKind
    uint32_t flags = 0;                             // KeywordSetFlags
    uint32_t first_keyword = 0, keyword_count = 0;  // into KWRD; an empty name is "no keyword"
    uint32_t key_shift = 0, key_bits = 0;           // see variant_key.h
};

// Keyword `from` of a keyword set gives, in every variant of its pass, the same SPIR-V as keyword
// `to` (both stages, every combination of the other sets): the compiler built `to`'s variants
// only, and a lookup that enables `from` finds them (Pack::FindVariant maps it). `to` is never
// itself aliased. A reader of format 1.0 skips the section, and such a lookup is a clear
// missing-variant error there, never another variant.
struct KeywordAliasRec {        // 16 bytes
    uint32_t keyword_set = 0;   // index into KSET
    uint32_t from = 0, to = 0;  // keyword indices within the set
    uint32_t reserved = 0;
};

struct VariantRec {  // 24 bytes
    uint32_t pass = 0;
    uint32_t stages = 0;  // 0: vertex and fragment only; n: VSTG record n - 1 has the others
    uint64_t key = 0;     // VariantKey bits
    uint32_t vertex_module = 0, fragment_module = 0;
};

// Unity's stage pragmas: vertex, fragment, geometry, hull (tessellation control), domain
// (tessellation evaluation).
enum class Stage : uint32_t { kVertex, kFragment, kGeometry, kTessControl, kTessEval };
inline constexpr uint32_t kStageCount = 5;

// Unity's pragma name of a stage ("vertex", "fragment", "geometry", "hull", "domain").
constexpr const char* StageName(Stage s) {
    switch (s) {
        case Stage::kVertex:
            return "vertex";
        case Stage::kFragment:
            return "fragment";
        case Stage::kGeometry:
            return "geometry";
        case Stage::kTessControl:
            return "hull";
        case Stage::kTessEval:
            return "domain";
    }
    return "?";
}

inline constexpr uint32_t kNoModule = ~0u;

struct VariantStagesRec {  // 16 bytes
    uint32_t geometry_module = kNoModule;
    uint32_t tess_control_module = kNoModule, tess_eval_module = kNoModule;  // both or neither
    uint32_t reserved = 0;
};

struct ModuleRec {              // 48 bytes
    uint32_t spirv_offset = 0;  // within SPRV, 4-aligned
    uint32_t spirv_size = 0;    // bytes, a multiple of 4
    uint64_t hash = 0;          // XXH64 of the SPIR-V bytes
    uint32_t stage = 0;         // Stage
    uint32_t first_interface = 0, interface_count = 0;
    uint32_t first_block = 0, block_count = 0;
    uint32_t first_resource = 0, resource_count = 0;
    uint32_t reserved = 0;
};

// Numeric types in reflection.
enum class BaseType : uint32_t { kUnknown, kBool, kInt, kUInt, kFloat, kHalf, kStruct, kDouble };

struct InterfaceVarRec {  // 32 bytes: a stage input or output
    StrRef name;
    StrRef semantic;  // HLSL semantic, upper-case ("POSITION", "TEXCOORD0"); empty for built-ins
    uint32_t location = 0;   // ~0u for built-ins
    uint32_t direction = 0;  // 0 input, 1 output
    uint32_t base_type = 0;  // BaseType
    uint32_t vecsize = 0;
};

enum class BlockKind : uint32_t { kUniform, kPushConstant };

struct BlockRec {                   // 32 bytes
    StrRef name;                    // "$Global" or the cbuffer's name
    uint32_t kind = 0;              // BlockKind
    uint32_t set = 0, binding = 0;  // push constants: 0, 0
    uint32_t size = 0;              // declared size in bytes
    uint32_t first_member = 0, member_count = 0;
};

struct MemberRec {  // 32 bytes
    StrRef name;
    uint32_t offset = 0, size = 0;
    uint32_t base_type = 0;  // BaseType
    uint32_t vecsize = 0, columns = 0;
    uint32_t array_size = 0;  // 0: not an array
};

enum class ResourceKind : uint32_t {
    kCombinedImageSampler,  // sampler2D (DX9 style)
    kSeparateImage,         // Texture2D
    kSeparateSampler,       // SamplerState
    kStorageImage,
    kStorageBuffer,
};

enum class ImageDim : uint32_t { kNone, k1D, k2D, k3D, kCube, kBuffer };

struct ResourceRec {  // 32 bytes
    StrRef name;
    uint32_t kind = 0;  // ResourceKind
    uint32_t set = 0, binding = 0;
    uint32_t dim = 0;  // ImageDim
    uint32_t arrayed = 0;
    uint32_t array_size = 0;  // descriptor count; 1 for a single resource
};

}  // namespace kiln::pack

#endif  // KILN_PACK_FORMAT_H_
