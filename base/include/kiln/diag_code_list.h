// Every stable diagnostic code, once: KILN_DIAG_CODE(name, number) per code, the ranges of
// kiln/diag_code.h. Included by kiln/diag_code.h (the enum) and by diagnostic.cpp (the list the
// -W options check their codes against); define KILN_DIAG_CODE before including it. Once
// published a code keeps its meaning (docs/diagnostics.md).
// An X-macro list, included more than once: no include guard, and no clang-format.
// clang-format off

KILN_DIAG_CODE(kCannotReadFile, 1)  // also: larger than kMaxSourceFileBytes
KILN_DIAG_CODE(kCannotWriteFile, 2)
KILN_DIAG_CODE(kBadCommandLine, 3)  // an unknown subcommand or option value the CLI reports itself
// a pack that is structurally invalid (the reader's reason in the message)
KILN_DIAG_CODE(kBadPack, 4)
KILN_DIAG_CODE(kUnknownPackName, 5)  // a shader or pass name the pack does not hold
KILN_DIAG_CODE(kMissingVariant, 6)  // the pack holds no variant with the requested keywords
KILN_DIAG_CODE(kBadScene, 7)  // a scene that cannot be loaded or rendered as asked
KILN_DIAG_CODE(kRenderFailed, 8)  // the renderer failed (device, pipeline, validation messages)
KILN_DIAG_CODE(kBadColorConfig, 9)  // an OpenColorIO config, display or view that does not exist
KILN_DIAG_CODE(kRenderWarning, 10)  // a runtime warning without a code of its own below
KILN_DIAG_CODE(kWorkerUnavailable, 11)  // no compile worker process could be found or started
// The runtime's warnings: the frame was rendered, but not entirely as the input asked.
// a missing variant replaced by the nearest (--missing-variant)
KILN_DIAG_CODE(kVariantFallback, 12)
KILN_DIAG_CODE(kTextureFallback, 13)  // a texture not found or not decodable: the default used
KILN_DIAG_CODE(kDefaultLight, 14)  // a scene without lights lit by the default directional light
KILN_DIAG_CODE(kPassNotDrawn, 15)  // a shader with no pass the render path draws
// glTF content the loader skips (primitive mode, attribute, light)
KILN_DIAG_CODE(kSceneContentIgnored, 16)
KILN_DIAG_CODE(kGltfWarning, 17)  // a warning of the glTF parser (tinygltf) about the file
// Packs that cannot be read, besides K0004.
KILN_DIAG_CODE(kPackTruncated, 18)  // shorter than its header says
KILN_DIAG_CODE(kNotAPack, 19)  // not a kiln pack (wrong magic)
KILN_DIAG_CODE(kPackVersion, 20)  // another format major version
KILN_DIAG_CODE(kPackChecksum, 21)  // the bytes changed after the pack was written
// an index given to a pack's API is past the end of its section
KILN_DIAG_CODE(kIndexOutOfRange, 22)
KILN_DIAG_CODE(kBadUsageFile, 23)  // a usage file (kiln render --usage) that cannot be read
// warning: a --pipeline-cache file that does not fit the device
KILN_DIAG_CODE(kPipelineCacheIgnored, 24)
KILN_DIAG_CODE(kRendererUnavailable, 25)  // kiln render: kiln-render could not be found or run
// kiln diff: the new pack grew past --max-added-variants/bytes
KILN_DIAG_CODE(kPackGrowthOverBudget, 26)
KILN_DIAG_CODE(kVariantTestFailed, 27)  // kiln test: a variant failed a check of the harness
KILN_DIAG_CODE(kNotFinite, 28)  // kiln stability: a non-finite value on an extreme input
KILN_DIAG_CODE(kOutsideBounds, 29)  // kiln stability: an error past the documented bound
// a glTF file requires an extension Kiln does not support
KILN_DIAG_CODE(kUnsupportedExtension, 30)
// kiln show: a module SPIRV-Cross or the disassembler refuses
KILN_DIAG_CODE(kCannotShowModule, 31)
// an image (texture, sky, glTF image) that is truncated, damaged or too large
KILN_DIAG_CODE(kBadImage, 32)

KILN_DIAG_CODE(kUnterminatedString, 1001)
KILN_DIAG_CODE(kUnterminatedComment, 1002)
KILN_DIAG_CODE(kUnterminatedProgramBlock, 1003)
KILN_DIAG_CODE(kUnexpectedCharacter, 1004)
KILN_DIAG_CODE(kStrayProgramEnd, 1005)

KILN_DIAG_CODE(kExpectedShader, 2001)
KILN_DIAG_CODE(kExpectedToken, 2002)
KILN_DIAG_CODE(kUnexpectedToken, 2003)
KILN_DIAG_CODE(kUnknownCommand, 2004)
KILN_DIAG_CODE(kInvalidValue, 2005)
KILN_DIAG_CODE(kUnclosedBlock, 2006)
KILN_DIAG_CODE(kNestingTooDeep, 2007)
KILN_DIAG_CODE(kTooManyErrors, 2008)
KILN_DIAG_CODE(kExpectedNumber, 2010)
KILN_DIAG_CODE(kUnknownPropertyType, 2011)
KILN_DIAG_CODE(kBadPropertyDefault, 2012)
KILN_DIAG_CODE(kBadAttribute, 2013)
KILN_DIAG_CODE(kLegacyCommandIgnored, 2014)
KILN_DIAG_CODE(kDuplicateCommand, 2015)
KILN_DIAG_CODE(kMisplacedCommand, 2016)
KILN_DIAG_CODE(kBadRenderTarget, 2017)

KILN_DIAG_CODE(kDuplicateProperty, 3001)
KILN_DIAG_CODE(kUndeclaredProperty, 3002)
KILN_DIAG_CODE(kPropertyRefType, 3003)
KILN_DIAG_CODE(kBadRange, 3004)
KILN_DIAG_CODE(kDefaultOutOfRange, 3005)
KILN_DIAG_CODE(kMultiplePrograms, 3006)
KILN_DIAG_CODE(kUnsupportedGlsl, 3007)
KILN_DIAG_CODE(kBadSurfaceShader, 3008)  // a surface shader whose passes cannot be generated
KILN_DIAG_CODE(kProgramOutsidePass, 3009)
KILN_DIAG_CODE(kDuplicateTag, 3010)
KILN_DIAG_CODE(kUnknownTextureDefault, 3011)
KILN_DIAG_CODE(kDuplicatePassName, 3012)
KILN_DIAG_CODE(kUnknownLightMode, 3013)
KILN_DIAG_CODE(kMisspelledLightMode, 3014)
KILN_DIAG_CODE(kUnknownUsePass, 3015)

KILN_DIAG_CODE(kUnknownPragma, 4001)
KILN_DIAG_CODE(kUnsupportedStage, 4002)
KILN_DIAG_CODE(kMissingEntryPoint, 4003)
KILN_DIAG_CODE(kDuplicateEntryPoint, 4004)
KILN_DIAG_CODE(kBadShaderTarget, 4005)
KILN_DIAG_CODE(kBadKeyword, 4006)
KILN_DIAG_CODE(kDuplicateKeyword, 4007)
KILN_DIAG_CODE(kTooManyVariants, 4008)
KILN_DIAG_CODE(kPragmaMissingArgument, 4009)
KILN_DIAG_CODE(kRendererRestricted, 4010)
KILN_DIAG_CODE(kVariantKeyTooWide, 4011)
KILN_DIAG_CODE(kUnknownSkipKeyword, 4012)
KILN_DIAG_CODE(kNoVariantsLeft, 4013)
KILN_DIAG_CODE(kEntryPointNotFound, 4014)
KILN_DIAG_CODE(kUnknownKeyword, 4015)
KILN_DIAG_CODE(kMisspelledPragma, 4016)
// a scene or usage file looks up a pass the shader lacks
KILN_DIAG_CODE(kUnknownRequestedPass, 4017)
// warning: a looked-up variant skip_variants or a rule drops
KILN_DIAG_CODE(kRequestedVariantNotBuilt, 4018)
// --verify-scene: the stripped pack misses a needed variant
KILN_DIAG_CODE(kSceneVerifyFailed, 4019)
KILN_DIAG_CODE(kBadVariantBudget, 4020)  // a "KilnMaxVariants" tag that is not a positive number

KILN_DIAG_CODE(kHlslError, 5001)
KILN_DIAG_CODE(kHlslWarning, 5002)
KILN_DIAG_CODE(kSpirvInvalid, 5003)
KILN_DIAG_CODE(kStageInterfaceMismatch, 5004)
KILN_DIAG_CODE(kPropertyUnused, 5005)
KILN_DIAG_CODE(kGlobalNotAProperty, 5006)
KILN_DIAG_CODE(kBlockLayoutMismatch, 5007)
KILN_DIAG_CODE(kPropertyTypeMismatch, 5008)
KILN_DIAG_CODE(kCompilerCrashed, 5009)  // glslang or SPIRV-Tools crashed in its worker process
KILN_DIAG_CODE(kCompilerTimeLimit, 5010)  // ... did not finish within --program-timeout
KILN_DIAG_CODE(kCompilerMemoryLimit, 5011)  // ... used more than --program-memory
KILN_DIAG_CODE(kProgramNestingTooDeep, 5012)  // parentheses, braces or #if nested past the limit
KILN_DIAG_CODE(kMacroExpansionTooLarge, 5013)  // a macro whose expansion is over the budget
KILN_DIAG_CODE(kExpressionTooLong, 5014)  // one statement or expression with too many terms

// K6xxx: material instances (.material files, kiln/material/material.h).
KILN_DIAG_CODE(kMaterialJsonSyntax, 6001)  // not valid JSON
KILN_DIAG_CODE(kMaterialUnknownField, 6002)  // a field the format does not have
KILN_DIAG_CODE(kMaterialFieldType, 6003)  // a field with the wrong JSON type
// "kiln_material" is not a version this build reads
KILN_DIAG_CODE(kMaterialUnsupportedVersion, 6004)
KILN_DIAG_CODE(kMaterialMissingField, 6005)  // "shader" absent
KILN_DIAG_CODE(kMaterialUnknownShader, 6006)  // no shader of that name in the pack
KILN_DIAG_CODE(kMaterialUnknownProperty, 6007)  // not in the shader's Properties
KILN_DIAG_CODE(kMaterialPropertyValueType, 6008)  // value does not fit the property's type
KILN_DIAG_CODE(kMaterialOutOfRange, 6009)  // Range(min, max) property outside its range
KILN_DIAG_CODE(kMaterialUnknownKeyword, 6010)  // keyword no pass of the shader declares
KILN_DIAG_CODE(kMaterialConflictingKeywords, 6011)  // two keywords of one set
// warning: a multi_compile keyword the renderer chooses
KILN_DIAG_CODE(kMaterialEngineKeyword, 6012)
KILN_DIAG_CODE(kMaterialRenderState, 6013)  // unknown render-state field or value
KILN_DIAG_CODE(kMaterialTextureNotFound, 6014)  // warning: texture file missing beside the material
KILN_DIAG_CODE(kMaterialDuplicate, 6015)  // the same property or keyword twice
// warning: a keyword its [Toggle] turns off
KILN_DIAG_CODE(kMaterialKeywordContradictsProperty, 6016)

// K7xxx: kiln lint (docs/variants.md, "Lint"): warnings about what keywords cost and where
// they are wasted or declared so that variants go missing at run time.
// every variant with it compiles to the same SPIR-V
KILN_DIAG_CODE(kLintKeywordChangesNothing, 7001)
KILN_DIAG_CODE(kLintKeywordOneStage, 7002)  // a set's keywords change only one stage
KILN_DIAG_CODE(kLintRedundantKeywords, 7003)  // two keywords of a set give identical SPIR-V
// shader_feature of a keyword the engine sets per draw
KILN_DIAG_CODE(kLintEngineShaderFeature, 7004)
// multi_compile of keywords only material properties set
KILN_DIAG_CODE(kLintMaterialMultiCompile, 7005)
// shader_feature of a keyword that looks set from code
KILN_DIAG_CODE(kLintShaderFeatureLooksGlobal, 7006)
KILN_DIAG_CODE(kLintKeywordDeclaredTwoWays, 7007)  // one keyword in differing sets of two passes
KILN_DIAG_CODE(kLintTooManyKeywords, 7008)  // past Unity's documented keyword limits
// [Toggle(KW)] / [KeywordEnum] of an undeclared keyword
KILN_DIAG_CODE(kLintPropertyKeywordUndeclared, 7009)
// a keyword [Toggle] on a property would drive, without it
KILN_DIAG_CODE(kLintKeywordWithoutToggle, 7010)
// render state the pass's LightMode or Queue contradicts
KILN_DIAG_CODE(kLintStateContradictsPass, 7011)

KILN_DIAG_CODE(kInternalError, 9001)
// clang-format on
