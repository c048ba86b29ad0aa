// The stable diagnostic codes and severities every Kiln library reports with: compiler
// diagnostics, the runtime's errors and warnings, the pack reader and .material files. Once
// published a code keeps its meaning (docs/diagnostics.md).
#ifndef KILN_DIAG_CODE_H_
#define KILN_DIAG_CODE_H_

#include <cstdint>

namespace kiln {

enum class Severity : uint8_t { kNote, kWarning, kError, kInternal };

// Stable diagnostic codes, printed as K<number>. Ranges:
//   K0xxx  input/output          K1xxx  ShaderLab lexer
//   K2xxx  ShaderLab parser      K3xxx  ShaderLab semantic checks
//   K4xxx  pragmas and variants  K5xxx  HLSL compilation, SPIR-V, reflection, bindings
//   K6xxx  material instances    K7xxx  kiln lint
//   K9xxx  internal compiler errors
enum class DiagCode : uint16_t {
    kCannotReadFile = 1,  // also: larger than kMaxSourceFileBytes
    kCannotWriteFile = 2,
    kBadCommandLine = 3,  // an unknown subcommand or option value the CLI reports itself
    kBadPack = 4,  // a pack that is structurally invalid (the reader's reason in the message)
    kUnknownPackName = 5,     // a shader or pass name the pack does not hold
    kMissingVariant = 6,      // the pack holds no variant with the requested keywords
    kBadScene = 7,            // a scene that cannot be loaded or rendered as asked
    kRenderFailed = 8,        // the renderer failed (device, pipeline, validation messages)
    kBadColorConfig = 9,      // an OpenColorIO config, display or view that does not exist
    kRenderWarning = 10,      // a runtime warning without a code of its own below
    kWorkerUnavailable = 11,  // no compile worker process could be found or started
    // The runtime's warnings: the frame was rendered, but not entirely as the input asked.
    kVariantFallback = 12,      // a missing variant replaced by the nearest (--missing-variant)
    kTextureFallback = 13,      // a texture not found or not decodable: the default used
    kDefaultLight = 14,         // a scene without lights lit by the default directional light
    kPassNotDrawn = 15,         // a shader with no pass the render path draws
    kSceneContentIgnored = 16,  // glTF content the loader skips (primitive mode, attribute, light)
    kGltfWarning = 17,          // a warning of the glTF parser (tinygltf) about the file
    // Packs that cannot be read, besides K0004.
    kPackTruncated = 18,         // shorter than its header says
    kNotAPack = 19,              // not a kiln pack (wrong magic)
    kPackVersion = 20,           // another format major version
    kPackChecksum = 21,          // the bytes changed after the pack was written
    kIndexOutOfRange = 22,       // an index given to a pack's API is past the end of its section
    kBadUsageFile = 23,          // a usage file (kiln render --usage) that cannot be read
    kPipelineCacheIgnored = 24,  // warning: a --pipeline-cache file that does not fit the device
    kRendererUnavailable = 25,   // kiln render: kiln-render could not be found or run
    kPackGrowthOverBudget = 26,  // kiln diff: the new pack grew past --max-added-variants/bytes
    kVariantTestFailed = 27,     // kiln test: a variant failed a check of the harness
    kNotFinite = 28,             // kiln stability: a non-finite value on an extreme input
    kOutsideBounds = 29,         // kiln stability: an error past the documented bound
    kUnsupportedExtension = 30,  // a glTF file requires an extension Kiln does not support
    kCannotShowModule = 31,      // kiln show: a module SPIRV-Cross or the disassembler refuses
    kBadImage = 32,  // an image (texture, sky, glTF image) that is truncated, damaged or too large

    kUnterminatedString = 1001,
    kUnterminatedComment = 1002,
    kUnterminatedProgramBlock = 1003,
    kUnexpectedCharacter = 1004,
    kStrayProgramEnd = 1005,

    kExpectedShader = 2001,
    kExpectedToken = 2002,
    kUnexpectedToken = 2003,
    kUnknownCommand = 2004,
    kInvalidValue = 2005,
    kUnclosedBlock = 2006,
    kNestingTooDeep = 2007,
    kTooManyErrors = 2008,
    kExpectedNumber = 2010,
    kUnknownPropertyType = 2011,
    kBadPropertyDefault = 2012,
    kBadAttribute = 2013,
    kLegacyCommandIgnored = 2014,
    kDuplicateCommand = 2015,
    kMisplacedCommand = 2016,
    kBadRenderTarget = 2017,

    kDuplicateProperty = 3001,
    kUndeclaredProperty = 3002,
    kPropertyRefType = 3003,
    kBadRange = 3004,
    kDefaultOutOfRange = 3005,
    kMultiplePrograms = 3006,
    kUnsupportedGlsl = 3007,
    kBadSurfaceShader = 3008,  // a surface shader whose passes cannot be generated
    kProgramOutsidePass = 3009,
    kDuplicateTag = 3010,
    kUnknownTextureDefault = 3011,
    kDuplicatePassName = 3012,
    kUnknownLightMode = 3013,
    kMisspelledLightMode = 3014,
    kUnknownUsePass = 3015,

    kUnknownPragma = 4001,
    kUnsupportedStage = 4002,
    kMissingEntryPoint = 4003,
    kDuplicateEntryPoint = 4004,
    kBadShaderTarget = 4005,
    kBadKeyword = 4006,
    kDuplicateKeyword = 4007,
    kTooManyVariants = 4008,
    kPragmaMissingArgument = 4009,
    kRendererRestricted = 4010,
    kVariantKeyTooWide = 4011,
    kUnknownSkipKeyword = 4012,
    kNoVariantsLeft = 4013,
    kEntryPointNotFound = 4014,
    kUnknownKeyword = 4015,
    kMisspelledPragma = 4016,
    kUnknownRequestedPass = 4017,      // a scene or usage file looks up a pass the shader lacks
    kRequestedVariantNotBuilt = 4018,  // warning: a looked-up variant skip_variants or a rule drops
    kSceneVerifyFailed = 4019,         // --verify-scene: the stripped pack misses a needed variant
    kBadVariantBudget = 4020,          // a "KilnMaxVariants" tag that is not a positive number

    kHlslError = 5001,
    kHlslWarning = 5002,
    kSpirvInvalid = 5003,
    kStageInterfaceMismatch = 5004,
    kPropertyUnused = 5005,
    kGlobalNotAProperty = 5006,
    kBlockLayoutMismatch = 5007,
    kPropertyTypeMismatch = 5008,
    kCompilerCrashed = 5009,         // glslang or SPIRV-Tools crashed in its worker process
    kCompilerTimeLimit = 5010,       // ... did not finish within --program-timeout
    kCompilerMemoryLimit = 5011,     // ... used more than --program-memory
    kProgramNestingTooDeep = 5012,   // parentheses, braces or #if nested past the limit
    kMacroExpansionTooLarge = 5013,  // a macro whose expansion is over the budget
    kExpressionTooLong = 5014,       // one statement or expression with too many terms

    // K6xxx: material instances (.material files, kiln/material/material.h).
    kMaterialJsonSyntax = 6001,           // not valid JSON
    kMaterialUnknownField = 6002,         // a field the format does not have
    kMaterialFieldType = 6003,            // a field with the wrong JSON type
    kMaterialUnsupportedVersion = 6004,   // "kiln_material" is not a version this build reads
    kMaterialMissingField = 6005,         // "shader" absent
    kMaterialUnknownShader = 6006,        // no shader of that name in the pack
    kMaterialUnknownProperty = 6007,      // not in the shader's Properties
    kMaterialPropertyValueType = 6008,    // value does not fit the property's type
    kMaterialOutOfRange = 6009,           // Range(min, max) property outside its range
    kMaterialUnknownKeyword = 6010,       // keyword no pass of the shader declares
    kMaterialConflictingKeywords = 6011,  // two keywords of one set
    kMaterialEngineKeyword = 6012,        // warning: a multi_compile keyword the renderer chooses
    kMaterialRenderState = 6013,          // unknown render-state field or value
    kMaterialTextureNotFound = 6014,      // warning: texture file missing beside the material
    kMaterialDuplicate = 6015,            // the same property or keyword twice
    kMaterialKeywordContradictsProperty = 6016,  // warning: a keyword its [Toggle] turns off

    // K7xxx: kiln lint (docs/variants.md, "Lint"): warnings about what keywords cost and where
    // they are wasted or declared so that variants go missing at run time.
    kLintKeywordChangesNothing = 7001,     // every variant with it compiles to the same SPIR-V
    kLintKeywordOneStage = 7002,           // a set's keywords change only one stage
    kLintRedundantKeywords = 7003,         // two keywords of a set give identical SPIR-V
    kLintEngineShaderFeature = 7004,       // shader_feature of a keyword the engine sets per draw
    kLintMaterialMultiCompile = 7005,      // multi_compile of keywords only material properties set
    kLintShaderFeatureLooksGlobal = 7006,  // shader_feature of a keyword that looks set from code
    kLintKeywordDeclaredTwoWays = 7007,    // one keyword in differing sets of two passes
    kLintTooManyKeywords = 7008,           // past Unity's documented keyword limits
    kLintPropertyKeywordUndeclared = 7009,  // [Toggle(KW)] / [KeywordEnum] of an undeclared keyword
    kLintKeywordWithoutToggle = 7010,  // a keyword [Toggle] on a property would drive, without it
    kLintStateContradictsPass = 7011,  // render state the pass's LightMode or Queue contradicts

    kInternalError = 9001,
};

}  // namespace kiln

#endif  // KILN_DIAG_CODE_H_
